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

#include <span>
#include <utility>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::solvers::detail {

struct PermutationGroup {
  csp::ConstraintId constraint = 0;  // the all_different that makes it a group: swaps
                                     // inside the group never change its violation (0)
  // In scope order: the all_different's own scope (a view, not a copy: the Problem
  // outlives the search, and a million-variable group would copy 4 MB at every solve).
  std::span<const csp::VariableId> variables;
  std::vector<double> values;  // the common domain's values, ascending
  std::vector<std::pair<csp::VariableId, double>> pinned;  // variable, its only value

  // The variables not pinned, in scope order, and the values not pinned, ascending. With
  // no pins (the usual case) they are `variables` and `values` themselves, not copies.
  std::span<const csp::VariableId> free_variables() const {
    return pinned.empty() ? variables : std::span<const csp::VariableId>(unpinned_variables);
  }
  std::span<const double> free_values() const {
    return pinned.empty() ? std::span<const double>(values)
                          : std::span<const double>(unpinned_values);
  }

  // Filled only when something is pinned (find_permutation_groups).
  std::vector<csp::VariableId> unpinned_variables;
  std::vector<double> unpinned_values;
};

std::vector<PermutationGroup> find_permutation_groups(const csp::Problem& problem);

}  // namespace sightline::solvers::detail
