// BoxTree: a bounding volume hierarchy over axis-aligned boxes, so that the questions a chase
// camera asks every frame (is this sight line clear? what does it hit first? how far is the
// nearest wall? which areas contain this point?) cost O(log n) in the number of boxes, not
// O(n) as the thesis' one-box-after-another test does.
//
// Built once per scene with the surface area heuristic over 16 bins of box centres (median
// split when the heuristic finds nothing better or the tree gets deep). Nodes are 32 bytes
// (float bounds, padded outward) and flattened in depth-first order into one vector: a node's
// left child is the next node, its right child is stored. Queries walk the tree with a fixed-size stack on the call stack: they never
// allocate, so they are safe on the per-frame path.
//
// Every query returns exactly what a brute-force loop over all boxes would return (the tests
// check this on random scenes), including ties: among boxes hit at the same parameter the
// smallest index wins.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "sightline/domains/camera/geometry/aabb.h"
#include "sightline/domains/camera/geometry/segment_box.h"

namespace sightline::camera {

class BoxTree {
 public:
  // Index of a box in the vector given to the constructor.
  using BoxIndex = std::uint32_t;

  struct Hit {
    double t = 0;        // segment parameter of the entry point, in [0, 1]
    BoxIndex box = 0;    // the box entered first (smallest index among equal t)
  };
  struct Nearest {
    double signed_distance = 0;  // Aabb::signed_distance to the nearest box (< 0: inside)
    BoxIndex box = 0;
  };

  BoxTree() = default;
  explicit BoxTree(std::vector<Aabb> boxes);

  // Moves the boxes without rebuilding: `boxes` holds the new box of every box, in the
  // constructor's order (same count). The tree keeps its shape and only recomputes node
  // bounds, bottom up, in O(n) with no allocation; queries stay exact, but the tree gets
  // slower as boxes wander far from where it was built. For movers (scene_at_time.h).
  void refit(const std::vector<Aabb>& boxes);

  std::size_t size() const { return boxes_.size(); }
  bool empty() const { return boxes_.empty(); }
  const Aabb& box(BoxIndex i) const { return boxes_[i]; }
  const std::vector<Aabb>& boxes() const { return boxes_; }
  // Bounds of all boxes (Aabb::empty() when there are none).
  const Aabb& bounds() const { return bounds_; }
  // Depth of the deepest leaf (1 for a single leaf, 0 for an empty tree).
  int depth() const { return depth_; }

  // True when the segment from `a` to `b` touches any box (closed boxes; see segment_box.h).
  // Stops at the first box found.
  bool segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // The first box the segment from `a` to `b` enters; t = 0 when `a` is inside a box.
  std::optional<Hit> first_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // The box with the smallest signed distance to `p`, among those closer than `limit`
  // (nullopt when none is). A finite limit prunes most of the tree: clearance queries only
  // care whether something is within the camera's radius.
  std::optional<Nearest> nearest(const Eigen::Vector3d& p,
                                 double limit = std::numeric_limits<double>::infinity()) const;
  // Calls visit(BoxIndex) for every box whose closed volume contains `p`, in no set order.
  template <class Visit>
  void for_each_containing(const Eigen::Vector3d& p, Visit&& visit) const;
  // Calls visit(BoxIndex) for every box whose closed volume meets the closed `query`
  // (touching counts), in no set order. For gathering the boxes near the camera
  // (nearby_boxes.h).
  template <class Visit>
  void for_each_touching(const Aabb& query, Visit&& visit) const;
  // The smallest-index box whose interior overlaps the interior of `query` (touching is not
  // overlapping).
  std::optional<BoxIndex> any_overlapping(const Aabb& query) const;

 private:
  // 32 bytes: the bounds are floats rounded outward and then padded by kNodePad (1 + |x|)
  // metres, so a node always contains its boxes and a node test can be a fast, slightly
  // conservative one; the boxes themselves are tested exactly, in double.
  struct Node {
    float lo[3];
    float hi[3];
    std::uint32_t first = 0;  // interior: id of the first of its two children; leaf: first item
    std::uint32_t count = 0;  // leaf: number of items (> 0); interior: 0
    Aabb bounds() const {
      return {Eigen::Vector3d(lo[0], lo[1], lo[2]), Eigen::Vector3d(hi[0], hi[1], hi[2])};
    }
  };
  static_assert(sizeof(Node) == 32);
  // Two siblings share one 64-byte cache line: a traversal tests both children of a node
  // together, so each level it descends costs one line, not two.
  struct alignas(64) NodePair {
    Node side[2];
  };
  const Node& node(std::uint32_t id) const { return pairs_[id >> 1].side[id & 1]; }
  Node& node(std::uint32_t id) { return pairs_[id >> 1].side[id & 1]; }

  // A segment prepared for node tests: origin and per-axis 1/delta (inf for 0).
  struct NodeRay {
    double origin[3];
    double inverse[3];
    bool negative[3];  // signbit(inverse): the slab is entered through its max plane
  };
  static NodeRay prepare(const Eigen::Vector3d& a, const Eigen::Vector3d& delta);
  // Conservative: true whenever some box inside the node meets the segment; sets `enter` to a
  // lower bound of the entry parameter of any such box. Needs no division: multiplying by
  // 1/delta errs by ~1e-16 relative, far inside the node padding. Near and far planes are
  // chosen by the sign of 1/delta, so a 0 * inf = NaN (a segment parallel to the slab,
  // starting exactly on a padded plane) fails both comparisons and drops that axis's
  // restriction, which only makes the test more conservative.
  static bool node_hit(const Node& node, const NodeRay& ray, double& enter);
  // Enough for any tree build() makes: the depth is capped well below this (see build()).
  static constexpr int kStackSize = 128;

  void build(std::uint32_t id, std::uint32_t begin, std::uint32_t end, int depth,
             std::vector<Eigen::Vector3d>& centres);

  std::vector<Aabb> boxes_;           // as given, indexed by BoxIndex
  std::vector<Aabb> leaf_boxes_;      // copies in leaf order, for locality
  std::vector<BoxIndex> leaf_index_;  // leaf order -> BoxIndex
  std::vector<NodePair> pairs_;       // node id = 2 x pair + side; the root is node 0
  Aabb bounds_ = Aabb::empty();       // exact bounds of all boxes
  int depth_ = 0;
};

template <class Visit>
void BoxTree::for_each_containing(const Eigen::Vector3d& p, Visit&& visit) const {
  if (pairs_.empty() || !node(0).bounds().contains(p)) return;
  std::uint32_t stack[kStackSize];
  int top = 0;
  stack[top++] = 0;  // nodes on the stack have passed their own test
  while (top > 0) {
    const Node& n = node(stack[--top]);
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        if (leaf_boxes_[i].contains(p)) visit(leaf_index_[i]);
      }
      continue;
    }
    for (std::uint32_t child = n.first; child < n.first + 2; ++child) {
      if (node(child).bounds().contains(p)) stack[top++] = child;
    }
  }
}

template <class Visit>
void BoxTree::for_each_touching(const Aabb& query, Visit&& visit) const {
  auto touches = [&](const Aabb& b) {
    return b.min.x() <= query.max.x() && query.min.x() <= b.max.x() &&
           b.min.y() <= query.max.y() && query.min.y() <= b.max.y() &&
           b.min.z() <= query.max.z() && query.min.z() <= b.max.z();
  };
  if (pairs_.empty() || !touches(node(0).bounds())) return;
  std::uint32_t stack[kStackSize];
  int top = 0;
  stack[top++] = 0;  // nodes on the stack have passed their own test
  while (top > 0) {
    const Node& n = node(stack[--top]);
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        if (touches(leaf_boxes_[i])) visit(leaf_index_[i]);
      }
      continue;
    }
    for (std::uint32_t child = n.first; child < n.first + 2; ++child) {
      if (touches(node(child).bounds())) stack[top++] = child;
    }
  }
}

}  // namespace sightline::camera
