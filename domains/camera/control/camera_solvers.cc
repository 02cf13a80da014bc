#include "sightline/domains/camera/control/camera_solvers.h"

#include "sightline/domains/camera/control/bourne_octree.h"
#include "sightline/domains/camera/control/occlusion_octree.h"

namespace sightline::camera {

void register_camera_solvers(solvers::SolverRegistry& registry) {
  if (!registry.contains("bourne-octree")) {
    solvers::register_solver<BourneOctreeSolver>(
        registry, "bourne-octree",
        "Bourne & Sattar's sliding octree for the camera: four-ray nominal occlusion (table 8)");
  }
  if (!registry.contains("occlusion-octree")) {
    solvers::register_solver<OcclusionOctreeSolver>(
        registry, "occlusion-octree",
        "Ali's occlusion-aware sliding octree: visible candidates only, orientation sweep, "
        "front/back probes (table 9)");
  }
}

solvers::SolverRegistry& solver_registry() {
  static solvers::SolverRegistry& registry = [] () -> solvers::SolverRegistry& {
    auto& r = solvers::SolverRegistry::global();
    register_camera_solvers(r);
    return r;
  }();
  return registry;
}

}  // namespace sightline::camera
