#include "sightline/domains/camera/scene_world.h"

#include <algorithm>

#include "sightline/domains/camera/constraints/clearance.h"
#include "sightline/domains/camera/geometry/segment_box.h"

namespace sightline::camera {

namespace {

Eigen::Vector3d eigen(const sightline::Vec3& v) { return {v.x, v.y, v.z}; }
sightline::Vec3 plain(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

std::optional<sightline::WorldHit> SceneWorld::first_hit(const sightline::Vec3& a,
                                                         const sightline::Vec3& b, double t) const {
  const Eigen::Vector3d pa = eigen(a), pb = eigen(b), delta = pb - pa;
  std::optional<SurfaceHit> best = scene_->first_hit(pa, pb);
  for (const Mover& m : scene_->movers()) {
    const Aabb box = m.box_at(t);
    SegmentClip clip;
    if (!clip_segment_to_box(pa, delta, box, best ? best->t : 1.0, clip)) continue;
    if (best && clip.enter >= best->t) continue;
    SurfaceHit hit;
    hit.t = clip.enter;
    if (hit.t > 0) hit.normal = box.nearest_face_normal(pa + hit.t * delta);
    best = hit;
  }
  if (!best) return std::nullopt;
  return sightline::WorldHit{best->t, plain(best->normal)};
}

double SceneWorld::clearance(const sightline::Vec3& p, double limit, double t) const {
  const Eigen::Vector3d q = eigen(p);
  double d = scene_->clearance(q, limit);
  for (const Mover& m : scene_->movers()) d = std::min(d, m.box_at(t).signed_distance(q));
  return std::min(d, limit);
}

bool SceneWorld::line_of_sight(const sightline::Vec3& a, const sightline::Vec3& b, double t) const {
  const Eigen::Vector3d pa = eigen(a), pb = eigen(b);
  if (!scene_->line_of_sight(pa, pb)) return false;
  return std::none_of(scene_->movers().begin(), scene_->movers().end(),
                      [&](const Mover& m) { return segment_hits_box(pa, pb, m.box_at(t)); });
}

std::optional<sightline::NearestSurface> SceneWorld::nearest_surface(const sightline::Vec3& p,
                                                                     double limit, double t) const {
  const Eigen::Vector3d q = eigen(p);
  std::optional<NearestSurface> best = scene_->nearest_surface(q, limit);
  for (const Mover& m : scene_->movers()) {
    const Aabb box = m.box_at(t);
    const double d = box.signed_distance(q);
    if (d >= limit || (best && d >= best->signed_distance)) continue;
    best = NearestSurface{d, signed_distance_gradient(box, q)};
  }
  if (!best) return std::nullopt;
  return sightline::NearestSurface{best->signed_distance, plain(best->gradient)};
}

bool SceneWorld::open_at(const sightline::Vec3& p, double t) const {
  const Eigen::Vector3d q = eigen(p);
  if (!scene_->open_at(q)) return false;
  return std::none_of(scene_->movers().begin(), scene_->movers().end(),
                      [&](const Mover& m) { return m.box_at(t).signed_distance(q) < 0; });
}

}  // namespace sightline::camera
