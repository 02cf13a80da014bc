#include "domains/camera/scene_at_time.h"

#include <algorithm>

#include "domains/camera/constraints/clearance.h"
#include "domains/camera/geometry/segment_box.h"

namespace sightline::camera {

SceneAtTime::SceneAtTime(const Scene& scene)
    : scene_(&scene),
      boxes_(scene.movers().size()),
      segments_(scene.movers().size(), 0),
      order_(scene.movers().size()),
      group_bounds_((scene.movers().size() + kGroupSize - 1) / kGroupSize) {
  set_time(scene.trajectory().start_time());
}

void SceneAtTime::set_time(double t) {
  time_ = t;
  const std::vector<Mover>& movers = scene_->movers();
  for (std::size_t i = 0; i < movers.size(); ++i) {
    boxes_[i] = Aabb::around_feet(movers[i].position_at(t, &segments_[i]), movers[i].size());
  }
  regroup();
}

void SceneAtTime::regroup() {
  bounds_ = Aabb::empty();
  for (const Aabb& box : boxes_) bounds_.merge(box);
  if (boxes_.empty()) return;
  const Eigen::Vector3d extent = bounds_.max - bounds_.min;
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (extent[i] > extent[axis]) axis = i;
  }
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<std::uint32_t>(i);
  std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
    return boxes_[a].min[axis] + boxes_[a].max[axis] < boxes_[b].min[axis] + boxes_[b].max[axis];
  });
  for (std::size_t g = 0; g < group_bounds_.size(); ++g) {
    group_bounds_[g] = Aabb::empty();
    const std::size_t end = std::min(order_.size(), (g + 1) * kGroupSize);
    for (std::size_t k = g * kGroupSize; k < end; ++k) group_bounds_[g].merge(boxes_[order_[k]]);
  }
}

void SceneAtTime::set_time_extrapolated(double now, double ahead) {
  time_ = now + ahead;
  const std::vector<Mover>& movers = scene_->movers();
  for (std::size_t i = 0; i < movers.size(); ++i) {
    const Eigen::Vector3d p = movers[i].position_at(now, &segments_[i]);
    boxes_[i] = Aabb::around_feet(p + ahead * movers[i].velocity_at(now), movers[i].size());
  }
  regroup();
}

bool SceneAtTime::mover_blocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (boxes_.empty() || !segment_hits_box(a, b, bounds_)) return false;
  for (std::size_t g = 0; g < group_bounds_.size(); ++g) {
    if (!segment_hits_box(a, b, group_bounds_[g])) continue;
    const std::size_t end = std::min(order_.size(), (g + 1) * kGroupSize);
    for (std::size_t k = g * kGroupSize; k < end; ++k) {
      if (segment_hits_box(a, b, boxes_[order_[k]])) return true;
    }
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
  for (std::size_t g = 0; g < group_bounds_.size(); ++g) {
    if (!clip_segment_to_box(a, delta, group_bounds_[g], best ? best->t : 1.0, clip)) continue;
    const std::size_t end = std::min(order_.size(), (g + 1) * kGroupSize);
    for (std::size_t k = g * kGroupSize; k < end; ++k) {
      const std::size_t i = order_[k];
      if (!clip_segment_to_box(a, delta, boxes_[i], best ? best->t : 1.0, clip)) continue;
      // Equal entries: the lower mover index wins, as in index order.
      if (best && (clip.enter > best->t ||
                   (clip.enter == best->t && (best->source != SurfaceHit::Source::kMover ||
                                              best->index < i)))) {
        continue;
      }
      SurfaceHit hit;
      hit.t = clip.enter;
      hit.source = SurfaceHit::Source::kMover;
      hit.index = static_cast<std::uint32_t>(i);
      if (hit.t > 0) hit.normal = boxes_[i].nearest_face_normal(a + hit.t * delta);
      best = hit;
    }
  }
  return best;
}

double SceneAtTime::clearance(const Eigen::Vector3d& p, double limit) const {
  double d = scene_->clearance(p, limit);
  for (std::size_t g = 0; g < group_bounds_.size(); ++g) {
    // Outside a group's bounds, its members are at least as far as the bounds.
    if (group_bounds_[g].signed_distance(p) >= d) continue;
    const std::size_t end = std::min(order_.size(), (g + 1) * kGroupSize);
    for (std::size_t k = g * kGroupSize; k < end; ++k) {
      d = std::min(d, boxes_[order_[k]].signed_distance(p));
    }
  }
  return std::min(d, limit);
}

std::optional<NearestSurface> SceneAtTime::nearest_surface(const Eigen::Vector3d& p,
                                                           double limit) const {
  std::optional<NearestSurface> best = scene_->nearest_surface(p, limit);
  for (std::size_t g = 0; g < group_bounds_.size(); ++g) {
    const double bound = group_bounds_[g].signed_distance(p);
    if (bound >= limit || (best && bound >= best->signed_distance)) continue;
    const std::size_t end = std::min(order_.size(), (g + 1) * kGroupSize);
    for (std::size_t k = g * kGroupSize; k < end; ++k) {
      const Aabb& box = boxes_[order_[k]];
      const double d = box.signed_distance(p);
      if (d >= limit || (best && d >= best->signed_distance)) continue;
      best = NearestSurface{d, signed_distance_gradient(box, p)};
    }
  }
  return best;
}

bool SceneAtTime::open_at(const Eigen::Vector3d& p) const {
  if (!scene_->open_at(p)) return false;
  // As Scene::open_at: strictly inside a box is closed, its faces are open.
  for (const Aabb& box : boxes_) {
    if (box.signed_distance(p) < 0) return false;
  }
  return true;
}

}  // namespace sightline::camera
