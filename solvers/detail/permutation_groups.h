// Permutation structure in a discrete problem, found generically for local search.
//
// A hard all_different with zero offsets over k variables whose domains are all the same k
// values forces those variables to be a permutation of the values. Local search can then
// start from a permutation and move by swapping two variables' values: every swap keeps the
// all_different satisfied, so the search never wastes moves on it. This is the structural
// neighbourhood of Sosic & Gu's N-queens solvers, found here from the constraints alone:
// nothing queen-specific. Soft all_differents are left alone (their optimum need not be a
// permutation), and a variable belongs to at most one group (the first found).
#pragma once

#include <vector>

#include "csp/problem.h"

namespace sightline::solvers::detail {

struct PermutationGroup {
  std::vector<csp::VariableId> variables;  // in scope order
  std::vector<double> values;              // the common domain's values, ascending
};

std::vector<PermutationGroup> find_permutation_groups(const csp::Problem& problem);

}  // namespace sightline::solvers::detail
