#include "sightline/solvers/tabu.h"

#include <algorithm>

#include "sightline/solvers/detail/tabu_search.h"

namespace sightline::solvers {

namespace {
constexpr std::size_t kMaxTableEntries = std::size_t{1} << 26;
}

const OptionSchema<TabuSolver::Options>& TabuSolver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.integer("tenure_min", &Options::tenure_min,
              "shortest tabu tenure: steps a left value stays forbidden (>= 0); -1 = "
              "max(2, mean domain size / 6)",
              -1);
    s.integer("tenure_max", &Options::tenure_max,
              "longest tabu tenure, steps (>= tenure_min); each move draws in between; -1 = "
              "max(10, 0.7 x mean domain size)",
              -1);
    s.integer("stall_moves", &Options::stall_moves,
              "steps without a new best before a perturbation; 0 = 100 x variables, >= 2000", 0);
    s.real("perturbation", &Options::perturbation,
           "fraction of the variables a perturbation gives random values, in (0, 1]", 0, 1);
    s.integer("restarts", &Options::restarts,
              "cap on perturbations; -1 = none when a limit is set (10 fruitless ones without)",
              -1);
    s.integer("scan_all_below", &Options::scan_all_below,
              "scan every variable's moves when the table has at most this many entries, "
              "else only the variables in a violated constraint (>= 0)",
              0);
    s.real("hard_weight", &Options::hard_weight,
           "rank moves by hard_weight x hard + soft (a penalty); 0 = hard first; -1 = adaptive "
           "(strategic oscillation)",
           -1);
    s.boolean("compound_moves", &Options::compound_moves,
              "also try pair moves: when moving x breaks a hard binary constraint with y, move y "
              "to a value allowed with x's new one (scored exactly)");
    s.boolean("stop_at_zero", &Options::stop_at_zero, "stop at a zero-cost feasible assignment");
    return s;
  }();
  return schema;
}

std::string TabuSolver::Options::validate() const {
  if (tenure_min < -1) {
    return "tenure_min must be >= 0 (or -1 = automatic), got " + std::to_string(tenure_min);
  }
  if (tenure_max < -1) {
    return "tenure_max must be >= 0 (or -1 = automatic), got " + std::to_string(tenure_max);
  }
  if (tenure_min >= 0 && tenure_max >= 0 && tenure_max < tenure_min) {
    return "tenure_max must be >= tenure_min (" + std::to_string(tenure_min) + "), got " +
           std::to_string(tenure_max);
  }
  if (stall_moves < 0) {
    return "stall_moves must be >= 0 (0 = automatic), got " + std::to_string(stall_moves);
  }
  if (!(perturbation > 0 && perturbation <= 1)) {
    return "perturbation must be in (0, 1], got " + detail::format_real(perturbation);
  }
  if (restarts < -1) return "restarts must be >= -1 (-1 = no cap), got " + std::to_string(restarts);
  if (!(hard_weight >= 0 || hard_weight == -1)) {
    return "hard_weight must be >= 0 (0 = lexicographic) or -1 (adaptive), got " +
           detail::format_real(hard_weight);
  }
  if (scan_all_below < 0) {
    return "scan_all_below must be >= 0, got " + std::to_string(scan_all_below);
  }
  return "";
}

TabuSolver::TabuSolver(std::string name, Options options)
    : name_(std::move(name)), options_(options) {}

std::string TabuSolver::unsuitable_reason(const csp::Problem& problem) const {
  if (!problem.all_discrete()) return "needs discrete domains (every variable)";
  std::size_t entries = 0;
  for (csp::VariableId v = 0; v < problem.num_variables(); ++v) entries += problem.domain(v).size();
  if (entries > kMaxTableEntries) {
    return "the move table would have " + std::to_string(entries) +
           " entries (sum of the domain sizes), more than 2^26";
  }
  return "";
}

void TabuSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                            const SolveContext& context, SolverResult& result) {
  if (std::string why = unsuitable_reason(problem); !why.empty()) {
    throw std::invalid_argument(name_ + ": " + why);
  }
  // The clock is read every `stride` moves: about every 2,000 table entries of work, so a
  // time limit holds when moves are expensive (a 1000-queens all_different: 10^6 entries)
  // and costs nothing noticeable when they are cheap.
  double total_work = 0;
  for (csp::ConstraintId c = 0; c < problem.num_constraints(); ++c) {
    const auto scope = problem.constraint(c).scope();
    for (csp::VariableId u : scope) {
      total_work += static_cast<double>(problem.domain(u).size()) *
                    static_cast<double>(scope.size() - 1);
    }
  }
  const double move_work =
      total_work / static_cast<double>(std::max<std::size_t>(1, problem.num_variables()));
  const auto stride =
      static_cast<unsigned>(std::clamp(2048.0 / std::max(1.0, move_work), 1.0, 64.0));
  Budget budget(context, stride);
  result.solutions_at_best = 0;
  const SolveLimits& l = context.limits;
  const bool unlimited =
      l.max_evaluations == 0 && l.max_iterations == 0 && !(l.time_limit_seconds > 0);
  detail::run_tabu_search(problem, start, options_, context.seed, unlimited, budget, result);
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
