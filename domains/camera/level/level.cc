#include "sightline/domains/camera/level/level.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "sightline/domains/camera/level/mesh_import.h"
#include "sightline/domains/camera/level/q3_level.h"

namespace sightline::camera {
namespace {

std::string lower_extension(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Where a message about the level points: the scene's `level:` block when the spec came
// from a scene, else the level file itself.
csp::SourceLocation error_location(const LevelSpec& spec) {
  if (!spec.where.file.empty()) return spec.where;
  return csp::SourceLocation{spec.file, 0, 0};
}

[[noreturn]] void fail(const LevelSpec& spec, const std::string& message) {
  throw csp::InputError(error_location(spec), "level file '" + spec.file + "' " + message);
}

std::string point_text(const Eigen::Vector3f& p) {
  std::ostringstream out;
  out << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return out.str();
}

LevelTransform resolve_transform(const LevelSpec& spec) {
  const bool quake3 = is_quake3_level(spec.file);
  LevelTransform transform;
  transform.scale = spec.scale.value_or(quake3 ? 0.03125 : 1.0);
  transform.up = spec.up.value_or(quake3 ? UpAxis::kZ : UpAxis::kY);
  if (!(std::isfinite(transform.scale) && transform.scale > 0)) {
    std::ostringstream message;
    message << "has scale " << transform.scale
            << ": expected a finite number > 0 (metres per file unit)";
    fail(spec, message.str());
  }
  return transform;
}

// The checks every source gets, whatever read it: indices in range, finite vertices (a NaN
// would poison the triangle index and every distance computed from it), at least one
// triangle with an area. Zero-area triangles are dropped: they block nothing, and the
// ray queries need not see them.
void check_and_clean(const LevelSpec& spec, TriangleMesh& mesh) {
  const auto vertex_count = mesh.vertices.size();
  for (std::size_t i = 0; i < vertex_count; ++i) {
    if (!mesh.vertices[i].allFinite()) {
      fail(spec, "has a vertex that is not a finite number in the scene's frame: vertex " +
                     std::to_string(i) + " of " + std::to_string(vertex_count) + " is " +
                     point_text(mesh.vertices[i]) +
                     " (a NaN or infinity in the file, or a scale that overflows)");
    }
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (std::uint32_t i : tri) {
      if (i >= vertex_count) {
        fail(spec, "is corrupt: triangle " + std::to_string(t) + " uses vertex " +
                       std::to_string(i) + " of " + std::to_string(vertex_count));
      }
    }
    // The edges' cross product in double from float corners: for coordinates of similar
    // magnitude the differences and products are exact, so it is zero exactly when the
    // corners repeat or lie on one line.
    const Eigen::Vector3d a = mesh.vertices[tri[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[tri[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[tri[2]].cast<double>();
    if ((b - a).cross(c - a).squaredNorm() > 0) mesh.triangles[kept++] = tri;
  }
  const std::size_t dropped = mesh.triangles.size() - kept;
  mesh.triangles.resize(kept);
  if (mesh.triangles.empty()) {
    fail(spec,
         "has no solid triangles" +
             (dropped == 1  ? std::string(" (its only triangle has zero area)")
              : dropped > 1 ? " (all " + std::to_string(dropped) + " triangles have zero area)"
                            : std::string()));
  }
}

}  // namespace

bool is_quake3_level(const std::string& file) {
  const std::string ext = lower_extension(file);
  return ext == ".bsp" || ext == ".pk3";
}

Level load_level(const LevelSpec& spec) {
  std::error_code error;
  const auto status = std::filesystem::status(spec.file, error);
  if (!std::filesystem::exists(status)) fail(spec, "does not exist");
  if (std::filesystem::is_directory(status)) fail(spec, "is a directory, not a file");

  const LevelTransform transform = resolve_transform(spec);
  const auto start = std::chrono::steady_clock::now();
  Level level = is_quake3_level(spec.file) ? load_quake3_level(spec, transform)
                                           : load_mesh_level(spec, transform);
  level.file = spec.file;
  level.transform = transform;
  check_and_clean(spec, level.mesh);
  level.load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return level;
}

}  // namespace sightline::camera
