// Level walks: characters' paths on a real level, made the way a person walks them.
//
// `sightline level walk` (apps/level_command.cc) builds a navigation mesh of the level with
// Recast for a person (WalkOptions: radius, height, step, slope ...), keeps its largest
// connected region, picks far-apart goals on it, plans between them with Detour, and turns
// each path into keyframes: walking speeds of 1.5-4 m/s, turning at corners, now and then a
// stop and a turn on the spot, 40-120 s per walk, every keyframe on the floor. The same
// seed gives the same walks. Scene files are written by walk_scene_yaml().
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "domains/camera/geometry/triangle_mesh.h"
#include "domains/camera/trajectory.h"

namespace sightline::experiments {

struct WalkOptions {
  // The person (Recast's agent). Step 0.56 m is Quake III's 18 units: its stairs' risers
  // are up to 16-18 units, and a smaller step leaves them unconnected.
  double agent_radius = 0.3;       // metres
  double agent_height = 1.8;       // metres
  double agent_step = 0.56;        // metres: the highest ledge walked up
  double max_slope_degrees = 45;   // steeper floors are not walkable
  double cell_size = 0.15;         // metres: Recast's voxel size across
  double cell_height = 0.1;        // metres: and up
  // The walk.
  double min_speed = 1.5, max_speed = 4.0;        // m/s, drawn per leg
  double min_seconds = 40, max_seconds = 120;     // per walk, drawn
  double stop_probability = 0.15;  // per corner: stop and turn on the spot
  double turn_rate_degrees = 360;  // deg/s when turning on the spot or at a corner
  int walks = 1;
  std::uint64_t seed = 1;
  // Empty when usable, else which field is wrong and why.
  std::string validate() const;
};

struct LevelWalk {
  std::vector<camera::Keyframe> keyframes;  // feet on the floor, times from 0
  double length_metres = 0;                 // along the path
};

class WalkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `options.walks` walks on `mesh` (metres, y up). Throws WalkError when the level has no
// walkable region big enough for a walk (the message says what was found).
std::vector<LevelWalk> generate_walks(const camera::TriangleMesh& mesh, const WalkOptions& options);

// A scene file (FORMATS.md) for one walk: `name`, a description, the `level:` block naming
// `level_file` (as it should appear in the file) and `map`, and the keyframes.
std::string walk_scene_yaml(const std::string& name, const std::string& description,
                            const std::string& level_file, const std::string& map,
                            const LevelWalk& walk);

}  // namespace sightline::experiments
