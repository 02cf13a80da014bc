// TriangleIndex: the geometric questions a chase camera asks, on a level's triangles,
// answered by Embree 3 (Intel's ray-tracing kernels, Debian's libembree-dev).
//
//  - segment_blocked(a, b): does the closed segment a-b meet any triangle (occlusion: one
//    rtcOccluded1 with tnear 0, tfar 1 on the unnormalised direction b - a);
//  - first_hit(a, b): the first triangle along it, with its unit normal (rtcIntersect1);
//  - nearest(p, limit): the distance to the nearest point of any triangle, when below
//    `limit` (clearance; rtcPointQuery with an exact point-triangle distance callback).
// Triangles are two-sided and have no inside. The scene is built once, with the robust
// flag (watertight edges: a segment through a shared edge meets one of its triangles) and
// high build quality; every query is thread-safe and allocates nothing. Embree's types
// stay in the .cc: this header is all the rest of the project sees.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>

#include "domains/camera/geometry/triangle_mesh.h"

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
  // Embree reports an error (with its message).
  explicit TriangleIndex(const TriangleMesh& mesh);
  ~TriangleIndex();
  TriangleIndex(TriangleIndex&&) noexcept;
  TriangleIndex& operator=(TriangleIndex&&) noexcept;

  bool empty() const { return triangle_count_ == 0; }
  std::size_t triangle_count() const { return triangle_count_; }
  const Aabb& bounds() const { return bounds_; }

  bool segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  std::optional<Hit> first_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  std::optional<Nearest> nearest(const Eigen::Vector3d& p,
                                 double limit = std::numeric_limits<double>::infinity()) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::size_t triangle_count_ = 0;
  Aabb bounds_ = Aabb::empty();
};

}  // namespace sightline::camera
