// SolidVolume: where a level is solid, beyond what its triangles say.
//
// A triangle soup has no inside, and a Quake III map's faces that are never seen (caulk,
// the outside of the hull) are not in it at all: a camera could slip into a wall where no
// face stops it, or float in the void outside the world. A level that knows its solid
// volumes (a Quake III map's BSP tree and brushes) answers solid_at() so that no camera
// position, cut target or baseline probe lands there. Points are in the scene's frame
// (metres, y up); implementations map them back to file units themselves.
#pragma once

#include <Eigen/Core>
#include <string>

namespace sightline::camera {

class SolidVolume {
 public:
  virtual ~SolidVolume() = default;
  // True when p is inside solid matter or outside the playable world. Must not allocate
  // (it runs on the per-frame path) and must be safe to call from several threads at once.
  virtual bool solid_at(const Eigen::Vector3d& p) const = 0;
  // One line for people: "Quake III brushes (1234 solid brushes)".
  virtual std::string describe() const = 0;
};

}  // namespace sightline::camera
