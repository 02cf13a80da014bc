// Level walks: characters' paths on a real level, made the way a person walks them.
//
// `sightline level walk` (apps/level_command.cc) builds a navigation mesh of the level with
// Recast for a person (WalkOptions: radius, height, step, slope ...; navigation_mesh.h),
// keeps one connected region of it (the one holding a game map's spawn points, else the
// largest), picks far-apart goals on it, plans between them with Detour, and turns each
// route into keyframes: walking speeds of 1.5-4 m/s, slowing and turning at corners, now
// and then a stop and a turn on the spot, 40-120 s per walk. The navigation mesh is only
// Recast's voxel picture of the level, so every keyframe is put on the level's own floor
// (a ray down into its triangles, floor_probe.h), with the person's headroom, and keyframes
// are added where the floor changes height (stairs, ramps) until no leg passes through a
// surface at knee, waist, chest or head height. A level's triangles can miss solid matter
// (a Quake III brush drawn with a non-solid surface, e.g. oa_thor's pipe-faced slabs): when
// the level knows its solid volume, a route whose person would be inside it (first_in_solid)
// is refused like one that leaves the floor, and another goal is walked to. The same seed
// gives the same walks (and, where no route meets solid matter, the same walks as without
// the check). Scene files are written by walk_scene_yaml().
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sightline/domains/camera/geometry/solid_volume.h"
#include "sightline/domains/camera/geometry/triangle_mesh.h"
#include "sightline/domains/camera/level/level_transform.h"
#include "sightline/domains/camera/trajectory.h"

namespace sightline::experiments {

struct WalkOptions {
  // The person (Recast's agent). Step 0.56 m is Quake III's 18 units: its stairs' risers
  // are up to 16-18 units, and a smaller step leaves them unconnected.
  double agent_radius = 0.3;      // metres
  double agent_height = 1.8;      // metres
  double agent_step = 0.56;       // metres: the highest ledge walked up
  double max_slope_degrees = 45;  // steeper floors are not walkable
  double cell_size = 0.15;        // metres: Recast's voxel size across
  // Metres up. Recast counts the step in whole cells (floor(step / cell_height)) and puts a
  // floor's top at the cell above it, so a riser can read one cell taller than it is: at
  // 0.05 the step counts 11 cells (0.55 m) and Quake III's 16-unit (0.5 m) risers always
  // connect; at 0.1 it would count 5 cells and those risers would read 5 or 6.
  double cell_height = 0.05;
  // The walk.
  double min_speed = 1.5, max_speed = 4.0;     // m/s, drawn per route from goal to goal
  double min_seconds = 40, max_seconds = 120;  // per walk, drawn
  double stop_probability = 0.15;              // per corner: stop and turn on the spot
  double turn_rate_degrees = 360;              // deg/s when turning on the spot or at a corner
  int walks = 1;
  std::uint64_t seed = 1;
  // Empty when usable, else which field is wrong and why.
  std::string validate() const;
};

struct LevelWalk {
  std::vector<camera::Keyframe> keyframes;  // feet on the floor, times from 0
  double length_metres = 0;                 // along the path
  int stops = 0;                            // stops with a turn on the spot
};

// The navigation mesh the walks were planned on (navigation_mesh.h).
struct NavigationMeshStats {
  int grid_width = 0, grid_depth = 0;   // Recast's cells across x and z
  double cell_size = 0;                 // metres across (raised from the options on a big level)
  double cell_height = 0;               // metres up
  int polygons = 0;                     // all walkable polygons
  int region_polygons = 0;              // polygons of the connected region walked
  int anchors = 0, region_anchors = 0;  // anchors given, and on the region walked
  double walkable_area = 0;             // m^2, all polygons (seen from above)
  double region_area = 0;               // m^2, the connected region walked
  double build_seconds = 0;             // Recast and Detour, wall clock
  std::string note;                     // what was adjusted and why (empty if nothing)
};

struct LevelWalks {
  std::vector<LevelWalk> walks;
  NavigationMeshStats navigation;
  double seconds = 0;  // everything, wall clock
};

class WalkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `options.walks` walks on `mesh` (metres, y up), on the connected walkable region holding
// most of `anchors` (where people are known to stand, e.g. quake3_spawn_points()), or the
// largest one when there are none. Throws WalkError when the level has no walkable region
// big enough for a walk (the message says what was found), std::invalid_argument when
// options.validate() fails. With `solid` (the level's solid volume, Level::solid; null when
// it has none) no walk puts the person inside it (first_in_solid).
LevelWalks generate_walks(const camera::TriangleMesh& mesh, const WalkOptions& options,
                          const std::vector<Eigen::Vector3d>& anchors = {},
                          const camera::SolidVolume* solid = nullptr);

// The person walking through the feet positions `feet` (metres, y up), looked at every
// 0.1 m along each straight leg at knee (0.5 m) and chest (1.3 m) height above the feet:
// the first leg (i: from feet[i] to feet[i + 1]; 0 for a single position) where a sample is
// solid, or nullopt when none is.
std::optional<std::size_t> first_in_solid(const std::vector<Eigen::Vector3d>& feet,
                                          const camera::SolidVolume& solid);

// A scene file (FORMATS.md) for one walk: `name`, a description, the `level:` block naming
// `level_file` (as it should appear in the file), `map` (omitted when empty), `scale` and
// `up` (omitted when absent: the format's defaults), and the keyframes (6 decimals).
std::string walk_scene_yaml(const std::string& name, const std::string& description,
                            const std::string& level_file, const std::string& map,
                            const LevelWalk& walk, std::optional<double> scale = std::nullopt,
                            std::optional<camera::UpAxis> up = std::nullopt);

}  // namespace sightline::experiments
