// Generated scenes: random pillar forests and city blocks, for benchmarks at any box count
// and for testing the camera on worlds nobody tuned it for; random switchbacks and random
// crossings by movers (issue 13), for testing a camera that must see occlusions coming.
//
// Every generated scene is valid by construction: boxes never overlap the character's path
// (a margin is kept around every segment), the camera starts in the clear, movers' paths are
// finite, and the same seed always gives the same scene.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sightline/domains/camera/scene.h"

namespace sightline::experiments {

struct GeneratedSceneOptions {
  std::uint64_t seed = 1;
  std::size_t boxes = 100;       // how many solid boxes
  double area_per_box = 30;      // m^2 of ground per box: sets the world's size
  double walk_seconds = 20;      // length of the character's walk
  double walk_speed = 1.4;       // m/s
};

// Pillars and short wall pieces of random size scattered over a square; the character
// wanders between them along random waypoints.
camera::Scene generate_pillar_forest(const GeneratedSceneOptions& options);
// Buildings on a grid of blocks separated by streets; some buildings have overhanging
// upper floors and some streets covered passages. The character walks the streets, turning
// at crossings.
camera::Scene generate_city(const GeneratedSceneOptions& options);

struct SwitchbackOptions {
  std::uint64_t seed = 1;
  int min_lanes = 3, max_lanes = 7;              // lanes walked; one U-turn between each two
  double min_lane_width = 2.2, max_lane_width = 4.5;  // metres, each lane drawn on its own
  double min_length = 10, max_length = 30;       // metres, the lanes' length (one per scene)
  double min_wall_height = 2.5, max_wall_height = 4;  // metres, one per scene
  double walk_speed = 1.3;                       // m/s
};

// A switchback: parallel walls along x, lanes between them of random widths, a gap of random
// width (1.6-3.5 m) at alternate ends of each inner wall, an outer wall all round; the
// character walks up the lanes, a U-turn through each gap.
camera::Scene generate_switchback(const SwitchbackOptions& options);

struct CrossingOptions {
  std::uint64_t seed = 1;
  std::size_t movers = 10;       // how many movers cross
  std::size_t pillars = 12;      // static pillars scattered away from the walk (>= 1 m)
  double walk_seconds = 25;      // length of the character's walk
  double walk_speed = 1.4;       // m/s
  double vehicle_fraction = 0.2; // of the movers, the share that are vehicles (4-12 m/s)
  double camera_distance = 4;    // metres behind the character the crossings aim at
};

// Open ground, a few pillars, the character wandering between random waypoints; movers (people
// at 0.8-2 m/s, vehicles at 4-12 m/s) cross at random times and angles. Two in three cross the
// line from the character to the point `camera_distance` behind her (where a chase camera is)
// at a random fraction of it, at the moment they are there; the rest cross her path ahead of
// her, a few seconds after or before she passes that point. Each mover walks a straight line
// 8-14 m either side of its crossing point (a vehicle half its length more) and stands still
// before and after, 1.5 m or more from her walk, its way missing the pillars (redrawn until
// it does, at most 50 times).
camera::Scene generate_crossings(const CrossingOptions& options);

}  // namespace sightline::experiments
