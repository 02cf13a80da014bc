// GridSolver (`grid`): exhaustive enumeration, the reference optimum for small problems.
//
// Every combination of the discrete domains' values, crossed with a lattice of `points`
// evenly spaced values per continuous dimension (both endpoints included; one point, the
// middle, when points = 1 or the interval is a single value). On an all-discrete problem a
// finished enumeration proves the optimum (StopReason::kProvenOptimal) and
// `solutions_at_best` counts exactly how many assignments reach it (92 for 8-queens); with
// continuous dimensions it is the optimum of the lattice only (kCompleted).
//
// Points are visited in odometer order (variable 0 turns fastest), so going from one point
// to the next changes one variable most of the time, and the score is kept by an
// IncrementalEvaluator: one step costs O(constraints touching the changed variables), which
// makes 8^8 = 16.7 million points of 8-queens a matter of a second or two. Candidates for
// the best are re-scored from scratch before they count, so floating-point drift of the
// incremental sums can neither make nor lose a tie, and the evaluator is re-synchronised
// every 2^16 points.
//
// Size guard: the solver refuses lattices above `max_points` rather than truncating them.
// unsuitable_reason() says so (with the size), and solve_into() on such a problem throws
// GridTooLarge with the same message: calling a solver on a problem it declared unsuitable
// is a caller's error, and a partial enumeration must never pass for an exhaustive one.
// The start assignment is not used (the enumeration covers it, or its lattice neighbours).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class GridTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class GridSolver : public Solver {
 public:
  struct Options {
    // Lattice points per continuous dimension, endpoints included (>= 1).
    std::int64_t points = 11;
    // Largest number of points (assignments) the solver agrees to enumerate.
    std::int64_t max_points = 100'000'000;

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  GridSolver(std::string name, Options options);
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;

  // Number of assignments the grid would visit (as a double: it may exceed 2^64).
  double lattice_size(const csp::Problem& problem) const;
  const Options& options() const { return options_; }

 private:
  // Number of values of variable `var` on the grid, and the index-th of them.
  std::size_t axis_size(const csp::Problem& problem, csp::VariableId var) const;
  static double axis_value(const csp::Domain& domain, std::size_t size, std::size_t index);

  std::string name_;
  Options options_;
  std::vector<std::size_t> sizes_;   // per variable, reused between solves
  std::vector<std::size_t> digits_;  // odometer position
};

}  // namespace sightline::solvers
