// Generated scenes: random pillar forests and city blocks, for benchmarks at any box count
// and for testing the camera on worlds nobody tuned it for.
//
// Every generated scene is valid by construction: boxes never overlap the character's path
// (a margin is kept around every segment), the camera starts in the clear, and the same
// seed always gives the same scene.
#pragma once

#include <cstddef>
#include <cstdint>

#include "domains/camera/scene.h"

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

}  // namespace sightline::experiments
