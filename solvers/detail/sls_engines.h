// The two search loops behind SlsSolver (see solvers/sls.h for what they do and why):
// min-conflicts with swaps for discrete problems, random-neighbourhood search for continuous
// and mixed ones. Each fills result.best, evaluations, iterations, stop and message; the
// caller scores the result (finish_result), except that run_discrete_sls returns the full
// evaluation of result.best (score, and breakdown when `keep_breakdown`) when it has made it
// from scratch already (it stopped at zero cost).
// `restart_cap` is SlsSolver::restart_cap (0 = restart until a limit stops the search); each
// notes its best on the budget (time to best).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sightline/solvers/sls.h"

namespace sightline::solvers::detail {

std::optional<FullEvaluation> run_discrete_sls(const csp::Problem& problem,
                                               std::span<const double> start,
                                               const SlsSolver::Options& options,
                                               std::uint64_t restart_cap, std::uint64_t seed,
                                               Budget& budget, SolverResult& result,
                                               bool keep_breakdown);

// `current` and `candidate` are scratch buffers kept by the caller between solves.
void run_continuous_sls(const csp::Problem& problem, std::span<const double> start,
                        const SlsSolver::Options& options, std::uint64_t restart_cap,
                        std::uint64_t seed, Budget& budget,
                        SolverResult& result, std::vector<double>& current,
                        std::vector<double>& candidate);

}  // namespace sightline::solvers::detail
