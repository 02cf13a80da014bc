// Small files for the suite tests: a scratch directory with two short scenes (a wall to
// hide behind, a room with a door), a helper to write a suite next to them, a tiny suite
// over them, and one to read a file back.
#pragma once

#include <filesystem>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace sightline::experiments::testing {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("sightline-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_ / "scenes");
    write("scenes/wall.yaml", R"(name: wall
frame_rate: 30
boxes:
  - {name: wall, min: [-3, 0, 2], max: [3, 3, 2.3]}
trajectory:
  - {t: 0, position: [0, 0, -2], yaw: 0}
  - {t: 1.0, position: [0, 0, 1], yaw: 0}
  - {t: 1.6, position: [0, 0, 1], yaw: 180}
)");
    write("scenes/room.yaml", R"(name: room
frame_rate: 30
boxes:
  - {name: west, min: [-4, 0, -4], max: [-3.8, 3, 4]}
  - {name: east, min: [3.8, 0, -4], max: [4, 3, 4]}
  - {name: north, min: [-4, 0, 3.8], max: [4, 3, 4]}
  - {name: south-a, min: [-4, 0, -4], max: [-0.8, 3, -3.8]}
  - {name: south-b, min: [0.8, 0, -4], max: [4, 3, -3.8]}
areas:
  - {name: room, kind: enclosed, min: [-4, 0, -4], max: [4, 3, 4]}
trajectory:
  - {t: 0, position: [0, 0, -6], yaw: 0}
  - {t: 1.5, position: [0, 0, 0], yaw: 0}
)");
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string write(const std::string& relative, const std::string& text) const {
    const std::filesystem::path p = path_ / relative;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  std::string path(const std::string& relative = "") const { return (path_ / relative).string(); }

 private:
  std::filesystem::path path_;
};

// A suite over the scratch directory's two scenes: 2 scenes x 2 camera solvers, plus 2 toy
// problems x 2 solvers: 8 deterministic runs.
inline constexpr const char* kTinySuite = R"(name: tiny
camera:
  scenes: [scenes/*.yaml]
  solvers:
    - occlusion-octree
    - {label: bourne-published, solver: bourne-octree, controller: {visibility_guard: false},
       area_adaptation: false}
problems:
  instances: [{nqueens: [6, 8]}]
  solvers: [sls, bnb]
)";

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace sightline::experiments::testing
