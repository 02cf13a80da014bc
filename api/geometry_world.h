// GeometryWorld: sightline's own geometry (boxes and triangles) as a sightline::World.
//
// It holds a camera::Scene with no path and no profile, only for its index; a Camera handed
// a GeometryWorld films that scene's index directly (packed sight lines, nearby boxes), not
// through the virtual interface, so sightline's own worlds keep their speed.
#pragma once

#include <memory>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/world.h"

namespace sightline {

class GeometryWorld final : public World {
 public:
  GeometryWorld(std::vector<camera::SolidBox> boxes, std::shared_ptr<camera::Level> level);

  std::optional<WorldHit> first_hit(const Vec3& a, const Vec3& b, double t) const override;
  double clearance(const Vec3& p, double limit, double t) const override;
  bool line_of_sight(const Vec3& a, const Vec3& b, double t) const override;
  std::optional<NearestSurface> nearest_surface(const Vec3& p, double limit,
                                                double t) const override;
  bool open_at(const Vec3& p, double t) const override;

  // The index, for a camera to copy (a Scene shares its triangle index between copies).
  const camera::Scene& scene() const { return scene_; }

 private:
  camera::Scene scene_;
};

}  // namespace sightline
