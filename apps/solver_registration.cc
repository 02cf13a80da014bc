#include "apps/solver_registration.h"

#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/solvers/toulbar2/toulbar2_solver.h"

namespace sightline::apps {

void register_all_solvers() {
  static const bool registered = [] {
    solvers::SolverRegistry& registry = solvers::SolverRegistry::global();
    camera::solver_registry();  // registers the camera's solvers into the global registry
    camera::register_composition_solvers(registry);
    // toulbar2 joins when its program is installed (solvers/toulbar2/toulbar2_solver.h).
    solvers::register_toulbar2_solver(registry);
    return true;
  }();
  (void)registered;
}

}  // namespace sightline::apps
