// make_geometry_world: sightline's own geometry (boxes in a BoxTree, triangles in Embree)
// behind the public interface.
#include "sightline/world.h"

#include <cmath>

#include "api/geometry_world.h"
#include "api/conversions.h"

namespace sightline {

std::shared_ptr<const World> make_geometry_world(const WorldGeometry& geometry) {
  std::vector<camera::SolidBox> solids;
  solids.reserve(geometry.boxes.size());
  for (std::size_t i = 0; i < geometry.boxes.size(); ++i) {
    const Box& b = geometry.boxes[i];
    if (!finite(b.min) || !finite(b.max)) {
      throw Error("geometry: box " + std::to_string(i) + " has a coordinate that is not finite");
    }
    if (!(b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z)) {
      throw Error("geometry: box " + std::to_string(i) +
                  " needs min < max on every axis");
    }
    solids.push_back(camera::SolidBox{"", camera::Aabb{to_eigen(b.min), to_eigen(b.max)}, {}});
  }
  if (geometry.triangle_indices.size() % 3 != 0) {
    throw Error("geometry: triangle indices come in threes, got " +
                std::to_string(geometry.triangle_indices.size()));
  }
  auto level = std::make_shared<camera::Level>();
  level->format = "triangles (sightline::WorldGeometry)";
  level->mesh.vertices.reserve(geometry.vertices.size());
  for (std::size_t i = 0; i < geometry.vertices.size(); ++i) {
    const Vec3& v = geometry.vertices[i];
    if (!finite(v)) throw Error("geometry: vertex " + std::to_string(i) + " is not finite");
    level->mesh.vertices.emplace_back(static_cast<float>(v.x), static_cast<float>(v.y),
                                      static_cast<float>(v.z));
  }
  for (std::size_t i = 0; i < geometry.triangle_indices.size(); i += 3) {
    std::array<std::uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      t[k] = geometry.triangle_indices[i + k];
      if (t[k] >= geometry.vertices.size()) {
        throw Error("geometry: triangle " + std::to_string(i / 3) + " names vertex " +
                    std::to_string(t[k]) + ", past the " +
                    std::to_string(geometry.vertices.size()) + " vertices");
      }
    }
    level->mesh.triangles.push_back(t);
  }
  return std::make_shared<const GeometryWorld>(std::move(solids), std::move(level));
}

GeometryWorld::GeometryWorld(std::vector<camera::SolidBox> boxes,
                             std::shared_ptr<camera::Level> level)
    : scene_("world", std::move(boxes), {}, camera::CharacterShape{},
             camera::Trajectory({camera::Keyframe{}})) {
  if (!level->mesh.empty()) scene_.set_level(std::move(level));
}

std::optional<WorldHit> GeometryWorld::first_hit(const Vec3& a, const Vec3& b, double) const {
  const auto hit = scene_.first_hit(to_eigen(a), to_eigen(b));
  if (!hit) return std::nullopt;
  return WorldHit{hit->t, to_vec3(hit->normal)};
}

double GeometryWorld::clearance(const Vec3& p, double limit, double) const {
  return scene_.clearance(to_eigen(p), limit);
}

bool GeometryWorld::line_of_sight(const Vec3& a, const Vec3& b, double) const {
  return scene_.line_of_sight(to_eigen(a), to_eigen(b));
}

std::optional<NearestSurface> GeometryWorld::nearest_surface(const Vec3& p, double limit,
                                                             double) const {
  const auto s = scene_.nearest_surface(to_eigen(p), limit);
  if (!s) return std::nullopt;
  return NearestSurface{s->signed_distance, to_vec3(s->gradient)};
}

bool GeometryWorld::open_at(const Vec3& p, double) const { return scene_.open_at(to_eigen(p)); }

}  // namespace sightline
