// Brute force for the TriangleIndex tests: every triangle, one after another, in double,
// written independently of triangle_index.cc (different methods, no shared code):
//  - segment against triangle: Moller-Trumbore (the crossing parameter and barycentrics);
//  - point to triangle: projection onto the plane, inside test by edge cross products, else
//    the nearest of the three edges (triangle_index.cc uses Voronoi regions instead);
//  - segment to triangle distance: 0 when they cross, else the smallest of the endpoints'
//    distances to the triangle and the segment's distances to the three edges.
// Embree works in float, so its answers are compared with a tolerance band: a segment
// "must" be blocked when it crosses a triangle farther than `tol` from its three edges
// (measured in 3D, so grazing angles widen the band as they should), and "may" be blocked
// when it comes within `tol` of one. In between is the ambiguous band: either answer is
// right, and the tests count these cases.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "sightline/domains/camera/geometry/triangle_mesh.h"

namespace sightline::camera::brute {

struct Triangle {
  Eigen::Vector3d v[3];
  Eigen::Vector3d centre;  // of the bounding sphere (the centroid)
  double radius = 0;       // bounding sphere radius around `centre`
};

inline std::vector<Triangle> triangles_of(const TriangleMesh& mesh) {
  std::vector<Triangle> out(mesh.size());
  for (std::uint32_t i = 0; i < mesh.size(); ++i) {
    Triangle& t = out[i];
    for (int k = 0; k < 3; ++k) t.v[k] = mesh.vertex(i, k);
    t.centre = (t.v[0] + t.v[1] + t.v[2]) / 3;
    for (int k = 0; k < 3; ++k) t.radius = std::max(t.radius, (t.v[k] - t.centre).norm());
  }
  return out;
}

inline double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double dd = d.squaredNorm();
  double s = dd > 0 ? (p - a).dot(d) / dd : 0;
  s = std::min(1.0, std::max(0.0, s));
  return (a + s * d - p).norm();
}

// The minimum over two segments is reached either with one of them at an endpoint (a
// point-segment distance) or at an interior critical point of both (the two lines' common
// perpendicular, when its feet lie inside both segments).
inline double segment_segment_distance(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                                       const Eigen::Vector3d& p2, const Eigen::Vector3d& q2) {
  double best = std::min({point_segment_distance(p1, p2, q2), point_segment_distance(q1, p2, q2),
                          point_segment_distance(p2, p1, q1), point_segment_distance(q2, p1, q1)});
  const Eigen::Vector3d d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.dot(d1), b = d1.dot(d2), c = d2.dot(d2), d = d1.dot(r), e = d2.dot(r);
  const double denominator = a * c - b * b;
  if (denominator > 1e-14 * a * c) {  // not parallel
    const double s = (b * e - c * d) / denominator;
    const double t = (a * e - b * d) / denominator;
    if (s > 0 && s < 1 && t > 0 && t < 1) best = std::min(best, (p1 + s * d1 - p2 - t * d2).norm());
  }
  return best;
}

// Distance from p to the triangle: the foot of p on the plane when it is inside (all three
// edge cross products point along the normal), else the nearest edge. A degenerate triangle
// (no normal) is its edges.
inline double point_triangle_distance(const Eigen::Vector3d& p, const Triangle& t) {
  const Eigen::Vector3d n = (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]);
  const double n2 = n.squaredNorm();
  if (n2 > 0) {
    const Eigen::Vector3d foot = p - n * ((p - t.v[0]).dot(n) / n2);
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& from = t.v[k];
      const Eigen::Vector3d& to = t.v[(k + 1) % 3];
      if ((to - from).cross(foot - from).dot(n) < 0) inside = false;
    }
    if (inside) return (p - foot).norm();
  }
  return std::min({point_segment_distance(p, t.v[0], t.v[1]),
                   point_segment_distance(p, t.v[1], t.v[2]),
                   point_segment_distance(p, t.v[2], t.v[0])});
}

// Moller-Trumbore on the line a + t (b - a): the crossing parameter t and barycentrics
// (u, v) of the crossing point (v0 + u (v1 - v0) + v (v2 - v0)); nullopt when the line is
// parallel to the plane (determinant exactly 0). t and (u, v) are not range-checked.
struct Crossing {
  double t, u, v;
};
inline std::optional<Crossing> moller_trumbore(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                               const Triangle& tri) {
  const Eigen::Vector3d d = b - a;
  const Eigen::Vector3d e1 = tri.v[1] - tri.v[0];
  const Eigen::Vector3d e2 = tri.v[2] - tri.v[0];
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0) return std::nullopt;
  const double inv = 1 / det;
  const Eigen::Vector3d s = a - tri.v[0];
  const double u = s.dot(p) * inv;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) * inv;
  const double t = e2.dot(q) * inv;
  return Crossing{t, u, v};
}

// See contact(): a segment ending on a surface must meet it at more than asin(0.05) = 2.9
// degrees from grazing for the contact to be definite.
constexpr double kMinEndCosine = 0.05;

inline bool crosses(const Crossing& c, double slack_t) {
  return c.u >= 0 && c.v >= 0 && c.u + c.v <= 1 && c.t >= -slack_t && c.t <= 1 + slack_t;
}

// How a segment relates to one triangle.
struct Contact {
  bool must = false;  // crosses it, farther than tol from its edges
  bool may = false;   // comes within tol of it
  double t = 0;       // the crossing parameter when `must`
};

inline Contact contact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Triangle& tri,
                       double tol) {
  Contact c;
  // Cheap rejection: the segment stays farther than tol from the bounding sphere.
  if (point_segment_distance(tri.centre, a, b) > tri.radius + tol) return c;
  // t slack: rounding of the brute force itself, for segments built to end on a face.
  const std::optional<Crossing> x = moller_trumbore(a, b, tri);
  const bool crossing = x && crosses(*x, 1e-12);
  double edge_distance = INFINITY;
  for (int k = 0; k < 3; ++k) {
    edge_distance =
        std::min(edge_distance, segment_segment_distance(a, b, tri.v[k], tri.v[(k + 1) % 3]));
  }
  if (crossing) {
    c.may = true;
    c.must = edge_distance >= tol;
    // A contact at an end of the segment (a segment ending on the surface) is definite only
    // when the segment meets the surface steeply enough: Embree's float rounding moves the
    // ray's crossing by a few ulps across the plane, which is ulps / cos(angle to the
    // normal) along the segment, beyond any fixed extension at grazing angles.
    const double length = (b - a).norm();
    const bool at_end = std::min(x->t, 1 - x->t) * length <= tol;
    if (at_end) {
      const Eigen::Vector3d n = (tri.v[1] - tri.v[0]).cross(tri.v[2] - tri.v[0]).normalized();
      if (std::abs(n.dot(b - a)) < kMinEndCosine * length) c.must = false;
    }
    c.t = std::min(1.0, std::max(0.0, x->t));
    return c;
  }
  c.may = edge_distance <= tol || point_triangle_distance(a, tri) <= tol ||
          point_triangle_distance(b, tri) <= tol;
  return c;
}

// The whole mesh against one segment.
struct SegmentVerdict {
  bool must = false;
  bool may = false;
  double first_must_t = INFINITY;       // the smallest t of a `must` contact
  std::uint32_t first_must_triangle = 0;
};

inline SegmentVerdict judge_segment(const std::vector<Triangle>& tris, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, double tol) {
  SegmentVerdict v;
  for (std::uint32_t i = 0; i < tris.size(); ++i) {
    const Contact c = contact(a, b, tris[i], tol);
    v.may = v.may || c.may;
    if (c.must) {
      v.must = true;
      if (c.t < v.first_must_t) {
        v.first_must_t = c.t;
        v.first_must_triangle = i;
      }
    }
  }
  return v;
}

struct NearestVerdict {
  double distance = INFINITY;
  std::uint32_t triangle = 0;
};

inline NearestVerdict nearest_triangle(const std::vector<Triangle>& tris,
                                       const Eigen::Vector3d& p) {
  NearestVerdict best;
  for (std::uint32_t i = 0; i < tris.size(); ++i) {
    if ((p - tris[i].centre).norm() - tris[i].radius >= best.distance) continue;
    const double d = point_triangle_distance(p, tris[i]);
    if (d < best.distance) best = {d, i};
  }
  return best;
}

}  // namespace sightline::camera::brute
