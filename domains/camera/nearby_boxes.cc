#include "sightline/domains/camera/nearby_boxes.h"

#include <algorithm>
#include <cmath>

#include "sightline/domains/camera/geometry/segment_box.h"

namespace sightline::camera {

namespace {

Aabb grown(const Aabb& box, double by) {
  const Eigen::Vector3d d(by, by, by);
  return {box.min - d, box.max + d};
}

}  // namespace

NearbyBoxes::NearbyBoxes(const Scene& scene) : scene_(&scene) { boxes_.reserve(kCapacity); }

void NearbyBoxes::cover(const Aabb& needed) {
  if (region_.contains(needed.min) && region_.contains(needed.max)) return;
  for (double margin : {kMargin, 0.0}) {
    if (gather(grown(needed, margin))) return;
  }
  boxes_.clear();
  region_ = Aabb::empty();
}

bool NearbyBoxes::gather(const Aabb& region) {
  boxes_.clear();
  bool fits = true;
  // Boxes touching the region grown by 1 mm: a box that close to a covered segment but
  // outside the region is kept too, so the exact test's rounding cannot matter.
  scene_->solid_tree().for_each_touching(grown(region, 1e-3), [&](BoxTree::BoxIndex i) {
    if (boxes_.size() == kCapacity) {
      fits = false;
      return;
    }
    const Aabb& box = scene_->solid_tree().box(i);
    Entry e{box, box};
    for (int k = 0; k < 3; ++k) {
      e.padded.min[k] -= kPad * (1 + std::abs(box.min[k]));
      e.padded.max[k] += kPad * (1 + std::abs(box.max[k]));
    }
    boxes_.push_back(e);
  });
  region_ = fits ? region : Aabb::empty();
  return fits;
}

bool NearbyBoxes::list_blocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  const Eigen::Vector3d lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  const Eigen::Vector3d delta = b - a;
  SegmentClip clip;
  for (const Entry& e : boxes_) {
    if (e.padded.min.x() > hi.x() || e.padded.max.x() < lo.x() || e.padded.min.y() > hi.y() ||
        e.padded.max.y() < lo.y() || e.padded.min.z() > hi.z() || e.padded.max.z() < lo.z()) {
      continue;
    }
    if (clip_segment_to_box(a, delta, e.box, 1.0, clip)) return true;
  }
  return false;
}

double NearbyBoxes::clearance(const Eigen::Vector3d& p, double limit) const {
  double d = limit;
  for (const Entry& e : boxes_) {
    // A box farther than `limit` along one axis from its padded bounds is farther than limit
    // (by at least the padding, far beyond rounding): it cannot lower d.
    if (e.padded.min.x() - p.x() >= limit || p.x() - e.padded.max.x() >= limit ||
        e.padded.min.y() - p.y() >= limit || p.y() - e.padded.max.y() >= limit ||
        e.padded.min.z() - p.z() >= limit || p.z() - e.padded.max.z() >= limit) {
      continue;
    }
    d = std::min(d, e.box.signed_distance(p));
  }
  return d;
}

}  // namespace sightline::camera
