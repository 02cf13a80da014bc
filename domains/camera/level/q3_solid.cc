#include "sightline/domains/camera/level/q3_solid.h"

namespace sightline::camera {

Q3SolidVolume::Q3SolidVolume(q3::BspTree tree, const LevelTransform& transform)
    : tree_(std::move(tree)), transform_(transform) {
  brush_solid_.reserve(tree_.brushes.size());
  for (const auto& brush : tree_.brushes) {
    const bool solid = tree_.shaders[static_cast<std::size_t>(brush.shader)].solid();
    brush_solid_.push_back(solid ? 1 : 0);
    solid_brushes_ += solid ? 1 : 0;
  }
}

bool Q3SolidVolume::solid_at(const Eigen::Vector3d& p) const {
  return solid_at_file(transform_.to_file(p));
}

bool Q3SolidVolume::solid_at_file(const Eigen::Vector3d& p) const {
  // Down the tree: children come after their parents (checked by the parser), so this ends.
  std::int32_t index = 0;
  while (index >= 0) {
    const q3::Node& node = tree_.nodes[static_cast<std::size_t>(index)];
    const q3::Plane& plane = tree_.planes[static_cast<std::size_t>(node.plane)];
    const double side = plane.normal.cast<double>().dot(p) - plane.dist;
    index = node.children[side >= 0 ? 0 : 1];
  }
  const q3::Leaf& leaf = tree_.leaves[static_cast<std::size_t>(-(index + 1))];
  if (leaf.cluster < 0) return true;  // outside the world, or inside opaque matter
  for (std::int32_t k = 0; k < leaf.leafbrush_count; ++k) {
    if (in_solid_brush(tree_.leafbrushes[static_cast<std::size_t>(leaf.first_leafbrush + k)], p)) {
      return true;
    }
  }
  // The brush entities, where they stand in the map (model 0 is the world, done above).
  for (std::size_t m = 1; m < tree_.models.size(); ++m) {
    const q3::Model& model = tree_.models[m];
    if ((p.array() < model.mins.cast<double>().array()).any() ||
        (p.array() > model.maxs.cast<double>().array()).any()) {
      continue;
    }
    for (std::int32_t k = 0; k < model.brush_count; ++k) {
      if (in_solid_brush(model.first_brush + k, p)) return true;
    }
  }
  return false;
}

// On or behind every side plane (the normals point out of the brush).
bool Q3SolidVolume::in_solid_brush(std::int32_t index, const Eigen::Vector3d& p) const {
  const auto b = static_cast<std::size_t>(index);
  if (!brush_solid_[b]) return false;
  const q3::Brush& brush = tree_.brushes[b];
  if (brush.side_count == 0) return false;
  for (std::int32_t s = 0; s < brush.side_count; ++s) {
    const q3::BrushSide& side = tree_.brushsides[static_cast<std::size_t>(brush.first_side + s)];
    const q3::Plane& plane = tree_.planes[static_cast<std::size_t>(side.plane)];
    if (plane.normal.cast<double>().dot(p) > plane.dist) return false;
  }
  return true;
}

std::string Q3SolidVolume::describe() const {
  return "Quake III brushes (" + std::to_string(solid_brushes_) + " solid brushes, " +
         std::to_string(tree_.models.empty() ? 0 : tree_.models.size() - 1) + " brush models)";
}

}  // namespace sightline::camera
