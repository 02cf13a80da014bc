// Permutation structure in a discrete problem, found generically for local search.
//
// A hard all_different with zero offsets over k variables whose domains are all the same k
// values forces those variables to be a permutation of the values. Local search can then
// start from a permutation and move by swapping two variables' values: every swap keeps the
// all_different satisfied, so the search never wastes moves on it. This is the structural
// neighbourhood of Sosic & Gu's N-queens solvers, found here from the constraints alone:
// nothing queen-specific. Soft all_differents are left alone (their optimum need not be a
// permutation), and a variable belongs to at most one group (the first found).
//
// Pinned variables: hard unary constraints (a clue, a fixed cell) may allow a group variable
// one value only. Such a variable is pinned: starts put it at that value and swaps leave it
// there, so the search permutes only the group's free variables over the free values (node
// consistency, done once). Pins are kept only when consistent (no value pinned twice);
// otherwise the group has none and the search sorts the clash out by itself.
#pragma once

#include <utility>
#include <vector>

#include "csp/problem.h"

namespace sightline::solvers::detail {

struct PermutationGroup {
  csp::ConstraintId constraint = 0;        // the all_different that makes it a group: swaps
                                           // inside the group never change its violation (0)
  std::vector<csp::VariableId> variables;  // in scope order
  std::vector<double> values;              // the common domain's values, ascending
  std::vector<csp::VariableId> free;       // the variables not pinned, in scope order
  std::vector<double> free_values;         // the values not pinned, ascending
  std::vector<std::pair<csp::VariableId, double>> pinned;  // variable, its only value
};

std::vector<PermutationGroup> find_permutation_groups(const csp::Problem& problem);

}  // namespace sightline::solvers::detail
