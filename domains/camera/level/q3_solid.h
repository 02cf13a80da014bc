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
//
// The camera asks this for every point it prices (each clearance query), so the arrays are
// laid out for that walk, not as the file has them: each node carries its plane; each leaf
// and each brush model lists only its solid brushes; and each solid brush is the box of its
// axial sides (q3map2 gives every brush its six axial bevels: p.x <= dist for a side
// (1, 0, 0), -p.x <= dist for (-1, 0, 0)), tested first, then its other side planes, side by
// side in one array. The same comparisons as the sides', in the same arithmetic, so for
// every finite point the answers are the file's to the bit (tests/domains/level/
// q3_solid_test.cc checks them against the game's walk over the raw lumps). Walking the
// file's own indirections (leaf -> leafbrush -> brush -> side -> plane) took a third of the
// camera's frame on level walks.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

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
  // A node with its plane: front child for normal . p - dist >= 0 (children as q3::Node's).
  struct Node {
    Eigen::Vector3d normal;
    double dist;
    std::array<std::int32_t, 2> children;
  };
  // A solid brush: the box of its axial sides (for a missing side, +infinity), then its
  // other sides, planes_[first_plane, first_plane + plane_count).
  struct SolidBrush {
    Eigen::Vector3d max;      // p[k] > max[k]: outside (the sides +axis k)
    Eigen::Vector3d neg_min;  // -p[k] > neg_min[k]: outside (the sides -axis k)
    std::int32_t first_plane = 0, plane_count = 0;
  };
  struct SidePlane {
    Eigen::Vector3d normal;
    double dist;
  };
  // A run of solid brush indices, solid_lists_[first, first + count).
  struct BrushList {
    std::int32_t first = 0, count = 0;
  };
  struct Leaf {
    std::int32_t cluster;  // < 0: outside the world or opaque
    BrushList brushes;
  };
  struct BrushModel {
    Eigen::Vector3d mins, maxs;
    BrushList brushes;
  };

  bool in_solid_brush(const SolidBrush& brush, const Eigen::Vector3d& p) const;
  bool in_any(const BrushList& list, const Eigen::Vector3d& p) const;

  LevelTransform transform_;
  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;
  std::vector<BrushModel> models_;  // the brush entities with solid brushes (models 1..n)
  std::vector<std::int32_t> solid_lists_;
  std::vector<SolidBrush> brushes_;  // the map's solid brushes with sides
  std::vector<SidePlane> planes_;
  int solid_brushes_ = 0;
  std::size_t brush_models_ = 0;
};

}  // namespace sightline::camera
