#include "apps/solve_options.h"

#include <charconv>
#include <cmath>

#include "apps/text_table.h"

namespace sightline::apps {

CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec == std::errc() && ptr == end && !text.empty()) return "";
        return "expected an integer in [0, 2^64 - 1], got '" + text + "'";
      },
      "UINT", "unsigned integer");
}

void add_solve_options(CLI::App& command, SolveOptions& options, const std::string& solution_help) {
  command
      .add_option("--solver", options.solver,
                  "registered solver or pipeline 'a>b' (see `sightline solvers`)")
      ->required();
  // One value per --set, so `--set a=1 FILE` leaves FILE to the positional argument.
  command
      .add_option("--set", options.settings,
                  "solver option key=value (repeatable; 'stage.key=value' in pipelines)")
      ->allow_extra_args(false);
  command.add_option("--seed", options.seed, "random seed (same seed, same result)")
      ->check(unsigned_integer())
      ->capture_default_str();
  // CLI11 reads "nan" and "inf" as numbers; make_context refuses them.
  command.add_option("--time-limit", options.time_limit_seconds,
                     "wall-clock limit in seconds (0 = none)");
  command
      .add_option("--max-evaluations", options.max_evaluations,
                  "limit on candidate evaluations (0 = none)")
      ->check(unsigned_integer());
  command
      .add_option("--max-iterations", options.max_iterations,
                  "limit on solver steps: moves, passes, nodes (0 = none)")
      ->check(unsigned_integer());
  command.add_option("--print-solution", options.solution_path, solution_help);
}

std::unique_ptr<solvers::Solver> make_solver(const SolveOptions& options) {
  solvers::OptionValues values;
  for (const std::string& text : options.settings) {
    auto [key, value] = solvers::split_option(text);
    if (values.count(key)) {
      throw solvers::OptionError("option '" + key + "' is set twice");
    }
    values.emplace(std::move(key), std::move(value));
  }
  return solvers::SolverRegistry::global().create(options.solver, values);
}

solvers::SolveContext make_context(const SolveOptions& options) {
  if (!std::isfinite(options.time_limit_seconds) || options.time_limit_seconds < 0) {
    throw solvers::OptionError("--time-limit must be a finite number of seconds >= 0, got " +
                               format_number(options.time_limit_seconds));
  }
  solvers::SolveContext context;
  context.seed = options.seed;
  context.limits.time_limit_seconds = options.time_limit_seconds;
  context.limits.max_evaluations = options.max_evaluations;
  context.limits.max_iterations = options.max_iterations;
  return context;
}

}  // namespace sightline::apps
