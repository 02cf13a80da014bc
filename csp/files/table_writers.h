// Writing a Problem for other tools and back to this project's files, every constraint as a
// cost table (expanded_table.h: its violation asked of the constraint for each tuple), so
// any kind goes, exactly:
//  - write_cfn: toulbar2's JSON cost-function network (cfn_reader.h; toulbar2's "CFN
//    format"), as toulbar2 itself reads it: names are identifiers (not starting with a
//    digit or one of "-.+", without spaces or "/#[]{}:,"), so the problem and a variable keep
//    their names when they are ones (else "problem", x<id>) and a value is named by its label
//    where the problem file gives labels, else v<value> (v0, v-1, v0.5); one dense cost list
//    per constraint (the scope's
//    tuples in lexicographic order, the last variable fastest); costs in fixed decimals with
//    the fewest places that hold every weighted cost exactly (decimal_costs.h: toulbar2
//    takes its precision from the upper bound's places, so the bound is written with as
//    many), hard tuples at the upper bound "mustbe": "<UB" (1 + the largest total soft cost);
//  - write_problem_yaml: this project's problem file (docs/PROBLEM_FORMAT.md): each
//    variable with its domain (int, values or real), each constraint a `table` with its
//    weight, hard flag and label: a table's own tuples, any other kind's tuples of non-zero
//    violation (default 0). Read back, it gives the same score to every assignment.
// Both need discrete domains under every constraint (continuous variables outside any
// constraint are written as they are in YAML; .cfn has none) and at most kMaxExpandedTuples
// tuples per expanded constraint; .cfn also costs of at most kMaxCostDecimals places;
// otherwise std::invalid_argument names what is in the way.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::csp {

// `value_labels[v]` names variable v's values as LoadedProblem::value_labels does (may be
// empty, or shorter than the variables).
void write_cfn(const Problem& problem, std::ostream& out,
               const std::vector<std::vector<std::string>>& value_labels = {});
void write_problem_yaml(const Problem& problem, std::ostream& out);

}  // namespace sightline::csp
