// The composition solvers, registered by name beside the generic ones and the camera's
// octrees: `shot-search` (shot_search.h), the one `compose` uses by default; `toric`
// (toric_framing.h), exact two-subject framing; `particle-swarm` (particle_swarm.h), the
// literature's baseline. Every other
// solver of the registry composes shots too: a shot is a csp::Problem
// (composition_problem.h).
#pragma once

#include "sightline/solvers/registry.h"

namespace sightline::camera {

inline constexpr const char* kRecommendedCompositionSolver = "shot-search";

// Adds the composition solvers to `registry`; calling it again is harmless.
void register_composition_solvers(solvers::SolverRegistry& registry);

}  // namespace sightline::camera
