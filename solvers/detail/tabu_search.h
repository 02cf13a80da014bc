// The search loop behind TabuSolver (solvers/tabu.h says what it does and why; this is how).
#pragma once

#include <cstdint>
#include <span>

#include "sightline/solvers/tabu.h"

namespace sightline::solvers::detail {

// Fills result.best, evaluations, iterations, stop and message. `unlimited`: the caller set
// no limit at all, so perturbations need a cap of their own (see TabuSolver).
void run_tabu_search(const csp::Problem& problem, std::span<const double> start,
                     const TabuSolver::Options& options, std::uint64_t seed, bool unlimited,
                     Budget& budget, SolverResult& result);

}  // namespace sightline::solvers::detail
