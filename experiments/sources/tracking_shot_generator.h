// Generated tracking shots: people moving through a place and a shot: block that keeps them
// framed and visible (FORMATS.md "Shots"), for judging a tracking camera on shots nobody
// tuned it for. Each seed draws one of four layouts, turned to one of four directions:
//   0 a pair walking along a street (side by side, or one behind the other as seen from
//     the street), past a row of columns and a wall, with a vehicle passing on the street
//     side, sometimes starting from rest once the shot is under way; a two-shot from the
//     street side;
//   1 one chasing another round the corner of a building (an L-shaped run); a two-shot;
//   2 three or four people crossing a square, each their own way, among a fountain,
//     kiosks and lamps; a group shot;
//   3 one circling another who turns to keep facing them, among pillars; an
//     over-the-shoulder shot.
// Obstacles never touch a path; the scene is written as YAML text and read by the scene
// reader, so it is valid by the same rules as any scene file.
#pragma once

#include <cstdint>
#include <string>

#include "sightline/domains/camera/scene.h"

namespace sightline::experiments {

struct TrackingShotOptions {
  std::uint64_t seed = 1;
  double seconds = 12;  // the shot's length
  int layout = -1;      // 0 street, 1 corner chase, 2 crossing, 3 circling; -1: by seed
};

std::string tracking_shot_yaml(const TrackingShotOptions& options);
camera::Scene generate_tracking_shot(const TrackingShotOptions& options);

}  // namespace sightline::experiments
