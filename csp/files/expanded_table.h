// A constraint over finite domains as the violation of every tuple of its scope's domains:
// how the file writers (wcsp_writer.h, table_writers.h) write any kind as a cost table, by
// asking the constraint itself.
#pragma once

#include <cstddef>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::csp {

// Tables larger than this are refused rather than written.
inline constexpr std::size_t kMaxExpandedTuples = 1'000'000;

// The violation of every tuple of the scope's domains, in odometer order (the last variable
// of the scope fastest), the rest of the assignment at the domains' first values. Throws
// std::invalid_argument naming the constraint (Problem::constraint_name) and `format`
// (".wcsp") for a continuous variable in the scope or more than kMaxExpandedTuples tuples.
std::vector<double> expand_violations(const Problem& problem, ConstraintId id, const char* format);

}  // namespace sightline::csp
