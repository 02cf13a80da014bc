// The segment/box intersection test (the slab method), used by every visibility query.
//
// A segment is written origin + t * delta, t in [0, t_max] (t_max = 1 reaches origin + delta).
// Following the thesis (section 3.3, after Van Verth & Bishop), each axis i clips t to the
// slab between the box's two planes:
//
//   s_i = (min_i - origin_i) / delta_i,   t_i = (max_i - origin_i) / delta_i   (swap if s_i > t_i)
//   enter = max(0, s_x, s_y, s_z),        exit = min(t_max, t_x, t_y, t_z)
//
// and the segment meets the box when enter <= exit. Choices, all deliberate:
//  - Boxes are closed and touching counts as a hit (enter == exit is a hit): a sight line
//    that grazes a wall's face or edge is blocked. For a camera this errs on the safe side.
//  - A segment parallel to an axis (delta_i == 0) never divides: it meets the slab for all t
//    when min_i <= origin_i <= max_i and for no t otherwise. So no 0 * inf = NaN can arise.
//  - A segment that starts inside (or on) the box hits it at t = 0.
//  - The planes are found by division, not by multiplying with a precomputed 1/delta_i: a
//    correctly rounded quotient makes two mathematically equal entry and exit parameters equal
//    in floating point too, so a segment exactly grazing an edge is reported consistently.
//    Division is also monotone in the numerator, so a box nested in another (a BVH node) is
//    never missed where the inner box is hit.
#pragma once

#include <Eigen/Core>
#include <utility>

#include "sightline/domains/camera/geometry/aabb.h"

namespace sightline::camera {

// The part [enter, exit] of the segment inside the closed box, if any.
struct SegmentClip {
  double enter = 0;
  double exit = 0;
};

// Clips the segment origin + t * delta, t in [0, t_max], to `box`. Returns false when they do
// not meet (then `clip` is unspecified).
inline bool clip_segment_to_box(const Eigen::Vector3d& origin, const Eigen::Vector3d& delta,
                                const Aabb& box, double t_max, SegmentClip& clip) {
  double enter = 0;
  double exit = t_max;
  for (int i = 0; i < 3; ++i) {
    if (delta[i] == 0) {
      // Parallel to the slab's planes: inside the slab for every t, or for none.
      if (origin[i] < box.min[i] || origin[i] > box.max[i]) return false;
      continue;
    }
    double near = (box.min[i] - origin[i]) / delta[i];
    double far = (box.max[i] - origin[i]) / delta[i];
    if (near > far) std::swap(near, far);
    if (near > enter) enter = near;
    if (far < exit) exit = far;
    if (enter > exit) return false;
  }
  clip.enter = enter;
  clip.exit = exit;
  return true;
}

// True when the segment from `a` to `b` (both ends included) touches the closed box.
inline bool segment_hits_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Aabb& box) {
  SegmentClip clip;
  return clip_segment_to_box(a, b - a, box, 1.0, clip);
}

}  // namespace sightline::camera
