// libFuzzer target for the Quake III map parser (q3_bsp.h): any bytes either parse or throw
// csp::InputError, never crash, overflow, leak or hang, and what parses keeps the promises
// the rest of the program relies on without checking again (q3_solid.cc indexes the tree
// blindly; the mesh goes to Embree): every index in range, every coordinate finite.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/level/q3_bsp.h"

namespace {

using namespace sightline::camera::q3;

void require(bool promise) {
  if (!promise) std::abort();  // libFuzzer saves the input as a crash
}

bool in(std::int64_t index, std::size_t size) {
  return index >= 0 && static_cast<std::uint64_t>(index) < size;
}

void check_promises(const Bsp& bsp) {
  for (const auto& v : bsp.vertices) require(v.allFinite());
  for (const auto& t : bsp.triangles) {
    for (std::uint32_t i : t) require(i < bsp.vertices.size());
  }
  require(bsp.triangles.size() <= kMaxTriangles);
  const BspTree& tree = bsp.tree;
  require(!tree.nodes.empty() && !tree.leaves.empty());
  for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
    require(in(tree.nodes[n].plane, tree.planes.size()));
    for (std::int32_t child : tree.nodes[n].children) {
      if (child < 0) {
        require(in(-(static_cast<std::int64_t>(child) + 1), tree.leaves.size()));
      } else {
        require(static_cast<std::size_t>(child) > n && in(child, tree.nodes.size()));
      }
    }
  }
  for (const auto& leaf : tree.leaves) {
    require(leaf.first_leafbrush >= 0 && leaf.leafbrush_count >= 0 &&
            static_cast<std::uint64_t>(leaf.first_leafbrush) + leaf.leafbrush_count <=
                tree.leafbrushes.size());
  }
  for (std::int32_t b : tree.leafbrushes) require(in(b, tree.brushes.size()));
  for (const auto& brush : tree.brushes) {
    require(in(brush.shader, tree.shaders.size()));
    require(brush.first_side >= 0 && brush.side_count >= 0 &&
            static_cast<std::uint64_t>(brush.first_side) + brush.side_count <=
                tree.brushsides.size());
  }
  for (const auto& side : tree.brushsides) require(in(side.plane, tree.planes.size()));
  for (const auto& model : tree.models) {
    require(model.mins.allFinite() && model.maxs.allFinite());
    require(model.first_brush >= 0 && model.brush_count >= 0 &&
            static_cast<std::uint64_t>(model.first_brush) + model.brush_count <=
                tree.brushes.size());
  }
  for (const auto& plane : tree.planes)
    require(plane.normal.allFinite() && std::isfinite(plane.dist));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    check_promises(parse_bsp(std::span<const unsigned char>(data, size), "fuzz.bsp"));
  } catch (const sightline::csp::InputError&) {
    // The expected answer to a bad map.
  }
  return 0;
}
