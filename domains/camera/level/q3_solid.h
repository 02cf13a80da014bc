// Q3SolidVolume: where a Quake III map is solid, from its BSP tree and brushes.
//
// A map's faces miss much of its matter (caulked sides, the outside of the hull), so the
// camera asks the map itself: the point, mapped back to file units, falls down the BSP tree
// to one leaf; it is solid when that leaf is outside the world or opaque (cluster < 0), or
// when it lies inside one of the leaf's brushes whose contents include CONTENTS_SOLID
// (on or behind every side plane: normal . p <= dist). This is how the game's own point
// contents test works (CM_PointContents), with the contents limited to "solid". The brush
// entities (doors, platforms: models 1..n, which no leaf lists) are solid too, where they
// stand in the map, as their faces are in the level's mesh: a point inside one of their
// solid brushes (within the model's bounds first) is solid.
//
// solid_at() walks arrays only: no allocation, no mutable state, safe from any thread.
#pragma once

#include <string>

#include "sightline/domains/camera/geometry/solid_volume.h"
#include "sightline/domains/camera/level/level_transform.h"
#include "sightline/domains/camera/level/q3_bsp.h"

namespace sightline::camera {

class Q3SolidVolume final : public SolidVolume {
 public:
  // `tree` as parse_bsp() checked it (every index in range, children after parents).
  Q3SolidVolume(q3::BspTree tree, const LevelTransform& transform);

  bool solid_at(const Eigen::Vector3d& p) const override;
  std::string describe() const override;

  // The same test for a point in file units (z up), for tests and tools.
  bool solid_at_file(const Eigen::Vector3d& file_point) const;

 private:
  bool in_solid_brush(std::int32_t brush, const Eigen::Vector3d& p) const;

  q3::BspTree tree_;
  LevelTransform transform_;
  std::vector<char> brush_solid_;  // per brush: its shader's contents include solid
  int solid_brushes_ = 0;
};

}  // namespace sightline::camera
