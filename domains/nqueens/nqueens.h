// N-queens as a weighted CSP: the classic toy domain, and the scale test of local search.
//
// One variable per column, q_i in 0..n-1 = the row of the queen in column i, so two queens
// never share a column by construction. Three hard AllDifferent constraints forbid the rest:
//   rows:           q_i       all different   (offsets 0)
//   diagonals:      q_i + i   all different   (offsets +i)
//   anti-diagonals: q_i - i   all different   (offsets -i)
// With the default "var" measure the hard violation of an assignment is the number of queens
// that would have to move to clear each line. Built through the public csp API only, so it
// exercises exactly what a user's problem would.
#pragma once

#include <cstddef>
#include <memory>
#include <span>

#include "sightline/csp/problem.h"

namespace sightline::nqueens {

// The n-queens problem (n >= 1); variables q0..q{n-1}; constraints in the order rows,
// diagonals, anti-diagonals. Throws std::invalid_argument for n == 0.
std::unique_ptr<csp::Problem> build_nqueens(std::size_t n);

// Number of pairs of queens attacking each other (same row or same diagonal), counted
// independently of the constraints above; rows[i] is the row of the queen in column i.
// O(n) with line counts. 0 means a solution.
std::size_t attacking_pairs(std::span<const double> rows);

}  // namespace sightline::nqueens
