// Scene: the world a chase camera works in, and the geometric questions it answers.
//
// Solid axis-aligned boxes (walls, pillars, roofs; a door is a gap between wall boxes, so
// visibility through doors is exact with no special case), optionally a level (a triangle
// mesh read from a game level or a mesh file, with the solid volumes the format knows),
// semantic areas (enclosed rooms, semi-enclosed courtyards) the camera adapts to, the
// character's body and path, and the camera's start and profile.
//
// The geometric queries below are the one interface every user of the geometry goes
// through (constraints, the controller, the baselines, the metrics' fast paths, the report's
// ray-cast views), whatever the source: boxes live in a BoxTree, the level's triangles in an
// Embree index (TriangleIndex), each O(log n) per query, none allocating. Boxes stay in the
// BoxTree. Measured (docs/BENCHMARKS.md, "Boxes: BoxTree or Embree"), the same boxes as 12
// triangles each in Embree answer sight lines about 3x and clearance 5-7x faster, but they
// are hollow: a point inside a box is neither blocked nor "inside" (no signed distance, which
// the clearance constraint's gradient and the keyframe checks need), and they build 10-14x
// slower. Box scenes already run well inside the frame budget, so exactness won.
//
// Scenes are read from YAML by scene_file.h; the constructor takes already validated parts.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/geometry/aabb.h"
#include "sightline/domains/camera/geometry/box_tree.h"
#include "sightline/domains/camera/geometry/triangle_index.h"
#include "sightline/domains/camera/level/level.h"
#include "sightline/domains/camera/mover.h"
#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/trajectory.h"
#include "sightline/world.h"

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

// A person of the scene other than the followed character (FORMATS.md `actors:`): a body
// like the character's on a path of its own. The scene also lists each actor as a mover of
// its size on its path's positions, so actors block sight and the camera as movers do at
// every frame's time; this record keeps what composition needs (the aim point, the yaw).
struct Actor {
  std::string name;  // unique among the scene's actors
  CharacterShape shape;
  Trajectory trajectory;
  csp::SourceLocation where;
  std::vector<csp::SourceLocation> keyframe_where;  // each keyframe's, for messages
  CharacterState state_at(double t) const { return trajectory.state_at(t); }
  Eigen::Vector3d aim_point(double t) const { return shape.look_at(state_at(t).position); }
};

// What a sight line or probe hits first: a solid box or a level triangle.
struct SurfaceHit {
  enum class Source { kBox, kTriangle, kMover };
  double t = 0;          // segment parameter of the hit, in [0, 1] (0 when starting inside)
  Source source = Source::kBox;
  std::uint32_t index = 0;  // the box (into solids()), the triangle (into level mesh) or the mover
  // Unit normal of the surface hit, facing the segment's start (for shading and sliding);
  // zero when the segment starts inside a box.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

// The nearest solid surface to a point, for clearance and its gradient.
struct NearestSurface {
  // Distance to the nearest surface; < 0 inside a box or inside the level's solid volume.
  double signed_distance = 0;
  // Gradient of signed_distance in p (unit): which way to move to get farther from it.
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
};

struct Shot;         // composition/shot.h: a scene's shot: block (the camera domain only
struct ScriptEntry;  // holds them), its named shots and its script

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
  // Whether someone is chased (FORMATS.md "Actors": a scene framed by a shot: block may have
  // nobody chased; its trajectory() is then the first target's, for the frames' times and
  // the trace's char_* columns, and character() is not a person of the scene).
  bool has_character() const { return has_character_; }
  // The followed character's name among the people: "character".
  const std::string& character_name() const { return character_name_; }
  void set_no_character() { has_character_ = false; }

  // The scene's shot: block (FORMATS.md "Shots"), or null: the camera then chases.
  const Shot* shot() const { return shot_.get(); }
  void set_shot(std::shared_ptr<const Shot> shot) { shot_ = std::move(shot); }
  // The scene's named shots (shots:) and script (script:), for an editor; empty without.
  const std::vector<std::shared_ptr<const Shot>>& named_shots() const { return named_shots_; }
  const std::vector<ScriptEntry>* script() const { return script_.get(); }
  void set_direction(std::vector<std::shared_ptr<const Shot>> named_shots,
                     std::shared_ptr<const std::vector<ScriptEntry>> script) {
    named_shots_ = std::move(named_shots);
    script_ = std::move(script);
  }
  // Bounds of the solid boxes, the level, the areas and the movers' swept boxes (Aabb::empty() when there are none).
  Aabb world_bounds() const;

  // Boxes that move on their own keyframes. Scene's queries below answer for the static
  // geometry only; SceneAtTime (scene_at_time.h) answers for everything at a given time.
  const std::vector<Mover>& movers() const { return movers_; }
  void set_movers(std::vector<Mover> movers) { movers_ = std::move(movers); }
  // The other people (FORMATS.md `actors:`), in file order. set_actors also appends a mover
  // per actor (named after it) to movers(), so they block like movers; call it after
  // set_movers.
  const std::vector<Actor>& actors() const { return actors_; }
  void set_actors(std::vector<Actor> actors);

  // The level, when the scene has one (null otherwise). Setting it builds its index.
  const Level* level() const { return level_.get(); }
  void set_level(std::shared_ptr<const Level> level);
  // Takes `other`'s level and its index (built once, shared by both scenes).
  void share_level(const Scene& other) {
    level_ = other.level_;
    triangles_ = other.triangles_;
  }
  const TriangleIndex& triangle_index() const { return *triangles_; }

  // A world that answers the geometry itself (sightline/world.h: a game's physics, through
  // the public API), or null. With one, SceneAtTime asks it every query at the frame's time
  // instead of the boxes and level (such a scene has neither), and adds the movers. Scene's
  // own static queries below do not ask it.
  const sightline::World* world() const { return world_.get(); }
  void set_world(std::shared_ptr<const sightline::World> world) { world_ = std::move(world); }
  // Mover i's path becomes a constant-velocity forecast from `position` at time t: the
  // public camera places the people a game reports each frame this way. Allocates nothing
  // once the path holds two keyframes.
  void place_mover(std::size_t i, const Eigen::Vector3d& position,
                   const Eigen::Vector3d& velocity, double t) {
    movers_[i].place(position, velocity, t);
  }

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
  // True when the segment from a to b touches no solid box and no level triangle (touching
  // a face blocks).
  bool line_of_sight(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return !solid_tree_.segment_blocked(a, b) && !triangles_->segment_blocked(a, b);
  }
  // The first solid surface along the segment from a to b (boxes and level triangles).
  std::optional<SurfaceHit> first_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // The same, from the scene's world at time t when it has one (world(): a world hit is
  // reported as a box, index 0), for the questions about walls rather than movers.
  std::optional<SurfaceHit> surface_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        double t) const;
  // Signed distance from p to the nearest solid surface (< 0 inside a box or inside the
  // level's solid volume). Distances of `limit` or more are reported as `limit` (infinity
  // with no geometry): a clearance test only needs to know whether something is nearer than
  // the camera's radius, and the limit prunes the search.
  double clearance(const Eigen::Vector3d& p,
                   double limit = std::numeric_limits<double>::infinity()) const;
  // The nearest surface closer than `limit` with the gradient of the signed distance, for
  // the clearance constraint's derivatives; nullopt when nothing is that close.
  std::optional<NearestSurface> nearest_surface(
      const Eigen::Vector3d& p, double limit = std::numeric_limits<double>::infinity()) const;
  // False inside the level's solid volume (inside a wall, outside the world: a Quake III
  // map's brushes) or inside a solid box; true elsewhere. Every camera position, cut
  // target and probe must be open.
  bool open_at(const Eigen::Vector3d& p) const;
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
  std::vector<Mover> movers_;
  std::vector<Actor> actors_;
  CharacterShape character_;
  Trajectory trajectory_;
  double frame_rate_;
  std::optional<Eigen::Vector3d> camera_start_;
  CameraProfile profile_;
  std::string profile_source_ = "preset thesis-default";
  BoxTree solid_tree_;
  BoxTree area_tree_;
  std::shared_ptr<const Level> level_;
  // Shared, so scenes stay copyable; never null (empty without a level).
  std::shared_ptr<const TriangleIndex> triangles_;
  std::shared_ptr<const sightline::World> world_;
  std::shared_ptr<const Shot> shot_;
  std::vector<std::shared_ptr<const Shot>> named_shots_;
  std::shared_ptr<const std::vector<ScriptEntry>> script_;
  bool has_character_ = true;
  std::string character_name_ = "character";
};

}  // namespace sightline::camera
