#include "sightline/domains/camera/level/q3_solid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline::camera {

Q3SolidVolume::Q3SolidVolume(q3::BspTree tree, const LevelTransform& transform)
    : transform_(transform) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Each solid brush with sides, once, wherever leaves and models list it.
  std::vector<std::int32_t> compact(tree.brushes.size(), -1);
  for (std::size_t b = 0; b < tree.brushes.size(); ++b) {
    const q3::Brush& brush = tree.brushes[b];
    if (!tree.shaders[static_cast<std::size_t>(brush.shader)].solid()) continue;
    ++solid_brushes_;
    if (brush.side_count == 0) continue;  // no side: contains nothing
    SolidBrush out;
    out.max = Eigen::Vector3d::Constant(kInf);
    out.neg_min = Eigen::Vector3d::Constant(kInf);
    out.first_plane = static_cast<std::int32_t>(planes_.size());
    for (std::int32_t s = 0; s < brush.side_count; ++s) {
      const q3::BrushSide& side = tree.brushsides[static_cast<std::size_t>(brush.first_side + s)];
      const q3::Plane& plane = tree.planes[static_cast<std::size_t>(side.plane)];
      const Eigen::Vector3d normal = plane.normal.cast<double>();
      const double dist = plane.dist;
      int axis = -1;
      for (int k = 0; k < 3; ++k) {
        if (normal[(k + 1) % 3] == 0 && normal[(k + 2) % 3] == 0 && std::abs(normal[k]) == 1)
          axis = k;
      }
      // An axial side's test, normal . p > dist, is p[k] > dist or -p[k] > dist exactly
      // (the other products are zeros); of several, the least dist decides.
      if (axis >= 0 && normal[axis] == 1) {
        out.max[axis] = std::min(out.max[axis], dist);
      } else if (axis >= 0) {
        out.neg_min[axis] = std::min(out.neg_min[axis], dist);
      } else {
        planes_.push_back({normal, dist});
      }
    }
    out.plane_count = static_cast<std::int32_t>(planes_.size()) - out.first_plane;
    compact[b] = static_cast<std::int32_t>(brushes_.size());
    brushes_.push_back(out);
  }
  auto list_of = [&](auto&& each_brush) {
    BrushList list{static_cast<std::int32_t>(solid_lists_.size()), 0};
    each_brush([&](std::int32_t b) {
      if (compact[static_cast<std::size_t>(b)] < 0) return;
      solid_lists_.push_back(compact[static_cast<std::size_t>(b)]);
      ++list.count;
    });
    return list;
  };
  nodes_.reserve(tree.nodes.size());
  for (const q3::Node& node : tree.nodes) {
    const q3::Plane& plane = tree.planes[static_cast<std::size_t>(node.plane)];
    nodes_.push_back({plane.normal.cast<double>(), plane.dist, node.children});
  }
  leaves_.reserve(tree.leaves.size());
  for (const q3::Leaf& leaf : tree.leaves) {
    const BrushList brushes = list_of([&](auto&& add) {
      for (std::int32_t k = 0; k < leaf.leafbrush_count; ++k) {
        add(tree.leafbrushes[static_cast<std::size_t>(leaf.first_leafbrush + k)]);
      }
    });
    leaves_.push_back({leaf.cluster, brushes});
  }
  // The brush entities, where they stand in the map (model 0 is the world, in the leaves).
  brush_models_ = tree.models.empty() ? 0 : tree.models.size() - 1;
  for (std::size_t m = 1; m < tree.models.size(); ++m) {
    const q3::Model& model = tree.models[m];
    const BrushList list = list_of([&](auto&& add) {
      for (std::int32_t k = 0; k < model.brush_count; ++k) add(model.first_brush + k);
    });
    if (list.count > 0)
      models_.push_back({model.mins.cast<double>(), model.maxs.cast<double>(), list});
  }
}

bool Q3SolidVolume::solid_at(const Eigen::Vector3d& p) const {
  return solid_at_file(transform_.to_file(p));
}

bool Q3SolidVolume::solid_at_file(const Eigen::Vector3d& p) const {
  // Down the tree: children come after their parents (checked by the parser), so this ends.
  std::int32_t index = 0;
  while (index >= 0) {
    const Node& node = nodes_[static_cast<std::size_t>(index)];
    index = node.children[node.normal.dot(p) - node.dist >= 0 ? 0 : 1];
  }
  const Leaf& leaf = leaves_[static_cast<std::size_t>(-(index + 1))];
  if (leaf.cluster < 0) return true;  // outside the world, or inside opaque matter
  if (in_any(leaf.brushes, p)) return true;
  for (const BrushModel& model : models_) {
    if ((p.array() < model.mins.array()).any() || (p.array() > model.maxs.array()).any()) continue;
    if (in_any(model.brushes, p)) return true;
  }
  return false;
}

bool Q3SolidVolume::in_any(const BrushList& list, const Eigen::Vector3d& p) const {
  for (std::int32_t k = 0; k < list.count; ++k) {
    const auto b = static_cast<std::size_t>(solid_lists_[static_cast<std::size_t>(list.first + k)]);
    if (in_solid_brush(brushes_[b], p)) return true;
  }
  return false;
}

// On or behind every side plane (the normals point out of the brush): the axial ones as a
// box, then the others.
bool Q3SolidVolume::in_solid_brush(const SolidBrush& brush, const Eigen::Vector3d& p) const {
  for (int k = 0; k < 3; ++k) {
    if (p[k] > brush.max[k] || -p[k] > brush.neg_min[k]) return false;
  }
  for (std::int32_t s = 0; s < brush.plane_count; ++s) {
    const SidePlane& plane = planes_[static_cast<std::size_t>(brush.first_plane + s)];
    if (plane.normal.dot(p) > plane.dist) return false;
  }
  return true;
}

std::string Q3SolidVolume::describe() const {
  return "Quake III brushes (" + std::to_string(solid_brushes_) + " solid brushes, " +
         std::to_string(brush_models_) + " brush models)";
}

}  // namespace sightline::camera
