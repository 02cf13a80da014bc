// TriangleIndex: the geometric questions a chase camera asks, on a level's triangles,
// answered by Embree 3 (Intel's ray-tracing kernels, Debian's libembree-dev).
//
//  - segment_blocked(a, b): does the closed segment a-b meet any triangle (occlusion: one
//    rtcOccluded1 along the unnormalised direction b - a); segments_blocked(a, ends) asks
//    it for several segments from one point at once, as ray packets;
//  - first_hit(a, b): the first triangle along it, with its unit normal (rtcIntersect1);
//  - nearest(p, limit): the distance to the nearest point of any triangle, when below
//    `limit` (clearance; rtcPointQuery with an exact point-triangle distance callback).
// Triangles are two-sided and have no inside. The scene is built once, with the robust
// flag (watertight edges: a segment through a shared edge meets one of its triangles) and
// high build quality; every query is thread-safe and allocates nothing. Embree's types
// stay in the .cc: this header is all the rest of the project sees.
//
// Precision. Embree works in float, so contacts are decided within a tolerance
// tol = 2^-19 (1.9e-6) x the largest coordinate involved (of the mesh or the query; at
// least 1 m): 1.9e-5 m in a 10 m room, 1.9e-4 m at 100 m.
//  - The segment is traced extended by tol at both ends, so a segment that ends (or starts)
//    exactly on a surface touches it; it may also report a triangle up to tol beyond an end.
//    At very grazing angles (below about 3 degrees to the surface) an end contact may still
//    be missed: Embree's float rounding across the plane is then longer than tol along the
//    segment.
//  - A segment that passes within about tol of a triangle's edge may go either way, except
//    that the robust flag makes closed meshes watertight: a segment entering a closed mesh
//    through an edge or a vertex is always blocked.
//  - A segment lying exactly in a triangle's plane does not meet that triangle (Embree's
//    test divides by a determinant that is then 0); in a closed mesh it still meets the
//    triangles around, where it leaves the face.
//  - A segment shorter than tol is a point: blocked when the point lies within tol of a
//    triangle (first_hit then reports t = 0 and the nearest triangle).
//  - nearest() is exact (double) whatever the scale: Embree only prunes, with its float
//    sphere widened by tol.
// Queries with a non-finite point meet nothing (false / nullopt).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>

#include "sightline/domains/camera/geometry/triangle_mesh.h"

namespace sightline::camera {

class TriangleIndex {
 public:
  struct Hit {
    double t = 0;                 // segment parameter of the hit, in [0, 1]
    std::uint32_t triangle = 0;   // index into the mesh's triangles
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, (v1 - v0) x (v2 - v0)
  };
  struct Nearest {
    double distance = 0;          // metres, >= 0
    std::uint32_t triangle = 0;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  // the nearest point on that triangle
  };

  TriangleIndex();  // empty: nothing is ever hit
  // Copies the mesh into Embree's buffers and builds the BVH. Throws std::runtime_error when
  // Embree reports an error (with its message), std::invalid_argument when a triangle names
  // a vertex the mesh does not have or a vertex is not finite.
  explicit TriangleIndex(const TriangleMesh& mesh);
  ~TriangleIndex();
  TriangleIndex(TriangleIndex&&) noexcept;
  TriangleIndex& operator=(TriangleIndex&&) noexcept;

  bool empty() const { return triangle_count_ == 0; }
  std::size_t triangle_count() const { return triangle_count_; }
  const Aabb& bounds() const { return bounds_; }

  // True when the closed segment from `a` to `b` touches a triangle (see Precision).
  bool segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // Segments from one point `a` to each of `ends` (at most kMaxFan): bit i of the result is
  // set when the segment a-ends[i] is blocked, as segment_blocked(a, ends[i]) answers. Traced
  // as Embree ray packets of up to 8 (rtcOccluded8): a candidate camera's sight lines to the
  // character's body, or to its predicted look-at points, all leave one point toward one
  // region a few metres away, so they share most of the tree's nodes, which a packet visits
  // once for all its rays.
  static constexpr std::size_t kMaxFan = 32;
  std::uint32_t segments_blocked(const Eigen::Vector3d& a,
                                 std::span<const Eigen::Vector3d> ends) const;
  // The first triangle the segment from `a` to `b` meets; t is clamped into [0, 1] (a
  // contact within tol before `a` is reported at t = 0).
  std::optional<Hit> first_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // The nearest triangle to `p` among those strictly closer than `limit` (nullopt when none
  // is). A finite limit prunes most of the tree: clearance queries only care whether
  // something is within the camera's radius.
  std::optional<Nearest> nearest(const Eigen::Vector3d& p,
                                 double limit = std::numeric_limits<double>::infinity()) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::size_t triangle_count_ = 0;
  Aabb bounds_ = Aabb::empty();
};

}  // namespace sightline::camera
