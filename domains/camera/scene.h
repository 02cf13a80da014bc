// Scene: the world a chase camera works in, and the geometric questions it answers.
//
// Solid axis-aligned boxes (walls, pillars, roofs; a door is a gap between wall boxes, so
// visibility through doors is exact with no special case), semantic areas (enclosed rooms,
// semi-enclosed courtyards) the camera adapts to, the character's body and path, and the
// camera's start and profile. Boxes and areas each live in a BoxTree, so every query below
// costs O(log n) in the number of boxes and none allocates.
//
// Scenes are read from YAML by scene_file.h; the constructor takes already validated parts.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "csp/input_error.h"
#include "domains/camera/geometry/aabb.h"
#include "domains/camera/geometry/box_tree.h"
#include "domains/camera/profile.h"
#include "domains/camera/trajectory.h"

namespace sightline::camera {

struct SolidBox {
  std::string name;  // may be empty
  Aabb box;
  csp::SourceLocation where;  // where it was written, for messages
};

struct Area {
  std::string name;
  AreaKind kind = AreaKind::kEnclosed;
  Aabb box;
  csp::SourceLocation where;
};

// The character's body: an axis-aligned box (it does not turn with the yaw) whose origin is
// the centre of its feet, and the point the camera aims at.
struct CharacterShape {
  Eigen::Vector3d size{0.6, 1.8, 0.6};  // extents along x, y, z, metres, > 0
  double look_at_height = 1.5;          // metres above the feet, in (0, size.y]

  Aabb body_at(const Eigen::Vector3d& feet) const { return Aabb::around_feet(feet, size); }
  Eigen::Vector3d look_at(const Eigen::Vector3d& feet) const {
    return feet + Eigen::Vector3d(0, look_at_height, 0);
  }
};

class Scene {
 public:
  Scene(std::string name, std::vector<SolidBox> solids, std::vector<Area> areas,
        CharacterShape character, Trajectory trajectory, double frame_rate = 60);

  // --- what the scene is ---
  const std::string& name() const { return name_; }
  const std::string& description() const { return description_; }
  void set_description(std::string text) { description_ = std::move(text); }
  double frame_rate() const { return frame_rate_; }
  const std::vector<SolidBox>& solids() const { return solids_; }
  const std::vector<Area>& areas() const { return areas_; }
  const CharacterShape& character() const { return character_; }
  const Trajectory& trajectory() const { return trajectory_; }
  // Bounds of the solid boxes and the areas (Aabb::empty() when there are none).
  Aabb world_bounds() const;

  // The camera's start, when the file gives one; otherwise the profile's ideal spot.
  const std::optional<Eigen::Vector3d>& camera_start() const { return camera_start_; }
  void set_camera_start(std::optional<Eigen::Vector3d> start) { camera_start_ = start; }
  Eigen::Vector3d start_camera_position() const;
  const CameraProfile& profile() const { return profile_; }
  // Where the profile came from: "preset thesis-default", "file close.yaml", "inline".
  const std::string& profile_source() const { return profile_source_; }
  void set_profile(CameraProfile profile, std::string source);

  // --- frames ---
  std::size_t frame_count() const { return trajectory_.frame_count(frame_rate_); }
  double frame_time(std::size_t frame) const { return trajectory_.frame_time(frame, frame_rate_); }
  CharacterState character_at(double t) const { return trajectory_.state_at(t); }

  // --- geometric queries (no allocation unless stated) ---
  // True when the segment from a to b touches no solid box (touching a face blocks).
  bool line_of_sight(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return !solid_tree_.segment_blocked(a, b);
  }
  // The first solid box along the segment from a to b (t in [0, 1]; 0 when a is inside one).
  std::optional<BoxTree::Hit> first_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return solid_tree_.first_hit(a, b);
  }
  // Signed distance from p to the nearest solid box (< 0 inside one). Distances of `limit`
  // or more are reported as `limit` (infinity with no boxes): a clearance test only needs to
  // know whether something is nearer than the camera's radius, and the limit prunes the tree.
  double clearance(const Eigen::Vector3d& p,
                   double limit = std::numeric_limits<double>::infinity()) const;
  // Indices of the areas whose closed box contains p, ascending. Allocates: for tools.
  std::vector<std::size_t> areas_containing(const Eigen::Vector3d& p) const;
  // The innermost area containing p (smallest volume; ties go to the smaller index).
  std::optional<std::size_t> innermost_area(const Eigen::Vector3d& p) const;
  // The smallest-index solid box whose interior overlaps `box`.
  std::optional<std::size_t> solid_overlapping(const Aabb& box) const;

  const BoxTree& solid_tree() const { return solid_tree_; }
  const BoxTree& area_tree() const { return area_tree_; }

 private:
  std::string name_;
  std::string description_;
  std::vector<SolidBox> solids_;
  std::vector<Area> areas_;
  CharacterShape character_;
  Trajectory trajectory_;
  double frame_rate_;
  std::optional<Eigen::Vector3d> camera_start_;
  CameraProfile profile_;
  std::string profile_source_ = "preset thesis-default";
  BoxTree solid_tree_;
  BoxTree area_tree_;
};

}  // namespace sightline::camera
