// Writing a Problem as toulbar2's .wcsp, so toulbar2 can solve what the project builds
// (a problem file's tables, a .wcsp read and re-written) and the two be compared.
//
// The problem must be discrete with integer weighted costs (.wcsp costs are integers).
// `table` constraints are written as their tables, `all_different` (zero offsets, one domain
// shared by its variables, since salldiff compares value indices) as salldiff, and every
// other constraint (not_equal, linear, abs_deviation, expression, any registered kind) as
// the cost table of its scope's domains, its violation asked of the constraint itself for
// each tuple (at most 1,000,000 tuples per constraint; more is refused naming it).
// Values are written as their index in the variable's domain, in domain order. The upper
// bound is 1 + the largest total soft cost (the sum over soft constraints of their largest
// weighted cost), so no soft cost is mistaken for "forbidden"; hard constraints write their
// positive-violation tuples (or, for all_different, their per-violation cost) at that
// bound. Reading the result back with read_wcsp_file gives a problem with the same feasible
// assignments and the same soft costs.
#pragma once

#include <ostream>

#include "sightline/csp/problem.h"

namespace sightline::csp {

// Writes `problem` in .wcsp format. Throws std::invalid_argument naming the first thing it
// cannot express (a continuous variable, a non-integer cost, a table too large).
void write_wcsp(const Problem& problem, std::ostream& out);

}  // namespace sightline::csp
