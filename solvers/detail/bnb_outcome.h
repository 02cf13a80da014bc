// How a branch and bound search ended, in the result: the stop reason and the start of the
// message, the same for the forward-checking search (bnb_search) and the one with soft arc
// consistency (bnb_soft_search), which each append their own counts.
#pragma once

#include <cstdint>
#include <sstream>

#include "sightline/solvers/solver.h"

namespace sightline::solvers::detail {

// Sets result.stop and writes "proved optimal" / "best found, not proved optimal" / ...
// (and the optimal count when counting) into `message`.
inline void describe_bnb_outcome(bool stopped, bool have_incumbent, bool count_mode,
                                 std::uint64_t optimal_count, const Budget& budget,
                                 SolverResult& result, std::ostringstream& message) {
  if (stopped) {
    result.stop = budget.reason();
    message << (have_incumbent ? "best found, not proved optimal"
                               : "no feasible assignment found before the limit");
  } else if (have_incumbent) {
    result.stop = StopReason::kProvenOptimal;
    message << "proved optimal";
  } else {
    result.stop = StopReason::kCompleted;
    message << "proved infeasible: no assignment satisfies every hard constraint";
  }
  if (count_mode && have_incumbent) {
    message << "; " << optimal_count << " optimal assignment" << (optimal_count == 1 ? "" : "s")
            << (stopped ? " found so far" : "");
  }
}

}  // namespace sightline::solvers::detail
