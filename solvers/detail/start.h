// Preparing a solver's start assignment, shared by the generic solvers.
//
// A start comes from a caller (the camera's current position, the previous stage of a
// pipeline, a user). A wrong length is a programming error and throws; a value outside its
// domain (a camera that drifted past a bound, a real value for an integer variable) is moved
// to the nearest member of the domain, so a solver always starts from a legal assignment.
#pragma once

#include <span>

#include "sightline/csp/problem.h"

namespace sightline::solvers::detail {

// Writes the start, clamped into the domains, into `out` (resized). Throws
// std::invalid_argument when start.size() != problem.num_variables().
void prepare_start(const csp::Problem& problem, std::span<const double> start,
                   csp::Assignment& out);

// True when both parts of the score are exactly zero or below (a zero-cost, feasible
// assignment: what `stop_at_zero` waits for).
inline bool is_zero(const csp::Score& s) { return s.hard <= 0 && s.soft <= 0; }

}  // namespace sightline::solvers::detail
