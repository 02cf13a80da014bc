// Aabb: a closed axis-aligned box, the only solid shape of a camera scene.
//
// Walls, pillars, roofs and the character's body are all axis-aligned boxes (as in the thesis,
// section 3.3). Boxes are closed: a point on a face is inside, and two boxes that only share a
// face touch but do not overlap. Everything here is inline because the BVH calls it in its
// inner loops.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace sightline::camera {

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();  // metres, min <= max on every axis
  Eigen::Vector3d max = Eigen::Vector3d::Zero();

  // The empty box (min = +inf, max = -inf), the identity of merge().
  static Aabb empty() {
    const double inf = INFINITY;
    return {Eigen::Vector3d::Constant(inf), Eigen::Vector3d::Constant(-inf)};
  }
  // The box of `size` (x, y, z extents) whose bottom face is centred on `feet`: how the
  // character's body is placed (its origin is the centre of its feet).
  static Aabb around_feet(const Eigen::Vector3d& feet, const Eigen::Vector3d& size) {
    const Eigen::Vector3d half(size.x() / 2, 0, size.z() / 2);
    return {feet - half, feet + half + Eigen::Vector3d(0, size.y(), 0)};
  }

  Eigen::Vector3d centre() const { return (min + max) / 2; }
  Eigen::Vector3d size() const { return max - min; }
  double volume() const { return size().prod(); }
  // Half the surface area (the SAH cost only needs proportions).
  double half_area() const {
    const Eigen::Vector3d e = size();
    return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
  }

  void merge(const Aabb& other) {
    min = min.cwiseMin(other.min);
    max = max.cwiseMax(other.max);
  }
  void merge(const Eigen::Vector3d& point) {
    min = min.cwiseMin(point);
    max = max.cwiseMax(point);
  }

  // Closed containment: the boundary counts as inside.
  bool contains(const Eigen::Vector3d& p) const {
    return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y() &&
           p.z() >= min.z() && p.z() <= max.z();
  }
  // True when the interiors intersect (a shared volume > 0); touching faces do not count, so a
  // character standing on a floor box or leaning on a wall does not overlap it.
  bool overlaps_interior(const Aabb& o) const {
    return min.x() < o.max.x() && o.min.x() < max.x() && min.y() < o.max.y() &&
           o.min.y() < max.y() && min.z() < o.max.z() && o.min.z() < max.z();
  }

  // The outward unit normal of the face nearest to `p` (for a point on the surface: the face
  // it lies on; ties go to the lower axis, min face first).
  Eigen::Vector3d nearest_face_normal(const Eigen::Vector3d& p) const {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    double best = INFINITY;
    for (int i = 0; i < 3; ++i) {
      if (std::abs(p[i] - min[i]) < best) {
        best = std::abs(p[i] - min[i]);
        n.setZero();
        n[i] = -1;
      }
      if (std::abs(p[i] - max[i]) < best) {
        best = std::abs(p[i] - max[i]);
        n.setZero();
        n[i] = 1;
      }
    }
    return n;
  }

  // Signed Euclidean distance from `p` to the box: the distance to the box when outside
  // (> 0), minus the distance to the nearest face when inside (<= 0, 0 on the boundary).
  //
  //   outside: e_i = max(min_i - p_i, 0, p_i - max_i),  d = sqrt(e_x^2 + e_y^2 + e_z^2)
  //   inside:  d = -min_i min(p_i - min_i, max_i - p_i)
  //
  // For nested boxes B inside N, signed_distance_N(p) <= signed_distance_B(p) everywhere, and
  // the inequality survives rounding because every step is monotone in the box bounds: this
  // is what lets the BVH prune a node by its bounds without ever losing the exact answer.
  double signed_distance(const Eigen::Vector3d& p) const {
    double outside = 0;
    double depth = INFINITY;
    for (int i = 0; i < 3; ++i) {
      const double below = min[i] - p[i];
      const double above = p[i] - max[i];
      const double excess = std::max({below, above, 0.0});
      outside += excess * excess;
      depth = std::min(depth, std::min(-below, -above));
    }
    if (outside > 0) return std::sqrt(outside);
    // The point is inside (or on) the box; depth >= 0 unless an excess underflowed to 0.
    return -std::max(depth, 0.0);
  }
};

}  // namespace sightline::camera
