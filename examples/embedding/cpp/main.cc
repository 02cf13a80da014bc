// main.cc: sightline's chase camera embedded in a C++ program, over the program's own world.
//
// A game that embeds sightline keeps its own physics: it subclasses sightline::World and
// answers the camera's questions (what does this segment hit first, is this sight line clear,
// how far is the nearest surface) with its own queries. This example plays the game: it loads
// a Quake III level's triangles, indexes them with its own bounding-volume hierarchy
// (triangle_bvh.h), replays a recorded walk (walk.h) and films it at 60 frames per second,
// writing one CSV row per frame and a summary of cuts, visibility and time per frame.
//
//   usage: sightline_cpp_example [walk.csv] [trace_out.csv]
//   defaults: oa_thor-walk1.csv and trace.csv in the current folder (the build copies the
//   walk next to the executable); SIGHTLINE_EXAMPLE_PK3 and SIGHTLINE_EXAMPLE_MAP choose
//   another level.
//   Exit: 0 done, 1 an error, 77 the level's .pk3 is not installed (a skip).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "sightline/camera.h"
#include "sightline/level.h"
#include "sightline/world.h"
#include "triangle_bvh.h"
#include "walk.h"

namespace example {
namespace {

constexpr double kFrameRate = 60;
constexpr const char* kDefaultPk3 = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3";
constexpr const char* kDefaultMap = "oa_thor";
constexpr int kExitSkip = 77;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The game's world as sightline sees it: every query answered by the example's own index.
// The level is static, so the time t is not needed. The query counters are relaxed atomics
// because a World may serve cameras on several threads at once.
class LevelWorld final : public sightline::World {
 public:
  struct Counts {
    std::uint64_t first_hits = 0, lines_of_sight = 0, clearances = 0;
  };

  explicit LevelWorld(TriangleBvh index) : index_(std::move(index)) {}

  std::optional<sightline::WorldHit> first_hit(const sightline::Vec3& a, const sightline::Vec3& b,
                                               double /*t*/) const override {
    first_hits_.fetch_add(1, std::memory_order_relaxed);
    const auto hit = index_.first_hit(from_sightline(a), from_sightline(b));
    if (!hit) return std::nullopt;
    return sightline::WorldHit{hit->fraction, to_sightline(hit->normal)};
  }

  double clearance(const sightline::Vec3& p, double limit, double /*t*/) const override {
    clearances_.fetch_add(1, std::memory_order_relaxed);
    return index_.clearance(from_sightline(p), limit);
  }

  bool line_of_sight(const sightline::Vec3& a, const sightline::Vec3& b,
                     double /*t*/) const override {
    lines_of_sight_.fetch_add(1, std::memory_order_relaxed);
    return index_.line_of_sight(from_sightline(a), from_sightline(b));
  }

  Counts counts() const {
    return {first_hits_.load(std::memory_order_relaxed),
            lines_of_sight_.load(std::memory_order_relaxed),
            clearances_.load(std::memory_order_relaxed)};
  }

 private:
  TriangleBvh index_;
  mutable std::atomic<std::uint64_t> first_hits_{0}, lines_of_sight_{0}, clearances_{0};
};

struct LevelDeleter {
  void operator()(sl_level* level) const { sl_level_destroy(level); }
};

// Loads the level through the levels component's C API and indexes its triangles.
TriangleBvh load_index(const std::string& pk3, const std::string& map) {
  const std::unique_ptr<sl_level, LevelDeleter> level(sl_level_load(pk3.c_str(), map.c_str()));
  if (!level) throw std::runtime_error(std::string("sl_level_load: ") + sl_level_last_error());
  const double* vertices = nullptr;
  const std::uint32_t* indices = nullptr;
  std::size_t vertex_count = 0, triangle_count = 0;
  sl_level_triangles(level.get(), &vertices, &vertex_count, &indices, &triangle_count);
  const auto start = Clock::now();
  TriangleBvh index({vertices, 3 * vertex_count}, {indices, 3 * triangle_count});
  const double seconds = seconds_since(start);
  std::printf("map %s in %s: %zu triangles, %zu vertices\n", map.c_str(), pk3.c_str(),
              triangle_count, vertex_count);
  std::printf("own BVH: %zu triangles, %zu nodes, built in %.1f ms\n", index.triangle_count(),
              index.node_count(), seconds * 1e3);
  return index;  // holds its own copy of the triangles: the level is freed here
}

sightline::PersonState person_at(const Walk& walk, double t) {
  const WalkState s = walk.at(t);
  return {to_sightline(s.position), to_sightline(s.velocity), s.yaw};
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

struct RunTotals {
  std::size_t cuts = 0, hidden = 0;
  std::vector<double> update_us;  // wall time of each Camera::update, microseconds
  LevelWorld::Counts queries;     // asked during the updates
};

void write_row(std::FILE* trace, std::size_t frame, double t, const sightline::PersonState& c,
               const sightline::CameraPose& pose) {
  const int written = std::fprintf(
      trace, "%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%.6g,%.1f\n", frame, t,
      c.position.x, c.position.y, c.position.z, c.yaw, pose.position.x, pose.position.y,
      pose.position.z, pose.target.x, pose.target.y, pose.target.z, pose.cut ? 1 : 0, pose.cost,
      pose.solve_seconds * 1e6);
  if (written < 0) throw std::runtime_error("cannot write the trace");
}

// Creates the camera at the walk's first frame and films the walk: one camera update and one
// trace row per frame.
RunTotals film(const std::shared_ptr<const LevelWorld>& world, const Walk& walk, std::FILE* trace) {
  const double t0 = walk.frame_time(0, kFrameRate);
  const sightline::PersonState first = person_at(walk, t0);
  // Default settings: the "anticipating" profile, one default person.
  sightline::Camera camera(world, sightline::CameraSettings{}, std::span(&first, 1), t0);
  const LevelWorld::Counts before = world->counts();
  if (std::fputs("frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,"
                 "target_x,target_y,target_z,cut,cost,solve_us\n",
                 trace) < 0) {
    throw std::runtime_error("cannot write the trace");
  }
  RunTotals totals;
  const std::size_t frames = walk.frame_count(kFrameRate);
  totals.update_us.reserve(frames);
  double previous_t = t0;
  for (std::size_t k = 0; k < frames; ++k) {
    const double t = walk.frame_time(k, kFrameRate);
    const sightline::PersonState person = person_at(walk, t);
    // Frame 0 is an update too: the camera's first frame, with the first state and a nominal
    // dt of one frame (as the C example, whose API has no pose getter, and sightline's own
    // experiment runner do).
    const double dt = k == 0 ? 1 / kFrameRate : t - previous_t;
    const auto start = Clock::now();
    const sightline::CameraPose& pose = camera.update(std::span(&person, 1), dt);
    totals.update_us.push_back(seconds_since(start) * 1e6);
    if (pose.cut) ++totals.cuts;
    if (!pose.look_at_visible) ++totals.hidden;
    write_row(trace, k, t, person, pose);
    previous_t = t;
  }
  const LevelWorld::Counts after = world->counts();
  totals.queries = {after.first_hits - before.first_hits,
                    after.lines_of_sight - before.lines_of_sight,
                    after.clearances - before.clearances};
  return totals;
}

// The p-th quantile (nearest rank) of sorted values.
double quantile(const std::vector<double>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[rank > 0 ? rank - 1 : 0];
}

void print_summary(const Walk& walk, RunTotals& totals) {
  const auto n = static_cast<double>(totals.update_us.size());
  std::sort(totals.update_us.begin(), totals.update_us.end());
  std::printf("frames: %zu over %.1f s (%zu keyframes)\n", totals.update_us.size(),
              walk.end() - walk.start(), walk.keyframes().size());
  std::printf("cuts: %zu\n", totals.cuts);
  std::printf("frames with look_at_visible = 0 (the camera's own flag): %zu\n", totals.hidden);
  std::printf("update time per frame: median %.1f us, p99 %.1f us\n",
              quantile(totals.update_us, 0.5), quantile(totals.update_us, 0.99));
  std::printf("world queries per frame: %.1f line_of_sight, %.1f first_hit, %.1f clearance\n",
              static_cast<double>(totals.queries.lines_of_sight) / n,
              static_cast<double>(totals.queries.first_hits) / n,
              static_cast<double>(totals.queries.clearances) / n);
}

std::string env_or(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value && value[0] ? value : fallback;
}

int run(int argc, char** argv) {
  if (argc > 3) {
    std::fprintf(stderr, "usage: %s [walk.csv] [trace_out.csv]\n", argv[0]);
    return 1;
  }
  const std::string walk_path = argc > 1 ? argv[1] : "oa_thor-walk1.csv";
  const std::string trace_path = argc > 2 ? argv[2] : "trace.csv";
  const std::string pk3 = env_or("SIGHTLINE_EXAMPLE_PK3", kDefaultPk3);
  const std::string map = env_or("SIGHTLINE_EXAMPLE_MAP", kDefaultMap);
  if (!std::filesystem::exists(pk3)) {
    std::printf("skipped: %s is not installed (OpenArena's data; or set SIGHTLINE_EXAMPLE_PK3)\n",
                pk3.c_str());
    return kExitSkip;
  }
  std::printf("sightline %s, C++ API, the example's own world\n", sightline::version());

  const Walk walk = Walk::read(walk_path);
  const auto world = std::make_shared<const LevelWorld>(load_index(pk3, map));
  File trace(std::fopen(trace_path.c_str(), "w"));
  if (!trace) throw std::runtime_error(trace_path + ": cannot create the trace file");
  RunTotals totals = film(world, walk, trace.get());
  if (std::fclose(trace.release()) != 0) {
    throw std::runtime_error(trace_path + ": cannot write the trace file");
  }
  print_summary(walk, totals);
  std::printf("trace: %s\n", trace_path.c_str());
  return 0;
}

}  // namespace
}  // namespace example

int main(int argc, char** argv) {
  try {
    return example::run(argc, argv);
  } catch (const sightline::Error& e) {
    std::fprintf(stderr, "sightline: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
  return 1;
}
