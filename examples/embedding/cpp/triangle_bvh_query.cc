// triangle_bvh_query.cc: the example index's queries: first hit and line of sight on a
// segment, and the distance to the nearest triangle (see triangle_bvh.h for what and why).
//
// Each walks the tree with a fixed stack (no allocation), nearer child first, and skips every
// node that cannot beat the best answer found so far: a segment clipped at the nearest hit,
// a distance capped at the nearest triangle yet.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "triangle_bvh.h"

namespace example {
namespace {

constexpr double kEdgeTolerance = 1e-9;  // barycentric slack: a ray along a shared edge hits

// A walk holds at most one entry per level below the root, plus one. Entries are popped field
// by field: copied whole, the node index is loaded together with its padding, which the CPU
// cannot forward from the narrower store that pushed it; that stall made the walks about
// twice as slow.
struct StackEntry {
  std::uint32_t node;
  double key;  // the segment parameter where it enters the node, or its squared distance
};
using Stack = std::array<StackEntry, TriangleBvh::kMaxDepth + 1>;

// Where the segment a + s d, s in [0, s_max], enters the box [lo, hi], or -1 when it misses.
// A 0 * inf (a on a slab face, d parallel to it) is NaN and leaves that slab unbounded.
double segment_enters(const V3& lo, const V3& hi, const V3& a, const V3& inv, double s_max) {
  double s0 = 0, s1 = s_max;
  const auto clip = [&](double lo_k, double hi_k, double a_k, double inv_k) {
    double near = (lo_k - a_k) * inv_k, far = (hi_k - a_k) * inv_k;
    if (near > far) std::swap(near, far);
    if (near > s0) s0 = near;
    if (far < s1) s1 = far;
  };
  clip(lo.x, hi.x, a.x, inv.x);
  clip(lo.y, hi.y, a.y, inv.y);
  clip(lo.z, hi.z, a.z, inv.z);
  return s0 <= s1 ? s0 : -1;
}

// Möller-Trumbore, both faces: the parameter s in [0, s_max] where a + s d meets the
// triangle (p0, p1, p2), or -1.
double segment_triangle(const V3& a, const V3& d, const V3& p0, const V3& p1, const V3& p2,
                        double s_max) {
  const V3 e1 = p1 - p0, e2 = p2 - p0, p = cross(d, e2);
  const double det = dot(e1, p);
  if (det == 0) return -1;  // parallel to the plane
  const double inv = 1 / det;
  const V3 to_a = a - p0;
  const double u = dot(to_a, p) * inv;
  if (u < -kEdgeTolerance || u > 1 + kEdgeTolerance) return -1;
  const V3 q = cross(to_a, e1);
  const double v = dot(d, q) * inv;
  if (v < -kEdgeTolerance || u + v > 1 + kEdgeTolerance) return -1;
  const double s = dot(e2, q) * inv;
  return s >= 0 && s <= s_max ? s : -1;
}

double box_distance_squared(const V3& lo, const V3& hi, const V3& p) {
  const auto gap = [](double lo_k, double hi_k, double p_k) {
    const double g = std::max({lo_k - p_k, p_k - hi_k, 0.0});
    return g * g;
  };
  return gap(lo.x, hi.x, p.x) + gap(lo.y, hi.y, p.y) + gap(lo.z, hi.z, p.z);
}

// The squared distance from p to the triangle (a, b, c): Ericson, "Real-Time Collision
// Detection", 5.1.5, finding which vertex, edge or the face is nearest from dot products.
double point_triangle_distance_squared(const V3& p, const V3& a, const V3& b, const V3& c) {
  const V3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length_squared(p - a);
  const V3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length_squared(p - b);
  const V3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length_squared(p - c);
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  double u = 0, w = 0;  // the nearest point is a + u ab + w ac
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    u = d1 / (d1 - d3);  // edge ab
  } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    w = d2 / (d2 - d6);  // edge ac
  } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    w = (d4 - d3) / ((d4 - d3) + (d5 - d6));  // edge bc
    u = 1 - w;
  } else {
    const double sum = va + vb + vc;  // the face
    u = vb / sum;
    w = vc / sum;
  }
  return length_squared(p - (a + u * ab + w * ac));
}

}  // namespace

TriangleBvh::Traced TriangleBvh::trace(const V3& a, const V3& b, bool any) const {
  if (nodes_.empty()) return {};
  double s = 1;  // the nearest hit yet, or the segment's end
  const V3 d = b - a;
  const V3 inv{1 / d.x, 1 / d.y, 1 / d.z};  // +-inf on an axis the segment is flat in
  const auto enters = [&](std::uint32_t node) {
    return segment_enters(nodes_[node].lo, nodes_[node].hi, a, inv, s);
  };
  const Triangle* hit = nullptr;
  Stack stack;
  int top = 0;
  if (const double root = enters(0); root >= 0) stack[top++] = {0, root};
  while (top > 0) {
    const std::uint32_t node = stack[--top].node;
    if (stack[top].key > s) continue;  // a nearer hit was found since it was pushed
    const Node& n = nodes_[node];
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const Triangle& tri = triangles_[i];
        const double t = segment_triangle(a, d, tri.a, tri.b, tri.c, s);
        if (t < 0) continue;
        hit = &tri;
        s = t;
        if (any) return {hit, s};
      }
      continue;
    }
    const std::uint32_t child[2] = {node + 1, n.first};
    const double enter[2] = {enters(child[0]), enters(child[1])};
    const int near = enter[1] >= 0 && (enter[0] < 0 || enter[1] < enter[0]) ? 1 : 0;
    if (enter[1 - near] >= 0) stack[top++] = {child[1 - near], enter[1 - near]};
    if (enter[near] >= 0) stack[top++] = {child[near], enter[near]};
  }
  return {hit, s};
}

std::optional<TriangleBvh::Hit> TriangleBvh::first_hit(const V3& a, const V3& b) const {
  const auto [tri, s] = trace(a, b, false);
  if (!tri) return std::nullopt;
  // The normal facing a; not zero, as needles are not indexed.
  V3 n = cross(tri->b - tri->a, tri->c - tri->a);
  if (dot(n, b - a) > 0) n = -1.0 * n;
  return Hit{s, (1 / length(n)) * n};
}

bool TriangleBvh::line_of_sight(const V3& a, const V3& b) const {
  return trace(a, b, true).triangle == nullptr;
}

double TriangleBvh::clearance(const V3& p, double limit) const {
  // Distances are >= 0, so a limit of 0 or less is the answer. An infinite limit squares to an
  // infinite best.
  if (!(limit > 0) || nodes_.empty()) return limit;
  double best2 = limit * limit;
  const auto distance2 = [&](std::uint32_t node) {
    return box_distance_squared(nodes_[node].lo, nodes_[node].hi, p);
  };
  Stack stack;
  int top = 0;
  stack[top++] = {0, distance2(0)};
  while (top > 0) {
    const std::uint32_t node = stack[--top].node;
    if (stack[top].key >= best2) continue;
    const Node& n = nodes_[node];
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const Triangle& tri = triangles_[i];
        best2 = std::min(best2, point_triangle_distance_squared(p, tri.a, tri.b, tri.c));
      }
      continue;
    }
    const std::uint32_t child[2] = {node + 1, n.first};
    const double d2[2] = {distance2(child[0]), distance2(child[1])};
    const int near = d2[1] < d2[0] ? 1 : 0;
    if (d2[1 - near] < best2) stack[top++] = {child[1 - near], d2[1 - near]};
    if (d2[near] < best2) stack[top++] = {child[near], d2[near]};
  }
  return std::min(std::sqrt(best2), limit);
}

}  // namespace example
