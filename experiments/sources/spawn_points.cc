#include "sightline/experiments/sources/spawn_points.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

#include "sightline/domains/camera/level/pk3_archive.h"
#include "sightline/domains/camera/level/q3_bsp.h"

namespace sightline::experiments {
namespace {

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() &&
         text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}
std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return text;
}

bool is_spawn(const std::string& classname) {
  const std::string c = lower(classname);
  return c.rfind("info_player_", 0) == 0 ||
         (c.rfind("team_ctf_", 0) == 0 && (ends_with(c, "player") || ends_with(c, "spawn")));
}

// The entity lump: { "key" "value" ... } blocks. Only quoted pairs matter here.
std::vector<Eigen::Vector3d> spawn_origins(const std::string& entities) {
  std::vector<Eigen::Vector3d> out;
  std::string classname, origin, key;
  bool have_key = false;
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const char c = entities[i];
    if (c == '{') {
      classname.clear(), origin.clear(), have_key = false;
    } else if (c == '}') {
      Eigen::Vector3d p;
      std::istringstream in(origin);
      if (is_spawn(classname) && in >> p.x() >> p.y() >> p.z()) out.push_back(p);
    } else if (c == '"') {
      const std::size_t end = entities.find('"', i + 1);
      if (end == std::string::npos) break;
      const std::string token = entities.substr(i + 1, end - i - 1);
      i = end;
      if (!have_key) {
        key = token;
      } else if (key == "classname") {
        classname = token;
      } else if (key == "origin") {
        origin = token;
      }
      have_key = !have_key;
    }
  }
  return out;
}

}  // namespace

std::vector<Eigen::Vector3d> quake3_spawn_points(const camera::LevelSpec& spec,
                                                 const camera::LevelTransform& transform) {
  if (!camera::is_quake3_level(spec.file)) return {};
  std::vector<unsigned char> bytes;
  std::string source = spec.file;
  if (ends_with(lower(spec.file), ".pk3")) {
    const camera::Pk3Archive archive(spec.file);
    const std::string entry = archive.select_map(spec.map);
    bytes = archive.read(entry);
    source += " (" + entry + ")";
  } else {
    std::ifstream in(spec.file, std::ios::binary);
    if (!in) throw csp::InputError(csp::SourceLocation{spec.file, 0, 0}, "cannot open the map");
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& p : spawn_origins(camera::q3::parse_bsp(bytes, source).entities)) {
    out.push_back(transform.to_scene(p));
  }
  return out;
}

}  // namespace sightline::experiments
