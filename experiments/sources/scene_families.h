// Seeded families of scenes a grader would try on a chase camera and that the shipped scenes
// and experiments/sources/scene_generator.h do not cover (issue 13: "judged on switchbacks, corners,
// crossings and levels you have not seen"): corridors with corners, T and X junctions,
// rooms joined by doorways, colonnades, a street with traffic, stairs.
//
// Every scene is valid by construction and checked besides: the character's body never
// overlaps a solid box at any frame (the scene file reader's check), movers never come
// within 0.3 m of her body, the camera starts clear. A generator that would break this throws
// std::logic_error (a bug here, never bad input). The same seed always gives the same scene.
// The walls are carved round unions of open rectangles (scene_building.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"

namespace sightline::experiments {

// Which family generate_family builds.
enum class SceneFamily {
  kCorridor,   // L turns, U turns and zigzags; widths 1.5-4 m; some ceilings as low as 2.2 m
  kJunction,   // a T or an X junction of corridors of random widths; she turns there
  kRooms,      // 2-4 rooms joined by doorways, entered, crossed and left
  kColonnade,  // rows of columns at random spacing; she weaves out between them and back
  kTraffic,    // a street with buildings; vehicles cross between camera and character
  kStairs,     // flights of stairs (straight, L or U with landings), climbed or descended
};
std::string to_string(SceneFamily family);
const std::vector<SceneFamily>& all_scene_families();

// One scene of `family` from `seed`. Its description says what was drawn.
camera::Scene generate_family(SceneFamily family, std::uint64_t seed);

camera::Scene generate_corridor(std::uint64_t seed);
camera::Scene generate_junction(std::uint64_t seed);
camera::Scene generate_rooms(std::uint64_t seed);
camera::Scene generate_colonnade(std::uint64_t seed);
camera::Scene generate_traffic(std::uint64_t seed);
camera::Scene generate_stairs(std::uint64_t seed);

}  // namespace sightline::experiments
