#include "sightline/domains/camera/baselines/sphere_probe.h"

#include <algorithm>
#include <vector>

#include "sightline/domains/camera/geometry/segment_box.h"

namespace sightline::camera {

namespace {

BoxTree grow_boxes(const Scene& scene, double radius) {
  std::vector<Aabb> grown;
  grown.reserve(scene.solids().size());
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius);
  for (const SolidBox& solid : scene.solids()) grown.push_back({solid.box.min - r, solid.box.max + r});
  return BoxTree(std::move(grown));
}

}  // namespace

SphereProbe::SphereProbe(const SceneAtTime& scene, double radius)
    : scene_(&scene), radius_(radius), grown_(grow_boxes(scene.scene(), radius)) {}

std::optional<double> SphereProbe::first_contact(const Eigen::Vector3d& a,
                                                 const Eigen::Vector3d& b) const {
  const double length = (b - a).norm();
  // Touching already at the start (Unreal: a sweep that starts in penetration).
  if (scene_->clearance(a, radius_) < radius_) return 0.0;
  if (length == 0) return std::nullopt;
  // Boxes: the sweep cannot touch a box before it enters that box grown by r, so tracing
  // starts at the grown boxes' first hit (none hit: no box is touched). A level's triangles
  // have no such broad phase here, so with a level the trace starts at a.
  double t = 0;
  if (scene_->scene().triangle_index().empty()) {
    const std::optional<BoxTree::Hit> broad = grown_.first_hit(a, b);
    double first = broad ? broad->t : 2.0;
    // The movers at this time, grown by r the same way (a flat loop: they are few).
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius_);
    SegmentClip clip;
    for (const Aabb& box : scene_->mover_boxes()) {
      if (clip_segment_to_box(a, b - a, Aabb{box.min - r, box.max + r}, std::min(first, 1.0),
                              clip)) {
        first = std::min(first, clip.enter);
      }
    }
    if (first > 1) return std::nullopt;  // no grown box is met, so no rounded one either
    t = first;
  }
  // Sphere tracing: t advances by the gap (d - r) / length. The distance query is limited
  // to what could still matter (the rest of the segment plus r).
  for (int step = 0; step < kMaxTraceSteps; ++step) {
    const Eigen::Vector3d p = a + t * (b - a);
    const double limit = radius_ + (1 - t) * length + kContactTolerance;
    const double gap = scene_->clearance(p, limit) - radius_;
    if (gap <= kContactTolerance) return t;
    t += gap / length;
    if (t >= 1) return std::nullopt;
  }
  return t;  // still clear here; stopping early only pulls the camera in a little more
}

}  // namespace sightline::camera
