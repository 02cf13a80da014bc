// The options every solving command shares (solve, nqueens, colour, and later follow):
// which solver, its settings, the seed and the limits, and where to write the solution.
//
// add_solve_options() declares them on a CLI11 subcommand; make_solver() and make_context()
// turn them into a registry-created solver and a SolveContext. Keeping them here means every
// command spells them the same way and validates them the same way (a NaN or negative time
// limit is refused, an unknown solver or option lists the valid ones).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sightline/solvers/registry.h"
#include "sightline/solvers/solver.h"

namespace sightline::apps {

struct SolveOptions {
  std::string solver;                 // registered name or pipeline "a>b"
  std::vector<std::string> settings;  // "key=value" solver options
  std::uint64_t seed = 1;
  double time_limit_seconds = 0;      // 0 = none
  std::uint64_t max_evaluations = 0;  // 0 = none
  std::uint64_t max_iterations = 0;   // 0 = none
  std::string solution_path;          // --print-solution; "-" is standard output
};

// Declares --solver (required), --set, --seed, --time-limit, --max-evaluations,
// --max-iterations and --print-solution on `command`, writing into `options`, which must
// outlive the parse.
void add_solve_options(CLI::App& command, SolveOptions& options, const std::string& solution_help);

// CLI11 reads "-1" into an unsigned option as a huge number and wraps values above 2^64;
// this check refuses both, naming the option.
CLI::Validator unsigned_integer();

// Creates the solver from the registry; throws solvers::OptionError (unknown solver or
// option, bad value).
std::unique_ptr<solvers::Solver> make_solver(const SolveOptions& options);
// The seed and limits; throws solvers::OptionError for a non-finite or negative time limit.
solvers::SolveContext make_context(const SolveOptions& options);

// Thrown by a command whose run finished but failed its own check; main prints the message
// and exits with status 1 (status 2 is for bad input and usage errors).
class RunFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown by a command that Ctrl-C or SIGTERM stopped after it saved what was done; main
// prints the message (how to go on) and exits with status 130.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sightline::apps
