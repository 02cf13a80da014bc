#include "sightline/domains/camera/scene_at_time.h"

#include <algorithm>
#include <cmath>

#include "sightline/domains/camera/constraints/clearance.h"
#include "sightline/domains/camera/geometry/segment_box.h"

namespace sightline::camera {

namespace {

sightline::Vec3 to_vec3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d to_eigen(const sightline::Vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

bool SceneAtTime::world_line_of_sight(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  return world_->line_of_sight(to_vec3(a), to_vec3(b), time_);
}

std::optional<NearestSurface> SceneAtTime::world_nearest_surface(const Eigen::Vector3d& p,
                                                                 double limit) const {
  const auto s = world_->nearest_surface(to_vec3(p), limit, time_);
  if (!s) return std::nullopt;
  return NearestSurface{s->signed_distance, to_eigen(s->gradient)};
}

SceneAtTime::SceneAtTime(const Scene& scene)
    : scene_(&scene),
      world_(scene.world()),
      boxes_(scene.movers().size()),
      segments_(scene.movers().size(), 0),
      order_(scene.movers().size()),
      group_bounds_((scene.movers().size() + kGroupSize - 1) / kGroupSize) {
  near_movers_.reserve(scene.movers().size());
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

void SceneAtTime::find_near_movers() {
  near_movers_.clear();
  near_region_ = Aabb::empty();
  if (!nearby_) return;
  const Aabb& region = nearby_->region();
  if (!region.contains(region.min)) return;  // covers nothing
  // Movers touching the region grown by 1 mm: one that close to a segment inside the region
  // is listed too, so the exact test's rounding cannot matter.
  const Eigen::Vector3d slack(1e-3, 1e-3, 1e-3);
  const Aabb grown{region.min - slack, region.max + slack};
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const Aabb& b = boxes_[i];
    if ((b.min.array() <= grown.max.array()).all() && (grown.min.array() <= b.max.array()).all()) {
      near_movers_.push_back(static_cast<std::uint32_t>(i));
    }
  }
  near_region_ = region;
}

void SceneAtTime::regroup() {
  find_near_movers();
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
  if (boxes_.empty()) return false;
  if (near_region_.contains(a) && near_region_.contains(b)) {
    for (std::uint32_t i : near_movers_) {
      if (segment_hits_box(a, b, boxes_[i])) return true;
    }
    return false;
  }
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

std::uint32_t SceneAtTime::static_blocked(const Eigen::Vector3d& a,
                                          std::span<const Eigen::Vector3d> ends) const {
  if (world_) {
    std::uint32_t hidden = 0;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      if (!world_line_of_sight(a, ends[i])) hidden |= 1u << i;
    }
    return hidden;
  }
  std::uint32_t blocked = scene_->triangle_index().segments_blocked(a, ends);
  if (scene_->solids().empty()) return blocked;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (!(blocked & (1u << i)) && boxes_block(a, ends[i])) blocked |= 1u << i;
  }
  return blocked;
}

std::uint32_t SceneAtTime::lines_of_sight(const Eigen::Vector3d& a,
                                          std::span<const Eigen::Vector3d> ends) const {
  std::uint32_t blocked = static_blocked(a, ends);
  for (std::size_t i = 0; i < ends.size() && !boxes_.empty(); ++i) {
    if (!(blocked & (1u << i)) && mover_blocks(a, ends[i])) blocked |= 1u << i;
  }
  const std::uint32_t all = ends.size() >= 32 ? ~0u : (1u << ends.size()) - 1;
  return ~blocked & all;
}

std::optional<SurfaceHit> SceneAtTime::first_hit(const Eigen::Vector3d& a,
                                                 const Eigen::Vector3d& b) const {
  std::optional<SurfaceHit> best = scene_->surface_hit(a, b, time_);
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
  // A ball inside the nearby region meets only the listed boxes (a box scene: the level's
  // triangles have their own index) and the listed movers.
  if (nearby_ && std::isfinite(limit) && limit >= 0 && scene_->triangle_index().empty() &&
      nearby_->covers_ball(p, limit)) {
    double d = nearby_->clearance(p, limit);
    const Eigen::Vector3d r(limit, limit, limit);
    if (near_region_.contains(p - r) && near_region_.contains(p + r)) {
      for (std::uint32_t i : near_movers_) d = std::min(d, boxes_[i].signed_distance(p));
      return std::min(d, limit);
    }
    return grouped_mover_clearance(p, d, limit);
  }
  if (world_) return grouped_mover_clearance(p, world_->clearance(to_vec3(p), limit, time_), limit);
  return grouped_mover_clearance(p, scene_->clearance(p, limit), limit);
}

bool SceneAtTime::closer_than(const Eigen::Vector3d& p, double r, double limit) const {
  const TriangleIndex& triangles = scene_->triangle_index();
  if (triangles.empty() || !(r > 0) || !(r <= limit) || !std::isfinite(limit)) {
    return clearance(p, limit) < r;
  }
  // Scene::clearance's parts, each deciding alone: a box, a triangle or a mover closer than
  // r, or p in the level's solid matter (whose clearance is negative).
  if (const auto box = scene_->solid_tree().nearest(p, limit); box && box->signed_distance < r) {
    return true;
  }
  if (triangles.nearest(p, r)) return true;
  const Level* level = scene_->level();
  if (level != nullptr && level->solid && level->solid->solid_at(p)) return true;
  return grouped_mover_clearance(p, limit, limit) < r;
}

double SceneAtTime::grouped_mover_clearance(const Eigen::Vector3d& p, double d,
                                            double limit) const {
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
  std::optional<NearestSurface> best =
      world_ ? world_nearest_surface(p, limit) : scene_->nearest_surface(p, limit);
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
  if (world_ ? !world_->open_at(to_vec3(p), time_) : !scene_->open_at(p)) return false;
  // As Scene::open_at: strictly inside a box is closed, its faces are open.
  for (const Aabb& box : boxes_) {
    if (box.signed_distance(p) < 0) return false;
  }
  return true;
}

}  // namespace sightline::camera
