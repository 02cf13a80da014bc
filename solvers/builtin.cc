// The solvers of solvers/, registered by name. One line per solver.
#include "sightline/solvers/registry.h"
#include "sightline/solvers/bnb.h"
#include "sightline/solvers/ceres_refine.h"
#include "sightline/solvers/chain.h"
#include "sightline/solvers/grid.h"
#include "sightline/solvers/lns.h"
#include "sightline/solvers/sliding_octree.h"
#include "sightline/solvers/sls.h"
#include "sightline/solvers/tabu.h"

namespace sightline::solvers {

void register_builtin_solvers(SolverRegistry& registry) {
  (void)registry;
  register_solver<GridSolver>(registry, "grid",
      "exhaustive: all discrete combinations x a lattice per continuous dimension");
  register_solver<SlsSolver>(registry, "sls",
      "local search: min-conflicts, tabu, swaps, restarts; Gaussian moves if continuous");
  register_solver<SlidingOctreeSolver>(registry, "sliding-octree",
      "Bourne's Sliding Octree Solver on a continuous box (2^d children per pass)");
  register_solver<BranchAndBoundSolver>(registry, "bnb",
      "exact depth-first branch and bound with forward checking (discrete); proves optimality");
  register_solver<CeresRefineSolver>(registry, "ceres-refine",
      "Ceres L-BFGS refinement of the continuous variables; never worse than its start");
  register_solver<TabuSolver>(registry, "tabu",
      "tabu search on exact weighted deltas, move table kept incrementally (discrete); anytime");
  register_solver<LnsSolver>(registry, "lns",
      "large-neighbourhood search: neighbourhoods along the constraint graph solved by bnb");
  register_solver<ChainSolver>(registry, "chain",
      "exact dynamic programming over a sequence (unary, consecutive pairs, stretch); optimal");
}

}  // namespace sightline::solvers
