#include "domains/camera/scene_at_time.h"

#include <algorithm>

#include "domains/camera/constraints/clearance.h"
#include "domains/camera/geometry/segment_box.h"

namespace sightline::camera {

SceneAtTime::SceneAtTime(const Scene& scene)
    : scene_(&scene),
      boxes_(scene.movers().size()),
      segments_(scene.movers().size(), 0),
      use_tree_(scene.movers().size() > kFlatMovers) {
  set_time(scene.trajectory().start_time());
  if (use_tree_) tree_ = BoxTree(boxes_);
}

void SceneAtTime::set_time(double t) {
  time_ = t;
  bounds_ = Aabb::empty();
  const std::vector<Mover>& movers = scene_->movers();
  for (std::size_t i = 0; i < movers.size(); ++i) {
    boxes_[i] = Aabb::around_feet(movers[i].position_at(t, &segments_[i]), movers[i].size());
    bounds_.merge(boxes_[i]);
  }
  if (use_tree_ && tree_.size() == boxes_.size()) tree_.refit(boxes_);
}

bool SceneAtTime::mover_blocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (boxes_.empty() || !segment_hits_box(a, b, bounds_)) return false;
  if (use_tree_) return tree_.segment_blocked(a, b);
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
  if (use_tree_) {
    const auto hit = tree_.first_hit(a, b);
    if (!hit || (best && hit->t >= best->t)) return best;
    SurfaceHit mover;
    mover.t = hit->t;
    mover.source = SurfaceHit::Source::kMover;
    mover.index = hit->box;
    if (mover.t > 0) mover.normal = boxes_[hit->box].nearest_face_normal(a + mover.t * delta);
    return mover;
  }
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
  if (use_tree_) {
    if (const auto near = tree_.nearest(p, d)) d = std::min(d, near->signed_distance);
    return d;
  }
  for (const Aabb& box : boxes_) d = std::min(d, box.signed_distance(p));
  return std::min(d, limit);
}

std::optional<NearestSurface> SceneAtTime::nearest_surface(const Eigen::Vector3d& p,
                                                           double limit) const {
  std::optional<NearestSurface> best = scene_->nearest_surface(p, limit);
  if (use_tree_) {
    const auto near = tree_.nearest(p, best ? best->signed_distance : limit);
    if (near && (!best || near->signed_distance < best->signed_distance)) {
      best = NearestSurface{near->signed_distance,
                            signed_distance_gradient(boxes_[near->box], p)};
    }
    return best;
  }
  for (const Aabb& box : boxes_) {
    const double d = box.signed_distance(p);
    if (d >= limit || (best && d >= best->signed_distance)) continue;
    best = NearestSurface{d, signed_distance_gradient(box, p)};
  }
  return best;
}

bool SceneAtTime::open_at(const Eigen::Vector3d& p) const {
  if (!scene_->open_at(p)) return false;
  // As Scene::open_at: strictly inside a box is closed, its faces are open.
  if (use_tree_) return !tree_.nearest(p, 0.0);
  for (const Aabb& box : boxes_) {
    if (box.signed_distance(p) < 0) return false;
  }
  return true;
}

}  // namespace sightline::camera
