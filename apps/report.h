// Printing what a solve produced: the one-line brief report, a summary of the per-constraint
// breakdown, and the solution file.
//
// The solution file follows toulbar2's `-w` convention so the two tools can be compared
// value for value: every variable's value in variable order, separated by spaces, a discrete
// value written as its index (from 0) in its domain, a continuous one as the number itself.
#pragma once

#include <ostream>
#include <span>
#include <string>

#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/problem.h"
#include "sightline/solvers/solver.h"

namespace sightline::apps {

// "australia: 7 variables (7 discrete, 0 continuous), 9 constraints (0 hard, 9 soft)".
std::string describe_problem(const csp::Problem& problem);

// Refuses (solvers::OptionError naming `what`) a solver unsuitable for `problem`; otherwise
// solves from the default assignment, checks the answer lies in the domains and prints it
// with print_result. The one way every solving command runs a solver.
solvers::SolverResult solve_and_print(std::ostream& out, const csp::Problem& problem,
                                      solvers::Solver& solver,
                                      const solvers::SolveContext& context,
                                      const std::string& what);

// The brief report, then "violated constraints: V of C (H hard, S soft)" and the `top`
// costliest violated ones with their labels.
void print_result(std::ostream& out, const csp::Problem& problem,
                  const solvers::SolverResult& result, const std::string& solver_name,
                  std::size_t top = 5);

// Writes `values` in the format above to `path` ("-" = `out`). Throws std::runtime_error
// when the file cannot be written, std::invalid_argument when a discrete value is not in its
// domain (a solver bug, never a user's).
// The same solve without printing (for --format json).
solvers::SolverResult solve_quietly(const csp::Problem& problem, solvers::Solver& solver,
                                    const solvers::SolveContext& context);
// A result as one JSON object: problem, solver, feasible, cost, hard, stop, message, times,
// evaluations, the assignment by variable name (a value's label where the file gives one)
// and the violated constraints by name.
std::string result_json(const csp::LoadedProblem& model, const std::string& solver,
                        const solvers::SolverResult& result);

void write_solution(const std::string& path, const csp::Problem& problem,
                    std::span<const double> values, std::ostream& out);

}  // namespace sightline::apps
