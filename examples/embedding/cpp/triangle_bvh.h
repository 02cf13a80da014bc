// triangle_bvh.h: the example's own spatial index over a level's triangles, standing in for a
// game's physics engine.
//
// sightline can index triangles itself (sightline::make_geometry_world), but a game already
// has a physics world and should let the camera ask it instead. This bounding-volume
// hierarchy plays that part: it answers the questions a sightline::World answers (the first
// hit on a segment, any hit on a segment, the distance to the nearest surface).
//
// The tree is built once (triangle_bvh_build.cc: binned surface-area heuristic over the
// triangles' bounding boxes); the queries (triangle_bvh_query.cc) are const, allocation-free
// and safe to run from several threads at once. Triangles are two-sided and have no inside,
// so distances are never negative. Needle and point triangles are left out: they block no
// sight line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "vector3.h"

namespace example {

class TriangleBvh {
 public:
  // Nodes deeper than this become leaves, so a query's fixed stack of kMaxDepth + 1 entries
  // never overflows.
  static constexpr int kMaxDepth = 63;

  struct Hit {
    double fraction = 0;  // in [0, 1]: the hit is at a + fraction (b - a)
    V3 normal;            // unit, facing a
  };

  // `vertices`: 3 doubles per vertex; `indices`: 3 per triangle, into the vertices. Finite
  // coordinates and indices within the vertices, as sl_level_triangles gives them.
  TriangleBvh(std::span<const double> vertices, std::span<const std::uint32_t> indices);

  // The nearest triangle on the segment a -> b, if any.
  std::optional<Hit> first_hit(const V3& a, const V3& b) const;
  // True when no triangle touches the segment a -> b (stops at the first one found).
  bool line_of_sight(const V3& a, const V3& b) const;
  // min(distance from p to the nearest triangle, limit); limit may be infinite.
  double clearance(const V3& p, double limit) const;

  std::size_t node_count() const { return nodes_.size(); }
  std::size_t triangle_count() const { return triangles_.size(); }  // the level's, less needles

 private:
  struct Node {
    V3 lo, hi;                // bounding box of everything below
    std::uint32_t first = 0;  // leaf: first triangle in triangles_; inner: the second child
    std::uint32_t count = 0;  // leaf: number of triangles (> 0); inner: 0 (first child: next)
  };
  struct Triangle {
    V3 a, b, c;
  };
  struct Item;  // a triangle while building

  std::uint32_t build_node(std::span<Item> items, int depth);
  static std::size_t split(std::span<Item> items);
  // The triangle nearest along a -> b (or, with any, the first found; null for none) and
  // where: at a + s (b - a).
  struct Traced {
    const Triangle* triangle = nullptr;
    double s = 1;
  };
  Traced trace(const V3& a, const V3& b, bool any) const;

  std::vector<Node> nodes_;
  std::vector<Triangle> triangles_;  // in leaf order
};

}  // namespace example
