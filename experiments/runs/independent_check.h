// Independent checks of what a camera run shows: is the look-at point visible, how much of
// the character's body is, is the camera clear of geometry.
//
// These deliberately share no code with the camera domain (no BVH, no slab test from
// domains/camera): every box is tested, with a separate clipping routine, so a bug in the
// controller's fast queries cannot hide itself. Tests and suite metrics both judge runs with
// these functions, never with the controller's own visibility flag.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sightline::experiments {

struct SolidBox {
  Eigen::Vector3d min, max;
};

// A mover (FORMATS.md `movers:`) as the independent checks see it: its size and keyframes
// copied as plain numbers and interpolated here, not by the camera domain's Mover, so a bug
// in how the camera places movers cannot hide itself from the metrics.
struct MovingBox {
  Eigen::Vector3d size{1, 1, 1};           // extents; the origin is the centre of the base
  std::vector<double> times;               // strictly increasing, at least one
  std::vector<Eigen::Vector3d> positions;  // the base centre at each time
};
// The box a mover fills at time t: its base centre moves linearly between keyframes and
// stays at the first (last) keyframe before (after) them; it spans position - [sx/2, 0, sz/2]
// to position + [sx/2, sy, sz/2].
SolidBox moving_box_at(const MovingBox& mover, double t);
// The boxes of all movers at time t, into `out` (cleared first).
void moving_boxes_at(const std::vector<MovingBox>& movers, double t, std::vector<SolidBox>& out);

// True when the closed segment a-b meets any box (closed boxes: touching a face counts).
// Liang-Barsky clipping of the segment against each box in turn.
bool segment_blocked(const std::vector<SolidBox>& boxes, const Eigen::Vector3d& a,
                     const Eigen::Vector3d& b);
// Euclidean distance from p to the nearest box (0 when inside one); +inf without boxes.
double distance_to_geometry(const std::vector<SolidBox>& boxes, const Eigen::Vector3d& p);
// Fraction (0..1) of `samples` body points visible from `eye`: points on a regular grid
// over the character's box (feet at `feet`, extents `size`), slightly inset so the body's
// own surface never blocks itself. The character is not a solid box here.
double visible_body_fraction(const std::vector<SolidBox>& boxes, const Eigen::Vector3d& eye,
                             const Eigen::Vector3d& feet, const Eigen::Vector3d& size);
// The 45 body points visible_body_fraction tests.
std::vector<Eigen::Vector3d> body_check_points(const Eigen::Vector3d& feet,
                                               const Eigen::Vector3d& size);

}  // namespace sightline::experiments
