// Writing a Problem as toulbar2's .wcsp, so toulbar2 can solve what the project builds
// (a problem file's tables, a .wcsp read and re-written) and the two be compared.
//
// The problem must be discrete and made of `table` and `all_different` (zero offsets, and
// one domain shared by its variables, since salldiff compares value indices) constraints
// whose weighted costs are integers: .wcsp costs are integers and it has nothing else.
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
// cannot express (a continuous variable, another constraint kind, a non-integer cost).
void write_wcsp(const Problem& problem, std::ostream& out);

}  // namespace sightline::csp
