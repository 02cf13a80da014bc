// triangle_bvh_build.cc: building the example's bounding-volume hierarchy (see
// triangle_bvh.h for what and why).
//
// Top-down: each node is split along the longest axis of its triangles' centres, at the
// cheapest of kBinCount - 1 planes by the surface-area heuristic (the expected cost of a ray
// visiting both halves), until a node holds kLeafSize triangles or fewer. Triangles are
// copied into leaf order so that a leaf reads one block of memory. O(n log n); the index
// allocates here only.
#include <algorithm>
#include <array>
#include <limits>

#include "triangle_bvh.h"

namespace example {
namespace {

constexpr std::size_t kLeafSize = 4;  // split nodes holding more triangles than this
constexpr int kBinCount = 12;         // candidate split planes per node, plus one
constexpr double kBoxPad = 1e-6;      // metres added around node boxes against rounding
constexpr double kMinSine = 1e-6;     // needles thinner than this (sine of an angle) are out
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Box {
  V3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};  // empty

  void grow(const V3& p) { grow(p, p); }
  void grow(const Box& b) { grow(b.lo, b.hi); }
  void grow(const V3& min, const V3& max) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], min[k]);
      hi[k] = std::max(hi[k], max[k]);
    }
  }
  double half_area() const {
    const V3 e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

// A needle or a point blocks no ray, and the closest-point formulas divide by its area.
bool is_needle(const V3& a, const V3& b, const V3& c) {
  const V3 e1 = b - a, e2 = c - a;
  return length_squared(cross(e1, e2)) <=
         kMinSine * kMinSine * length_squared(e1) * length_squared(e2);
}

}  // namespace

struct TriangleBvh::Item {
  Box bounds;
  V3 centre;
  Triangle triangle;
};

TriangleBvh::TriangleBvh(std::span<const double> vertices, std::span<const std::uint32_t> indices) {
  const auto vertex = [&](std::uint32_t i) {
    return V3{vertices[3 * std::size_t{i}], vertices[3 * std::size_t{i} + 1],
              vertices[3 * std::size_t{i} + 2]};
  };
  std::vector<Item> items;
  items.reserve(indices.size() / 3);
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const Triangle tri{vertex(indices[t]), vertex(indices[t + 1]), vertex(indices[t + 2])};
    if (is_needle(tri.a, tri.b, tri.c)) continue;
    Item item{{}, {}, tri};
    item.bounds.grow(tri.a);
    item.bounds.grow(tri.b);
    item.bounds.grow(tri.c);
    item.centre = 0.5 * (item.bounds.lo + item.bounds.hi);
    items.push_back(item);
  }
  nodes_.reserve(2 * items.size());
  triangles_.reserve(items.size());
  if (!items.empty()) build_node(items, 0);
}

std::uint32_t TriangleBvh::build_node(std::span<Item> items, int depth) {
  const auto id = static_cast<std::uint32_t>(nodes_.size());
  Box bounds;
  for (const Item& item : items) bounds.grow(item.bounds);
  const V3 pad{kBoxPad, kBoxPad, kBoxPad};
  nodes_.push_back(Node{bounds.lo - pad, bounds.hi + pad, 0, 0});
  if (items.size() <= kLeafSize || depth >= kMaxDepth) {
    nodes_[id].first = static_cast<std::uint32_t>(triangles_.size());
    nodes_[id].count = static_cast<std::uint32_t>(items.size());
    for (const Item& item : items) triangles_.push_back(item.triangle);
    return id;
  }
  const std::size_t mid = split(items);
  build_node(items.first(mid), depth + 1);  // the first child is the next node
  const std::uint32_t second = build_node(items.subspan(mid), depth + 1);
  nodes_[id].first = second;
  return id;
}

// Reorders the items into two non-empty runs by the cheapest binned plane and returns where
// the second starts.
std::size_t TriangleBvh::split(std::span<Item> items) {
  Box centres;
  for (const Item& item : items) centres.grow(item.centre);
  const V3 extent = centres.hi - centres.lo;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  if (!(extent[axis] > 0)) return items.size() / 2;  // all centres coincide: any halves

  const double start = centres.lo[axis], scale = kBinCount / extent[axis];
  const auto bin_of = [&](const Item& item) {
    return std::clamp(static_cast<int>((item.centre[axis] - start) * scale), 0, kBinCount - 1);
  };
  std::array<Box, kBinCount> bins;
  std::array<std::size_t, kBinCount> counts{};
  for (const Item& item : items) {
    const int k = bin_of(item);
    bins[k].grow(item.bounds);
    ++counts[k];
  }
  // Plane p separates bins [0, p] from [p + 1, kBinCount): sweep from the right, then the left.
  std::array<double, kBinCount - 1> right_cost;
  Box box;
  std::size_t n = 0;
  for (int p = kBinCount - 2; p >= 0; --p) {
    box.grow(bins[p + 1]);
    n += counts[p + 1];
    right_cost[p] = n ? box.half_area() * static_cast<double>(n) : kInf;
  }
  int best = 0;
  double best_cost = kInf;
  box = Box{};
  n = 0;
  for (int p = 0; p < kBinCount - 1; ++p) {
    box.grow(bins[p]);
    n += counts[p];
    const double cost = n ? box.half_area() * static_cast<double>(n) + right_cost[p] : kInf;
    if (cost < best_cost) {
      best_cost = cost;
      best = p;
    }
  }
  // The lowest and highest centres fall in the first and last bins, so both runs are filled.
  const auto second = std::partition(items.begin(), items.end(),
                                     [&](const Item& item) { return bin_of(item) <= best; });
  return static_cast<std::size_t>(second - items.begin());
}

}  // namespace example
