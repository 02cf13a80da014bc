#include "sightline/solvers/solver.h"

#include <sstream>
#include <utility>

namespace sightline::solvers {

const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::kCompleted: return "completed";
    case StopReason::kProvenOptimal: return "proven optimal";
    case StopReason::kTargetReached: return "target reached";
    case StopReason::kEvaluationLimit: return "evaluation limit";
    case StopReason::kIterationLimit: return "iteration limit";
    case StopReason::kTimeLimit: return "time limit";
    case StopReason::kInterrupted: return "interrupted";
  }
  return "?";
}

std::string SolverResult::brief_report(const std::string& solver_name) const {
  std::ostringstream out;
  out << solver_name << ": cost " << score.soft << (feasible() ? " feasible" : " INFEASIBLE");
  if (!feasible()) out << " (hard violation " << score.hard << ")";
  out << ", " << evaluations << " evaluations, " << iterations << " iterations, "
      << wall_seconds << " s";
  if (best_found_seconds >= 0) {
    out << ", best at " << best_found_seconds << " s (" << evaluations_at_best << " evaluations)";
  }
  out << ", stop: " << to_string(stop);
  if (!message.empty()) out << " (" << message << ")";
  return out.str();
}

std::string Solver::unsuitable_reason(const csp::Problem&) const { return ""; }

SolverResult Solver::solve(const csp::Problem& problem, std::span<const double> start,
                           const SolveContext& context) {
  SolverResult result;
  solve_into(problem, start, context, result);
  return result;
}

Budget::Budget(const SolveLimits& limits, unsigned clock_stride)
    : limits_(limits), clock_stride_(clock_stride ? clock_stride : 1),
      start_(std::chrono::steady_clock::now()) {}

Budget::Budget(const SolveContext& context, unsigned clock_stride) : Budget(context.limits, clock_stride) {
  keep_trajectory_ = context.want_trajectory;
}

bool Budget::exhausted(std::uint64_t evaluations, std::uint64_t iterations) {
  if (limits_.max_evaluations && evaluations >= limits_.max_evaluations) {
    reason_ = StopReason::kEvaluationLimit;
    return true;
  }
  if (limits_.max_iterations && iterations >= limits_.max_iterations) {
    reason_ = StopReason::kIterationLimit;
    return true;
  }
  if ((limits_.time_limit_seconds > 0 || limits_.stop) && ++calls_ % clock_stride_ == 0) {
    if (limits_.stop_requested()) {
      reason_ = StopReason::kInterrupted;
      return true;
    }
    if (limits_.time_limit_seconds > 0 && read_clock(evaluations) >= limits_.time_limit_seconds) {
      reason_ = StopReason::kTimeLimit;
      return true;
    }
  }
  return false;
}

double Budget::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double Budget::read_clock(std::uint64_t evaluations) {
  last_reading_ = elapsed_seconds();
  last_reading_evaluations_ = evaluations;
  read_once_ = true;
  return last_reading_;
}

void Budget::note_best(std::uint64_t evaluations, std::uint64_t stale_evaluations,
                       const csp::Score* score) {
  const bool fresh_enough = read_once_ && evaluations >= last_reading_evaluations_ &&
                            evaluations - last_reading_evaluations_ <= stale_evaluations;
  record_best(evaluations, fresh_enough && stale_evaluations > 0 ? last_reading_
                                                                  : read_clock(evaluations),
              score);
}

void Budget::record_best(std::uint64_t evaluations, double seconds, const csp::Score* score) {
  best_seconds_ = seconds;
  best_evaluations_ = evaluations;
  if (keep_trajectory_ && score != nullptr) {
    // Improvements a reused clock reading puts at the same time keep only the last.
    if (!trajectory_.empty() && trajectory_.back().seconds == seconds) trajectory_.pop_back();
    trajectory_.push_back({seconds, evaluations, *score});
  }
}

FullEvaluation evaluate_fully(const csp::Problem& problem, std::span<const double> values,
                              bool keep_breakdown) {
  FullEvaluation out;
  if (!keep_breakdown) {
    out.score = problem.score(values);
    return out;
  }
  out.breakdown = problem.breakdown(values);
  // Summed as Problem::score sums constraint_score, in the same order: the same bits.
  for (const csp::ConstraintCost& c : out.breakdown) {
    out.score += c.hard ? csp::Score{c.cost, 0} : csp::Score{0, c.cost};
  }
  return out;
}

void finish_result(const csp::Problem& problem, const SolveContext& context,
                   const Budget& budget, SolverResult& result,
                   std::optional<FullEvaluation> evaluated) {
  if (!evaluated) evaluated = evaluate_fully(problem, result.best, context.want_breakdown);
  result.score = evaluated->score;
  if (context.want_breakdown) {
    result.breakdown = std::move(evaluated->breakdown);
  } else {
    result.breakdown.clear();
  }
  result.wall_seconds = budget.elapsed_seconds();
  result.best_found_seconds = budget.best_found_seconds();
  result.evaluations_at_best = budget.best_found_seconds() >= 0 ? budget.evaluations_at_best() : 0;
  result.trajectory.clear();
  if (context.want_trajectory) {
    // What the solver noted, then the result itself unless that was the last point noted.
    result.trajectory = budget.trajectory();
    const auto& last = result.trajectory;
    if (last.empty() || result.score.better_than(last.back().score) ||
        last.back().score.better_than(result.score)) {
      const bool known = result.best_found_seconds >= 0;
      result.trajectory.push_back({known ? result.best_found_seconds : result.wall_seconds,
                                   known ? result.evaluations_at_best : result.evaluations,
                                   result.score});
    }
  }
}

}  // namespace sightline::solvers
