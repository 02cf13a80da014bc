#include "sightline/solvers/sls.h"

#include <utility>

#include "sightline/solvers/detail/sls_engines.h"

namespace sightline::solvers {

const OptionSchema<SlsSolver::Options>& SlsSolver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.real("walk_probability", &Options::walk_probability,
           "chance of a random move when a variable is at a local minimum, in [0, 1]", 0, 1);
    s.integer("tabu_tenure", &Options::tabu_tenure,
              "steps a variable may not return to the value it left by a non-improving move", 0);
    s.integer("value_samples", &Options::value_samples,
              "candidate values per step when a domain has more (>= 1)", 1);
    s.integer("swap_samples", &Options::swap_samples,
              "swap partners tried per step in a permutation group (>= 1)", 1);
    s.boolean("permutation_moves", &Options::permutation_moves,
              "keep hard all_different permutations and move by swaps");
    s.boolean("greedy_start", &Options::greedy_start, "one greedy repair pass at each start");
    s.integer("greedy_samples", &Options::greedy_samples,
              "values or partners tried per variable in the greedy pass (>= 1)", 1);
    s.integer("greedy_window", &Options::greedy_window,
              "greedy swap partners come from the next this-many variables; 0 = all later", 0);
    s.real("placement_attempts", &Options::placement_attempts,
           "draws per variable when placing a randomly dealt permutation group (0 = off)", 0);
    s.integer("stall_moves", &Options::stall_moves,
              "steps without progress before a restart; 0 = 10 x variables + 1000", 0);
    s.integer("restarts", &Options::restarts,
              "cap on restarts; 0 = none: run until a limit (10 restarts if no limit is set)", 0);
    s.boolean("stop_at_zero", &Options::stop_at_zero, "stop at a zero-cost feasible assignment");
    s.real("initial_radius", &Options::initial_radius,
           "continuous step scale, fraction of each domain's width (> 0)");
    s.real("min_radius", &Options::min_radius,
           "continuous: restart when the radius falls below this (> 0)");
    s.real("shrink", &Options::shrink, "continuous: radius multiplier on failure, in (0, 1)");
    s.integer("patience", &Options::patience,
              "continuous: failures in a row before the radius shrinks (>= 1)", 1);
    return s;
  }();
  return schema;
}

std::string SlsSolver::Options::validate() const {
  if (!(walk_probability >= 0 && walk_probability <= 1)) {
    return "walk_probability must be in [0, 1], got " + detail::format_real(walk_probability);
  }
  if (tabu_tenure < 0) return "tabu_tenure must be >= 0, got " + std::to_string(tabu_tenure);
  if (value_samples < 1) return "value_samples must be >= 1, got " + std::to_string(value_samples);
  if (swap_samples < 1) return "swap_samples must be >= 1, got " + std::to_string(swap_samples);
  if (greedy_samples < 1) {
    return "greedy_samples must be >= 1, got " + std::to_string(greedy_samples);
  }
  if (greedy_window < 0) {
    return "greedy_window must be >= 0 (0 = every later variable), got " +
           std::to_string(greedy_window);
  }
  if (stall_moves < 0)
    return "stall_moves must be >= 0 (0 = automatic), got " + std::to_string(stall_moves);
  if (restarts < 0) return "restarts must be >= 0, got " + std::to_string(restarts);
  if (!(initial_radius > 0)) {
    return "initial_radius must be > 0, got " + detail::format_real(initial_radius);
  }
  if (!(min_radius > 0 && min_radius <= initial_radius)) {
    return "min_radius must be in (0, initial_radius], got " + detail::format_real(min_radius);
  }
  if (!(shrink > 0 && shrink < 1)) {
    return "shrink must be in (0, 1), got " + detail::format_real(shrink);
  }
  if (patience < 1) return "patience must be >= 1, got " + std::to_string(patience);
  return "";
}

SlsSolver::SlsSolver(std::string name, Options options)
    : name_(std::move(name)), options_(options) {}

std::uint64_t SlsSolver::restart_cap(const SolveContext& context) const {
  if (options_.restarts > 0) return static_cast<std::uint64_t>(options_.restarts);
  return context.runs_to_the_limit() ? 0 : static_cast<std::uint64_t>(kDefaultRestarts);
}

void SlsSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                           const SolveContext& context, SolverResult& result) {
  Budget budget(context, 256);
  result.solutions_at_best = 0;
  const std::uint64_t cap = restart_cap(context);
  std::optional<FullEvaluation> evaluated;
  if (problem.all_discrete()) {
    evaluated = detail::run_discrete_sls(problem, start, options_, cap, context.seed, budget,
                                         result, context.want_breakdown);
  } else {
    detail::run_continuous_sls(problem, start, options_, cap, context.seed, budget, result,
                               current_, candidate_);
  }
  // Ending on the default restarts is not what the user asked for (anytime): say why.
  if (result.stop == StopReason::kCompleted && options_.restarts == 0 && cap != 0) {
    result.message += "; " + std::to_string(kDefaultRestarts) +
                      (!context.anytime
                           ? " restarts is the default of a pipeline stage before the last: "
                             "set restarts=N to change it"
                           : " restarts is the default when no limit is set: give a time, "
                             "evaluation or iteration limit, or restarts=N");
  }
  finish_result(problem, context, budget, result, std::move(evaluated));
}

}  // namespace sightline::solvers
