#include "domains/camera/scene_at_time.h"

#include <algorithm>

#include "domains/camera/constraints/clearance.h"
#include "domains/camera/geometry/segment_box.h"

namespace sightline::camera {

SceneAtTime::SceneAtTime(const Scene& scene)
    : scene_(&scene),
      boxes_(scene.movers().size()),
      segments_(scene.movers().size(), 0) {
  set_time(scene.trajectory().start_time());
}

void SceneAtTime::set_time(double t) {
  time_ = t;
  bounds_ = Aabb::empty();
  const std::vector<Mover>& movers = scene_->movers();
  for (std::size_t i = 0; i < movers.size(); ++i) {
    boxes_[i] = Aabb::around_feet(movers[i].position_at(t, &segments_[i]), movers[i].size());
    bounds_.merge(boxes_[i]);
  }
}

void SceneAtTime::set_time_extrapolated(double now, double ahead) {
  time_ = now + ahead;
  bounds_ = Aabb::empty();
  const std::vector<Mover>& movers = scene_->movers();
  for (std::size_t i = 0; i < movers.size(); ++i) {
    const Eigen::Vector3d p = movers[i].position_at(now, &segments_[i]);
    boxes_[i] = Aabb::around_feet(p + ahead * movers[i].velocity_at(now), movers[i].size());
    bounds_.merge(boxes_[i]);
  }
}

bool SceneAtTime::mover_blocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (boxes_.empty() || !segment_hits_box(a, b, bounds_)) return false;
  for (const Aabb& box : boxes_) {
    if (segment_hits_box(a, b, box)) return true;
  }
  return false;
}

std::optional<SurfaceHit> SceneAtTime::first_hit(const Eigen::Vector3d& a,
                                                 const Eigen::Vector3d& b) const {
  std::optional<SurfaceHit> best = scene_->first_hit(a, b);
  if (boxes_.empty()) return best;
  const Eigen::Vector3d delta = b - a;
  SegmentClip clip;
  if (!clip_segment_to_box(a, delta, bounds_, best ? best->t : 1.0, clip)) return best;
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (!clip_segment_to_box(a, delta, boxes_[i], best ? best->t : 1.0, clip)) continue;
    if (best && clip.enter >= best->t) continue;
    SurfaceHit hit;
    hit.t = clip.enter;
    hit.source = SurfaceHit::Source::kMover;
    hit.index = static_cast<std::uint32_t>(i);
    if (hit.t > 0) hit.normal = boxes_[i].nearest_face_normal(a + hit.t * delta);
    best = hit;
  }
  return best;
}

double SceneAtTime::clearance(const Eigen::Vector3d& p, double limit) const {
  double d = scene_->clearance(p, limit);
  for (const Aabb& box : boxes_) d = std::min(d, box.signed_distance(p));
  return std::min(d, limit);
}

std::optional<NearestSurface> SceneAtTime::nearest_surface(const Eigen::Vector3d& p,
                                                           double limit) const {
  std::optional<NearestSurface> best = scene_->nearest_surface(p, limit);
  for (const Aabb& box : boxes_) {
    const double d = box.signed_distance(p);
    if (d >= limit || (best && d >= best->signed_distance)) continue;
    best = NearestSurface{d, signed_distance_gradient(box, p)};
  }
  return best;
}

bool SceneAtTime::open_at(const Eigen::Vector3d& p) const {
  if (!scene_->open_at(p)) return false;
  for (const Aabb& box : boxes_) {
    if (box.contains(p)) return false;
  }
  return true;
}

}  // namespace sightline::camera
