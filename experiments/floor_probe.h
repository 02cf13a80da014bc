// FloorProbe: what a person's body meets on a level's triangles. The walk generator
// (level_walk.h) asks it where the floor is under a point of the navigation mesh (Recast's
// floors are voxel approximations, a few centimetres to a stair's height off), whether a
// person standing there has headroom, and whether the lines their knees and chest sweep
// between two keyframes pass clear of every surface.
//
// Geometry: a coarse grid over x and z of the triangles' footprints, each query testing the
// triangles of the cells its segment passes over (the segments are short: a keyframe's leg,
// a ray of a couple of metres). Triangles are two-sided.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "domains/camera/geometry/triangle_mesh.h"

namespace sightline::experiments {

class FloorProbe {
 public:
  // Heights above the feet the legs are checked at: knees, waist, chest, head.
  static constexpr double kBodyHeights[] = {0.5, 1.0, 1.3, 1.7};

  // Keeps a reference to `mesh` (metres, y up): it must outlive the probe.
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
  // Parameter in [0, 1] where segment a + t (b - a) meets triangle `i`, if it does.
  std::optional<double> hit(std::uint32_t i, const Eigen::Vector3d& a,
                            const Eigen::Vector3d& d) const;
  template <class Visit>
  void for_cells(double x0, double z0, double x1, double z1, Visit&& visit) const;

  const camera::TriangleMesh& mesh_;
  double person_height_;
  double cell_ = 2.0;  // metres
  double min_x_ = 0, min_z_ = 0;
  int nx_ = 0, nz_ = 0;
  std::vector<std::uint32_t> start_;      // per cell, into triangles_ (CSR)
  std::vector<std::uint32_t> triangles_;
};

}  // namespace sightline::experiments
