// Writing a Problem for other tools and back to this project's files, every constraint as a
// cost table (expanded_table.h: its violation asked of the constraint for each tuple), so
// any kind goes, exactly:
//  - write_cfn: toulbar2's JSON cost-function network (cfn_reader.h): variables with their
//    values named by the numbers they are, one dense cost list per constraint (the scope's
//    tuples in lexicographic order, the last variable fastest), weighted costs in decimal,
//    hard tuples at the upper bound "mustbe": "<UB" (1 + the largest total soft cost);
//  - write_problem_yaml: this project's problem file (docs/PROBLEM_FORMAT.md): each
//    variable with its domain (int, values or real), each constraint a `table` with its
//    weight, hard flag and label: a table's own tuples, any other kind's tuples of non-zero
//    violation (default 0). Read back, it gives the same score to every assignment.
// Both need discrete domains under every constraint (continuous variables outside any
// constraint are written as they are in YAML; .cfn has none) and at most kMaxExpandedTuples
// tuples per expanded constraint; otherwise std::invalid_argument names what is in the way.
#pragma once

#include <ostream>

#include "sightline/csp/problem.h"

namespace sightline::csp {

void write_cfn(const Problem& problem, std::ostream& out);
void write_problem_yaml(const Problem& problem, std::ostream& out);

}  // namespace sightline::csp
