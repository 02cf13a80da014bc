// FloorProbe: what a person's body meets on a level's triangles. The walk generator
// (level_walk.h) asks it where the floor is under a point of the navigation mesh (Recast's
// floors are voxel approximations, a few centimetres to a stair's height off), whether a
// person standing there has headroom, and whether the lines their knees and chest sweep
// between two keyframes pass clear of every surface.
//
// The geometry is camera::TriangleIndex (Embree): triangles are two-sided, queries are
// thread-safe.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

#include "sightline/domains/camera/geometry/triangle_index.h"
#include "sightline/domains/camera/geometry/triangle_mesh.h"

namespace sightline::experiments {

class FloorProbe {
 public:
  // Heights above the feet the legs are checked at: knees, waist, chest, head.
  static constexpr double kBodyHeights[] = {0.5, 1.0, 1.3, 1.7};

  // Indexes a copy of `mesh` (metres, y up).
  FloorProbe(const camera::TriangleMesh& mesh, double person_height);

  // The height of the first surface met going straight down at (x, z) from `top` to
  // `bottom`, if any.
  std::optional<double> floor_below(double x, double z, double top, double bottom) const;
  // Nothing between just above the feet and the person's height above them.
  bool has_headroom(const Eigen::Vector3d& feet) const;
  // The lines from a to b at every height of kBodyHeights meet no surface.
  bool body_clear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // The closed segment a-b meets a triangle.
  bool segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

 private:
  camera::TriangleIndex index_;
  double person_height_;
};

}  // namespace sightline::experiments
