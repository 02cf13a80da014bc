#include "sightline/domains/camera/geometry/box_tree.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace sightline::camera {
namespace {

// This many boxes or fewer always make a leaf: testing 4 contiguous boxes costs about as much
// as one more level of nodes, and fewer, larger leaves keep the tree small in the cache.
constexpr std::uint32_t kMinLeaf = 4;
// Up to this many make a leaf when the heuristic finds splitting them no cheaper; more are
// always split (unless the boxes' centres coincide, when no plane can separate them).
constexpr std::uint32_t kMaxLeaf = 16;
constexpr int kBins = 16;
// Beyond this depth, split at the median: it halves the count, so the depth stays below
// kMedianDepth + log2(n) < the traversal stack size.
constexpr int kMedianDepth = 40;
// Node bounds are padded outward by this much times (1 + |coordinate|) metres: orders of
// magnitude more than the rounding of the node test for any scene within +-1e7 m.
constexpr double kNodePad = 1e-6;

// Beyond float's range the bound becomes infinite (a cast would be undefined behaviour).
float padded_down(double x) {
  const double target = x - kNodePad * (1 + std::abs(x));
  if (target < -std::numeric_limits<float>::max()) return -INFINITY;
  if (target > std::numeric_limits<float>::max()) return std::numeric_limits<float>::max();
  float f = static_cast<float>(target);
  if (static_cast<double>(f) > target) f = std::nextafter(f, -INFINITY);
  return f;
}
float padded_up(double x) {
  const double target = x + kNodePad * (1 + std::abs(x));
  if (target > std::numeric_limits<float>::max()) return INFINITY;
  if (target < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::max();
  float f = static_cast<float>(target);
  if (static_cast<double>(f) < target) f = std::nextafter(f, INFINITY);
  return f;
}

}  // namespace

BoxTree::NodeRay BoxTree::prepare(const Eigen::Vector3d& a, const Eigen::Vector3d& delta) {
  NodeRay ray;
  for (int i = 0; i < 3; ++i) {
    ray.origin[i] = a[i];
    ray.inverse[i] = 1.0 / delta[i];  // +-inf for a zero component, by IEEE 754
    ray.negative[i] = std::signbit(ray.inverse[i]);
  }
  return ray;
}

bool BoxTree::node_hit(const Node& node, const NodeRay& ray, double& enter) {
  double t0 = 0;
  double t1 = 1;
  for (int i = 0; i < 3; ++i) {
    const double near_plane = ray.negative[i] ? node.hi[i] : node.lo[i];
    const double far_plane = ray.negative[i] ? node.lo[i] : node.hi[i];
    const double t_near = (near_plane - ray.origin[i]) * ray.inverse[i];
    const double t_far = (far_plane - ray.origin[i]) * ray.inverse[i];
    if (t_near > t0) t0 = t_near;  // false for NaN: the axis then restricts nothing
    if (t_far < t1) t1 = t_far;
  }
  enter = t0;
  return t0 <= t1;
}

BoxTree::BoxTree(std::vector<Aabb> boxes) : boxes_(std::move(boxes)) {
  if (boxes_.size() >= std::numeric_limits<std::uint32_t>::max() / 4) {
    throw std::length_error("BoxTree: too many boxes");
  }
  if (boxes_.empty()) return;
  std::vector<Eigen::Vector3d> centres(boxes_.size());
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    centres[i] = boxes_[i].centre();
    bounds_.merge(boxes_[i]);
  }
  leaf_index_.resize(boxes_.size());
  std::iota(leaf_index_.begin(), leaf_index_.end(), 0u);
  // A binary tree over n items has fewer than 2n nodes: n + 1 pairs never reallocate.
  pairs_.reserve(boxes_.size() + 1);
  pairs_.emplace_back();  // the root alone (its sibling slot stays unused)
  build(0, 0, static_cast<std::uint32_t>(boxes_.size()), 1, centres);
  leaf_boxes_.resize(boxes_.size());
  for (std::size_t i = 0; i < boxes_.size(); ++i) leaf_boxes_[i] = boxes_[leaf_index_[i]];
}

void BoxTree::refit(const std::vector<Aabb>& boxes) {
  if (boxes.size() != boxes_.size()) throw std::invalid_argument("BoxTree::refit: box count changed");
  if (boxes_.empty()) return;
  boxes_ = boxes;  // same size: copies in place
  bounds_ = Aabb::empty();
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    leaf_boxes_[i] = boxes_[leaf_index_[i]];
    bounds_.merge(boxes_[i]);
  }
  // Children are created after their parent (build() appends them), so their ids are larger:
  // a pass from the largest id down sees every child before its parent. Id 1, the root's
  // sibling slot, is unused.
  auto set = [](Node& n, const Aabb& b) {
    for (int i = 0; i < 3; ++i) {
      n.lo[i] = padded_down(b.min[i]);
      n.hi[i] = padded_up(b.max[i]);
    }
  };
  for (auto id = static_cast<std::uint32_t>(2 * pairs_.size() - 1);; --id) {
    if (id == 1) continue;
    Node& n = node(id);
    Aabb b = Aabb::empty();
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) b.merge(leaf_boxes_[i]);
    } else {
      b = node(n.first).bounds();
      b.merge(node(n.first + 1).bounds());
    }
    set(n, b);
    if (id == 0) break;
  }
}

void BoxTree::build(std::uint32_t id, std::uint32_t begin, std::uint32_t end, int depth,
                    std::vector<Eigen::Vector3d>& centres) {
  depth_ = std::max(depth_, depth);
  Aabb bounds = Aabb::empty();
  Aabb centre_bounds = Aabb::empty();
  for (std::uint32_t i = begin; i < end; ++i) {
    bounds.merge(boxes_[leaf_index_[i]]);
    centre_bounds.merge(centres[leaf_index_[i]]);
  }
  for (int i = 0; i < 3; ++i) {
    node(id).lo[i] = padded_down(bounds.min[i]);
    node(id).hi[i] = padded_up(bounds.max[i]);
  }
  const std::uint32_t count = end - begin;
  auto make_leaf = [&] {
    node(id).first = begin;
    node(id).count = count;
  };
  if (count <= kMinLeaf) return make_leaf();

  const Eigen::Vector3d extent = centre_bounds.size();
  int widest = 0;
  extent.maxCoeff(&widest);
  // All centres coincide: no plane separates them. Keep small groups together and halve
  // large ones by position in the list (any split is as good as another).
  if (extent[widest] <= 0 && count <= kMaxLeaf) return make_leaf();

  std::uint32_t mid = begin;
  if (depth < kMedianDepth && extent[widest] > 0) {
    // Surface area heuristic over kBins bins of centres on each axis:
    //   cost(split) = 1 + (A_left * N_left + A_right * N_right) / A_node,  cost(leaf) = N.
    // A is the surface area (halved: only ratios matter); 1 is the cost of visiting a node
    // relative to testing one box.
    double best_cost = std::numeric_limits<double>::infinity();
    int best_axis = -1;
    int best_bin = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (extent[axis] <= 0) continue;
      std::array<Aabb, kBins> bin_bounds;
      bin_bounds.fill(Aabb::empty());
      std::array<std::uint32_t, kBins> bin_count{};
      const double scale = kBins / extent[axis];
      for (std::uint32_t i = begin; i < end; ++i) {
        const BoxIndex b = leaf_index_[i];
        const int bin = std::min(
            kBins - 1, static_cast<int>((centres[b][axis] - centre_bounds.min[axis]) * scale));
        bin_bounds[bin].merge(boxes_[b]);
        ++bin_count[bin];
      }
      // Sweep from the right to know the right side's area and count for each split plane.
      std::array<double, kBins> right_area{};
      std::array<std::uint32_t, kBins> right_count{};
      Aabb acc = Aabb::empty();
      std::uint32_t n = 0;
      for (int bin = kBins - 1; bin > 0; --bin) {
        acc.merge(bin_bounds[bin]);
        n += bin_count[bin];
        right_area[bin] = n ? acc.half_area() : 0;
        right_count[bin] = n;
      }
      acc = Aabb::empty();
      n = 0;
      for (int split = 1; split < kBins; ++split) {  // left = bins [0, split)
        acc.merge(bin_bounds[split - 1]);
        n += bin_count[split - 1];
        if (n == 0 || right_count[split] == 0) continue;
        const double cost =
            1.0 + (acc.half_area() * n + right_area[split] * right_count[split]) /
                      std::max(bounds.half_area(), 1e-300);
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bin = split;
        }
      }
    }
    if (best_axis >= 0 && best_cost >= count && count <= kMaxLeaf) {
      return make_leaf();  // testing the boxes directly is cheaper than splitting
    }
    if (best_axis >= 0) {
      const double scale = kBins / extent[best_axis];
      const double lo = centre_bounds.min[best_axis];
      auto in_left = [&](BoxIndex b) {
        return std::min(kBins - 1, static_cast<int>((centres[b][best_axis] - lo) * scale)) <
               best_bin;
      };
      mid = static_cast<std::uint32_t>(
          std::partition(leaf_index_.begin() + begin, leaf_index_.begin() + end, in_left) -
          leaf_index_.begin());
    }
  }
  if (mid == begin || mid == end) {
    // Median split along the widest axis (deep trees, coincident centres, or no SAH split).
    mid = begin + count / 2;
    std::nth_element(leaf_index_.begin() + begin, leaf_index_.begin() + mid,
                     leaf_index_.begin() + end, [&](BoxIndex a, BoxIndex b) {
                       return centres[a][widest] < centres[b][widest];
                     });
  }
  const auto first = static_cast<std::uint32_t>(2 * pairs_.size());
  pairs_.emplace_back();
  node(id).first = first;
  node(id).count = 0;
  build(first, begin, mid, depth + 1, centres);
  build(first + 1, mid, end, depth + 1, centres);
}

bool BoxTree::segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (pairs_.empty()) return false;
  const Eigen::Vector3d delta = b - a;
  const NodeRay ray = prepare(a, delta);
  double enter;
  if (!node_hit(node(0), ray, enter)) return false;
  std::uint32_t stack[kStackSize];
  int top = 0;
  stack[top++] = 0;  // nodes on the stack have passed their own test
  SegmentClip clip;
  while (top > 0) {
    const Node& n = node(stack[--top]);
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        if (clip_segment_to_box(a, delta, leaf_boxes_[i], 1.0, clip)) return true;
      }
      continue;
    }
    assert(top + 2 <= kStackSize);
    if (node_hit(node(n.first + 1), ray, enter)) stack[top++] = n.first + 1;
    if (node_hit(node(n.first), ray, enter)) stack[top++] = n.first;
  }
  return false;
}

std::optional<BoxTree::Hit> BoxTree::first_hit(const Eigen::Vector3d& a,
                                               const Eigen::Vector3d& b) const {
  if (pairs_.empty()) return std::nullopt;
  const Eigen::Vector3d delta = b - a;
  const NodeRay ray = prepare(a, delta);
  struct Pending {
    std::uint32_t node;
    double enter;  // a lower bound of the entry parameter of the node's boxes
  };
  Pending stack[kStackSize];
  int top = 0;
  double root_enter;
  if (!node_hit(node(0), ray, root_enter)) return std::nullopt;
  stack[top++] = {0, root_enter};
  SegmentClip clip;
  bool found = false;
  Hit best{std::numeric_limits<double>::infinity(), 0};
  while (top > 0) {
    const Pending pending = stack[--top];
    // A node entered after the best hit cannot hold a better one. Equal entries are still
    // visited: they may hold a box with the same t and a smaller index.
    if (pending.enter > best.t) continue;
    const Node& n = node(pending.node);
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        if (!clip_segment_to_box(a, delta, leaf_boxes_[i], 1.0, clip)) continue;
        const BoxIndex index = leaf_index_[i];
        if (!found || clip.enter < best.t || (clip.enter == best.t && index < best.box)) {
          best = {clip.enter, index};
          found = true;
        }
      }
      continue;
    }
    // Push the farther child first so the nearer one is explored first and tightens best.t.
    const std::uint32_t left = n.first;
    const std::uint32_t right = n.first + 1;
    double left_enter, right_enter;
    const bool left_hit = node_hit(node(left), ray, left_enter);
    const bool right_hit = node_hit(node(right), ray, right_enter);
    assert(top + 2 <= kStackSize);
    if (left_hit && right_hit) {
      if (left_enter <= right_enter) {
        stack[top++] = {right, right_enter};
        stack[top++] = {left, left_enter};
      } else {
        stack[top++] = {left, left_enter};
        stack[top++] = {right, right_enter};
      }
    } else if (left_hit) {
      stack[top++] = {left, left_enter};
    } else if (right_hit) {
      stack[top++] = {right, right_enter};
    }
  }
  if (!found) return std::nullopt;
  return best;
}

std::optional<BoxTree::Nearest> BoxTree::nearest(const Eigen::Vector3d& p, double limit) const {
  if (pairs_.empty()) return std::nullopt;
  struct Pending {
    std::uint32_t node;
    double bound;  // signed distance to the node's bounds: a lower bound for its boxes
  };
  Pending stack[kStackSize];
  int top = 0;
  stack[top++] = {0, node(0).bounds().signed_distance(p)};
  bool found = false;
  Nearest best{limit, 0};
  // A node whose lower bound exceeds the best so far is skipped; before anything is found the
  // best is `limit`, which must be beaten strictly.
  auto worth = [&](double bound) {
    return found ? bound <= best.signed_distance : bound < best.signed_distance;
  };
  while (top > 0) {
    const Pending pending = stack[--top];
    if (!worth(pending.bound)) continue;
    const Node& n = node(pending.node);
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const double d = leaf_boxes_[i].signed_distance(p);
        const BoxIndex index = leaf_index_[i];
        if (!worth(d)) continue;
        if (!found || d < best.signed_distance || index < best.box) {
          best = {d, index};
          found = true;
        }
      }
      continue;
    }
    const std::uint32_t left = n.first;
    const std::uint32_t right = n.first + 1;
    const double left_bound = node(left).bounds().signed_distance(p);
    const double right_bound = node(right).bounds().signed_distance(p);
    assert(top + 2 <= kStackSize);
    if (left_bound <= right_bound) {
      stack[top++] = {right, right_bound};
      stack[top++] = {left, left_bound};
    } else {
      stack[top++] = {left, left_bound};
      stack[top++] = {right, right_bound};
    }
  }
  if (!found) return std::nullopt;
  return best;
}

std::optional<BoxTree::BoxIndex> BoxTree::any_overlapping(const Aabb& query) const {
  if (pairs_.empty() || !node(0).bounds().overlaps_interior(query)) return std::nullopt;
  std::uint32_t stack[kStackSize];
  int top = 0;
  stack[top++] = 0;
  std::optional<BoxIndex> best;
  while (top > 0) {
    const Node& n = node(stack[--top]);
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        if (leaf_boxes_[i].overlaps_interior(query) && (!best || leaf_index_[i] < *best)) {
          best = leaf_index_[i];
        }
      }
      continue;
    }
    for (std::uint32_t child = n.first; child < n.first + 2; ++child) {
      if (node(child).bounds().overlaps_interior(query)) stack[top++] = child;
    }
  }
  return best;
}

}  // namespace sightline::camera
