// The solvers of solvers/, registered by name. One line per solver.
#include "solvers/registry.h"

namespace sightline::solvers {

void register_builtin_solvers(SolverRegistry& registry) {
  (void)registry;
}

}  // namespace sightline::solvers
