// Mover: a solid axis-aligned box that moves on its own keyframes (a passer-by, a sliding
// door, a bus), as FORMATS.md's `movers:` block defines it.
//
// It keeps its size and orientation; its origin is the centre of its base, so at time t it
// spans position(t) - [sx/2, 0, sz/2] to position(t) + [sx/2, sy, sz/2]. Between keyframes the
// position is interpolated linearly; before the first and after the last keyframe the mover
// stays where they put it. Movers block sight and the camera like boxes, at each frame's
// time (SceneAtTime places them); they are never checked against the character.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/geometry/aabb.h"

namespace sightline::camera {

struct MoverKeyframe {
  double t = 0;                                        // seconds
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of the base, metres
};

class Mover {
 public:
  // Requires a size > 0 on every axis, at least one keyframe, finite values and strictly
  // increasing times (std::invalid_argument otherwise: the scene reader reports bad input
  // with its location before building one).
  Mover(std::string name, Eigen::Vector3d size, std::vector<MoverKeyframe> path,
        csp::SourceLocation where = {});

  const std::string& name() const { return name_; }  // may be empty
  const Eigen::Vector3d& size() const { return size_; }
  const std::vector<MoverKeyframe>& path() const { return path_; }
  const csp::SourceLocation& where() const { return where_; }

  // Base centre at time t. O(log keyframes), no allocation.
  Eigen::Vector3d position_at(double t) const;
  // Same, starting the keyframe search at *segment and leaving there the segment of t: O(1)
  // for times that advance frame by frame.
  Eigen::Vector3d position_at(double t, std::size_t* segment) const;
  // The solid box at time t.
  Aabb box_at(double t) const { return Aabb::around_feet(position_at(t), size_); }
  // Velocity at time t (m/s): that of the segment holding t, zero outside the path.
  Eigen::Vector3d velocity_at(double t) const;
  // Replaces the path by a constant-velocity forecast: at `position` at time t and until
  // then, moving with `velocity` for kForecastSeconds after it, then still. Allocates nothing
  // when the path already holds two keyframes. Requires finite values.
  static constexpr double kForecastSeconds = 10.0;
  void place(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double t);
  // Every box the mover occupies between the first and the last keyframe (the union of its
  // boxes along the path).
  Aabb swept_box() const;

 private:
  std::string name_;
  Eigen::Vector3d size_;
  std::vector<MoverKeyframe> path_;
  csp::SourceLocation where_;
};

}  // namespace sightline::camera
