// IndependentTriangles: the independent check of visibility and clearance against a level's
// triangles, for run metrics and tests (independent_check.h does the same for boxes).
//
// Deliberately shares no code with the camera domain's fast path (Embree, TriangleIndex):
// triangles are copied into doubles, bucketed in a plain uniform grid of this file's own,
// and every candidate triangle is tested with Moller-Trumbore (segments) or the distance to
// its plane and its three edges (points), so a bug in the controller's queries cannot hide
// itself. The grid only skips triangles whose cells a query cannot reach; it never decides
// a hit. Closed semantics, as the camera's: a segment that touches a triangle (edges and
// end points included, to 1e-9 relative) is blocked.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "sightline/domains/camera/geometry/triangle_mesh.h"

namespace sightline::experiments {

class IndependentTriangles {
 public:
  explicit IndependentTriangles(const camera::TriangleMesh& mesh);

  std::size_t size() const { return triangles_.size(); }
  // True when the closed segment a-b meets any triangle.
  bool segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // Distance from p to the nearest triangle, or `limit` when none is nearer.
  double distance(const Eigen::Vector3d& p, double limit) const;

 private:
  struct Triangle {
    Eigen::Vector3d a, b, c;
  };
  // Calls visit(triangle index) for every triangle bucketed in a cell that overlaps the box
  // [lo, hi] (a triangle may be visited more than once); stops when visit returns true.
  template <class Visit>
  bool visit_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Visit&& visit) const;
  std::array<long, 3> cell_of(const Eigen::Vector3d& p) const;

  std::vector<Triangle> triangles_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double cell_ = 1;
  std::array<long, 3> cells_{0, 0, 0};
  std::vector<std::uint32_t> first_;  // per cell, into items_ (size cells + 1)
  std::vector<std::uint32_t> items_;
};

// The closed segment a-b meets triangle (p, q, r): Moller-Trumbore with inclusive bounds.
bool segment_meets_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                            const Eigen::Vector3d& r);
// Euclidean distance from x to the triangle (p, q, r): to its plane when x projects inside
// it, else to the nearest of its three edges.
double point_triangle_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& p,
                               const Eigen::Vector3d& q, const Eigen::Vector3d& r);

}  // namespace sightline::experiments
