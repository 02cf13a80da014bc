// Writing a Problem as toulbar2's .wcsp, so toulbar2 can solve what the project builds
// (a problem file's tables, a .wcsp read and re-written) and the two be compared.
//
// The problem must be discrete, and .wcsp costs are integers: by default every weighted cost
// must be one; with WcspWriteOptions::max_decimals > 0 fractional costs are written
// multiplied by 10^d, d the fewest decimal places that hold every weighted cost exactly
// (decimal_costs.h), so a solver reading the file finds the same optima (the toulbar2
// solver divides the costs it reports by the returned scale).
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
// assignments and the same soft costs (times the scale).
#pragma once

#include <ostream>

#include "sightline/csp/problem.h"

namespace sightline::csp {

struct WcspWriteOptions {
  // Decimal places a weighted cost may have (0 .. kMaxCostDecimals of decimal_costs.h): 0
  // writes integer costs only; more scales every cost by the fewest power of ten that makes
  // each an integer.
  int max_decimals = 0;
};

// Writes `problem` in .wcsp format and returns the factor every weighted cost was multiplied
// by (1 when they are integers). Throws std::invalid_argument naming the first thing it
// cannot express (a continuous variable, a cost with more decimal places than allowed, a
// table too large), by the constraint's name (Problem::constraint_name).
double write_wcsp(const Problem& problem, std::ostream& out, const WcspWriteOptions& options = {});

}  // namespace sightline::csp
