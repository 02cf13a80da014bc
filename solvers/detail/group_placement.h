// Constructive start for a permutation group: Sosic & Gu's placement, stated generically.
//
// The group's free variables are retracted from the evaluator (they stop counting) and then
// placed back one at a time, in scope order. Variable k draws a random value among those not
// yet dealt out; if placing it there makes no constraint worse given the variables already
// placed (hard or soft), it takes it, otherwise it draws again. After `attempts_per_variable` x k
// draws in all, the variables still waiting take the values left, in the order they are, and local
// search repairs what remains. On N-queens this is QS4's placement phase (judged against the
// queens already placed only, which is what makes most draws succeed: about 43% of them,
// where a check against the whole board succeeds about e^-2 of the time), but nothing here
// knows about queens: it needs only constraints whose incremental states support partial
// assignments (all_different does; see IncrementalState).
//
// The evaluator's score is partial until place_group returns; callers must not record it.
#pragma once

#include <cstdint>
#include <vector>

#include "sightline/csp/incremental_evaluator.h"
#include "sightline/solvers/detail/permutation_groups.h"
#include "sightline/solvers/detail/random.h"

namespace sightline::solvers::detail {

// True when every free variable of `group` can be retracted (see IncrementalEvaluator).
bool can_place_group(const csp::IncrementalEvaluator& evaluator, const PermutationGroup& group);

struct PlacementReport {
  std::uint64_t draws = 0;    // values tried (each one place_is_free)
  std::size_t placed = 0;     // variables that found a value making nothing worse
  std::size_t left_over = 0;  // variables that took what was left
};

// Re-deals the values the group's free variables hold now (a permutation of the free
// values) as described above. `pool` is scratch, kept by the caller between calls.
PlacementReport place_group(csp::IncrementalEvaluator& evaluator, const PermutationGroup& group,
                            double attempts_per_variable, Random& random,
                            std::vector<double>& pool);

}  // namespace sightline::solvers::detail
