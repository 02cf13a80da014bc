// SceneWorld: an experiment scene's geometry (boxes, level, and the movers where their
// keyframes put them at each query's time) as a sightline::World, the interface a game
// implements. It lets the public camera film a scene file through that interface, as a game
// would, and the tests compare it with the camera that asks the scene directly.
//
// Stateless and const: each query places the movers at its own time (a loop over them, as
// few as a scene's people and doors), so it answers from several threads at once.
#pragma once

#include "sightline/domains/camera/scene.h"
#include "sightline/world.h"

namespace sightline::camera {

class SceneWorld final : public sightline::World {
 public:
  // `scene` must outlive this object.
  explicit SceneWorld(const Scene& scene) : scene_(&scene) {}

  std::optional<sightline::WorldHit> first_hit(const sightline::Vec3& a, const sightline::Vec3& b,
                                               double t) const override;
  double clearance(const sightline::Vec3& p, double limit, double t) const override;
  bool line_of_sight(const sightline::Vec3& a, const sightline::Vec3& b, double t) const override;
  std::optional<sightline::NearestSurface> nearest_surface(const sightline::Vec3& p, double limit,
                                                           double t) const override;
  bool open_at(const sightline::Vec3& p, double t) const override;

 private:
  const Scene* scene_;
};

}  // namespace sightline::camera
