#include "sightline/domains/camera/level/q3_level.h"

#include <chrono>
#include <fstream>
#include <iterator>
#include <memory>

#include "sightline/domains/camera/level/pk3_archive.h"
#include "sightline/domains/camera/level/q3_bsp.h"
#include "sightline/domains/camera/level/q3_solid.h"

namespace sightline::camera {

namespace {

bool has_pk3_extension(const std::string& file) {
  if (file.size() < 4) return false;
  std::string ext = file.substr(file.size() - 4);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".pk3";
}

std::vector<unsigned char> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw csp::InputError(csp::SourceLocation{path, 0, 0},
                          "cannot open the map: no such file or not readable");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
  if (in.bad()) throw csp::InputError(csp::SourceLocation{path, 0, 0}, "cannot read the map");
  return bytes;
}

}  // namespace

Level load_quake3_level(const LevelSpec& spec, const LevelTransform& transform) {
  const auto start = std::chrono::steady_clock::now();
  Level level;
  level.file = spec.file;
  level.format = "Quake III BSP (IBSP 46)";
  level.transform = transform;

  std::vector<unsigned char> bytes;
  std::string source = spec.file;
  if (has_pk3_extension(spec.file)) {
    const Pk3Archive archive(spec.file);
    const std::string entry = archive.select_map(spec.map);
    bytes = archive.read(entry);
    level.map = entry.substr(5, entry.size() - 5 - 4);  // "maps/oa_thor.bsp" -> "oa_thor"
    source = spec.file + " (" + entry + ")";
  } else {
    bytes = read_file(spec.file);
  }

  q3::Bsp bsp = q3::parse_bsp(bytes, source);
  if (bsp.triangles.empty()) {
    throw csp::InputError(csp::SourceLocation{source, 0, 0},
                          "the map has no solid drawn faces: no triangles to load");
  }
  level.mesh.vertices.reserve(bsp.vertices.size());
  for (const auto& v : bsp.vertices) level.mesh.vertices.push_back(transform.to_scene(v));
  level.mesh.triangles = std::move(bsp.triangles);
  level.solid = std::make_shared<Q3SolidVolume>(std::move(bsp.tree), transform);
  level.load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return level;
}

}  // namespace sightline::camera
