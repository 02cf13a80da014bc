// Seeded families of agile characters (issue 24): what players do that a walk does not --
// strafing (facing one way, moving another), running through corners at 6-8 m/s, backing
// up and turning on the spot, climbing onto ledges and dropping off them, orbiting a pillar,
// and moving about small rooms under low ceilings. A camera tuned on walks meets these in
// every game; each family draws its layout, speeds and facings from the seed.
//
// Valid by construction and checked like scene_families.h (the body never inside a solid
// box, the camera starting clear); the same seed gives the same scene.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"

namespace sightline::experiments {

enum class AgileFamily {
  kStrafe,      // among pillars, moving sideways, diagonally or straight, at 2.5-5 m/s
  kRun,         // a zigzag of 6-10 corridor legs, run at 6-8 m/s
  kReverse,     // in a corridor: forward, backing up facing forward, forward, a 180 on the spot
  kVertical,    // climbing onto a ledge and a platform, dropping 1.5-3 m off its edge
  kOrbit,       // one or two laps round a pillar, facing the way or facing the pillar
  kTightRooms,  // small rooms under 2.2-2.6 m ceilings, joined by narrow doorways
};
std::string to_string(AgileFamily family);
const std::vector<AgileFamily>& all_agile_families();

camera::Scene generate_agile(AgileFamily family, std::uint64_t seed);

}  // namespace sightline::experiments
