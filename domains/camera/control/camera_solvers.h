// The camera's own solvers, registered by name beside the generic ones.
//
// Solvers that need to know what a camera is (the octrees of Bourne and Ali) live in the
// camera domain and join the one registry here, so scenes, suites and the command line name
// them like any other ("occlusion-octree", "bourne-octree", "occlusion-octree>ceres-refine").
#pragma once

#include "sightline/solvers/registry.h"

namespace sightline::camera {

// The camera solver `follow`, the library and the suites use when none is named.
inline constexpr const char* kRecommendedCameraSolver = "occlusion-octree";

// Adds bourne-octree and occlusion-octree to `registry`; calling it again is harmless.
void register_camera_solvers(solvers::SolverRegistry& registry);
// The global registry with the camera's solvers in it.
solvers::SolverRegistry& solver_registry();

}  // namespace sightline::camera
