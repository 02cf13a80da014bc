// ceres-refine: the phases, the adapter of the objective (ceres_refine_objective.cc) to
// Ceres, the back-off, the alternatives. This is the one translation unit of solvers/ that
// includes Ceres.
#include "sightline/solvers/ceres_refine.h"

#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/iteration_callback.h>
#include <ceres/types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace sightline::solvers {

namespace {

// Ceres' view of the objective. Ceres owns this small adapter; the objective is the solver's.
class CeresObjective : public ceres::FirstOrderFunction {
 public:
  explicit CeresObjective(detail::RefinementObjective* objective) : objective_(objective) {}
  bool Evaluate(const double* parameters, double* cost, double* gradient) const override {
    const std::size_t n = objective_->num_parameters();
    return objective_->evaluate(std::span<const double>(parameters, n), *cost,
                                gradient ? std::span<double>(gradient, n) : std::span<double>());
  }
  int NumParameters() const override { return static_cast<int>(objective_->num_parameters()); }

 private:
  detail::RefinementObjective* objective_;
};

// Stops Ceres between iterations once the pipeline's time or evaluation budget is spent
// (Ceres' own clock covers time within its iteration; the objective's cap covers the rest).
class BudgetCallback : public ceres::IterationCallback {
 public:
  BudgetCallback(Budget* budget, const detail::RefinementObjective* objective,
                 std::uint64_t evaluations_before)
      : budget_(budget), objective_(objective), before_(evaluations_before) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (objective_->cap_reached() ||
        budget_->exhausted(before_ + objective_->evaluations(),
                           static_cast<std::uint64_t>(summary.iteration))) {
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  Budget* budget_;
  const detail::RefinementObjective* objective_;
  std::uint64_t before_;
};

bool parse_direction(const std::string& text, ceres::LineSearchDirectionType& type) {
  static constexpr std::pair<const char*, ceres::LineSearchDirectionType> kNames[] = {
      {"lbfgs", ceres::LBFGS},
      {"bfgs", ceres::BFGS},
      {"nonlinear_cg", ceres::NONLINEAR_CONJUGATE_GRADIENT},
      {"steepest_descent", ceres::STEEPEST_DESCENT},
  };
  for (const auto& [name, value] : kNames) {
    if (text == name) {
      type = value;
      return true;
    }
  }
  return false;
}

}  // namespace

const OptionSchema<CeresRefineSolver::Options>& CeresRefineSolver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.integer("max_iterations", &Options::max_iterations, "Ceres minimiser iterations per run (phase or round), >= 1", 1,
              1'000'000);
    s.real("function_tolerance", &Options::function_tolerance,
           "stop when the relative decrease of the objective is below this, > 0");
    s.real("gradient_tolerance", &Options::gradient_tolerance,
           "stop when the gradient's max norm (unbounded parameters) is below this, > 0");
    s.real("parameter_tolerance", &Options::parameter_tolerance,
           "stop when the step is below this times |u|, > 0");
    s.real("smoothing", &Options::smoothing,
           "width of the rounded |r| and max(0, r) kinks, in each constraint's units; "
           "0 = exact violations",
           0.0);
    s.text("line_search_direction", &Options::line_search_direction,
           "lbfgs | bfgs | nonlinear_cg | steepest_descent");
    s.integer("smoothing_rounds", &Options::smoothing_rounds,
              "refine rounds, each with a smoothing 10 times smaller, while they gain; 1..10", 1,
              10);
    s.integer("backoff_steps", &Options::backoff_steps,
              "halvings of the step start->refined tried when the refined point is worse, "
              "0..60",
              0, 60);
    s.boolean("guard_hard", &Options::guard_hard,
              "treat points that break hard constraints more than the start as "
              "not evaluable during the search");
    s.boolean("restore_feasibility", &Options::restore_feasibility,
              "from an infeasible start, first minimise the hard constraints' violation");
    s.real("hard_penalty", &Options::hard_penalty,
           "multiplier of hard weights in the slide phase (follows walls); 0 = no slide, >= 0",
           0.0);
    s.integer("alternatives", &Options::alternatives,
              "after another solver in a pipeline: also refine from up to this many of its "
              "alternatives (other basins) and keep the best; 0..64",
              0, 64);
    s.integer("poll_evaluations", &Options::poll_evaluations,
              "Score evaluations of the derivative-free poll that follows edges without a "
              "gradient (0/1 constraints, steps); 0 = no poll",
              0, 1'000'000'000);
    s.real("poll_step", &Options::poll_step,
           "the poll's first step, as a fraction of each variable's half-width, in (0, 1]");
    s.real("poll_min_step", &Options::poll_min_step,
           "the poll stops below this step (fraction of the half-width), in (0, poll_step]");
    return s;
  }();
  return schema;
}

std::string CeresRefineSolver::Options::validate() const {
  if (max_iterations < 1) return "max_iterations must be >= 1";
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(function_tolerance)) return "function_tolerance must be a finite number > 0";
  if (!positive(gradient_tolerance)) return "gradient_tolerance must be a finite number > 0";
  if (!positive(parameter_tolerance)) return "parameter_tolerance must be a finite number > 0";
  if (!std::isfinite(smoothing) || smoothing < 0) {
    return "smoothing must be a finite number >= 0 (0 = exact violations)";
  }
  ceres::LineSearchDirectionType direction;
  if (!parse_direction(line_search_direction, direction)) {
    return "line_search_direction must be one of lbfgs, bfgs, nonlinear_cg, "
           "steepest_descent; got '" +
           line_search_direction + "'";
  }
  if (smoothing_rounds < 1 || smoothing_rounds > 10) return "smoothing_rounds must be in [1, 10]";
  if (backoff_steps < 0 || backoff_steps > 60) return "backoff_steps must be in [0, 60]";
  if (!std::isfinite(hard_penalty) || hard_penalty < 0) {
    return "hard_penalty must be a finite number >= 0 (0 = no slide phase)";
  }
  if (alternatives < 0 || alternatives > 64) return "alternatives must be in [0, 64]";
  if (poll_evaluations < 0) return "poll_evaluations must be >= 0 (0 = no poll phase)";
  if (!(poll_step > 0 && poll_step <= 1)) return "poll_step must be in (0, 1]";
  if (!(poll_min_step > 0 && poll_min_step <= poll_step)) {
    return "poll_min_step must be in (0, poll_step]";
  }
  return "";
}

CeresRefineSolver::CeresRefineSolver(std::string name, Options options)
    : name_(std::move(name)), options_(std::move(options)) {}

std::string CeresRefineSolver::unsuitable_reason(const csp::Problem& problem) const {
  for (csp::VariableId v = 0; v < problem.num_variables(); ++v) {
    const csp::Domain& domain = problem.domain(v);
    if (domain.is_continuous() && domain.upper() > domain.lower()) {
      return "";
    }
  }
  return "needs at least one continuous variable with a non-empty interval";
}

void CeresRefineSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                   const SolveContext& context, SolverResult& result) {
  Budget budget(context, 1);
  max_evaluations_ = context.limits.max_evaluations;
  result.evaluations = 0;
  result.iterations = 0;
  result.solutions_at_best = 0;
  result.stop = StopReason::kCompleted;
  result.message.clear();
  result.alternatives.clear();
  refine_from(problem, start, context, budget, result);
  best_ = anchor_;
  best_score_ = anchor_score_;
  // Alternative starts (another basin, from the stage before): refine from each too and
  // keep the best. The start's own refinement came first, so the result is still never
  // worse than the start nor less feasible.
  const std::size_t tries = std::min(static_cast<std::size_t>(options_.alternatives),
                                     context.alternative_starts.size());
  for (std::size_t i = 0; i < tries && result.stop == StopReason::kCompleted; ++i) {
    const csp::Assignment& from = context.alternative_starts[i];
    if (from.size() != start.size()) continue;  // not an assignment of this problem
    result.message += "; from alternative " + std::to_string(i + 1) + ":";
    refine_from(problem, from, context, budget, result);
    if (detail::improves(anchor_score_, best_score_)) {
      best_.swap(anchor_);
      best_score_ = anchor_score_;
    }
  }
  result.best = best_;
  finish_result(problem, context, budget, result);
  if (result.stop == StopReason::kCompleted && result.score.feasible() && result.score.soft <= 0) {
    result.stop = StopReason::kTargetReached;
  }
}

void CeresRefineSolver::refine_from(const csp::Problem& problem, std::span<const double> start,
                                    const SolveContext& context, Budget& budget,
                                    SolverResult& result) {
  anchor_.assign(start.begin(), start.end());  // a copy: `start` may alias result.best
  anchor_score_ = problem.score(anchor_);
  ++result.evaluations;
  auto note = [&result](const std::string& text) {
    const bool fresh = result.message.empty() || result.message.back() == ':';
    result.message += (result.message.empty() ? "" : fresh ? " " : "; ") + text;
  };
  auto running = [&result] { return result.stop == StopReason::kCompleted; };

  if (!unsuitable_reason(problem).empty()) {
    note("no continuous variable to refine");
  } else if (anchor_score_.feasible() && anchor_score_.soft <= 0) {
    result.stop = StopReason::kTargetReached;
  } else {
    if (!anchor_score_.feasible() && options_.restore_feasibility) {
      note("restore:");
      if (run_ceres(problem, anchor_, Terms::kHard, 0.0, false, context, budget, result)) {
        accept_along_segment(problem, result);
      }
    }
    // Continuation: the smoothed optimum is O(s) away from a kinked one (an L1 problem's
    // optimum is a vertex where kinks meet), so each round restarts from the last with a
    // width 10 times smaller, until a round gains nothing. Rounds after the first start next
    // to the optimum and cost a few iterations.
    bool hit_wall = false;
    double smoothing = options_.smoothing;
    for (std::int64_t round = 0; round < options_.smoothing_rounds && running(); ++round) {
      if (round > 0) smoothing /= 10;
      note("refine (smoothing " + detail::format_real(smoothing) + "):");
      if (!run_ceres(problem, anchor_, Terms::kSoft, smoothing, options_.guard_hard, context,
                     budget, result)) {
        break;
      }
      hit_wall = hit_wall || objective_.guard_rejections() > 0;
      if (!accept_along_segment(problem, result) || smoothing == 0) break;
    }
    if (running() && hit_wall && options_.hard_penalty > 0) {
      note("slide:");
      if (run_ceres(problem, anchor_, Terms::kSoftAndPenalisedHard, smoothing, false,
                    context, budget, result)) {
        // Ceres' point is usually a little inside a wall: push it out (a restore run, which
        // may overshoot by a whole first step), come back to the wall by bisection between
        // the pushed and the inside point, then judge it.
        csp::Score slid;
        if (running() && judge(problem, candidate_, result, slid) &&
            slid.hard > detail::hard_tolerance(anchor_score_.hard)) {
          inside_ = candidate_;
          note("push out:");
          if (run_ceres(problem, inside_, Terms::kHard, 0.0, false, context, budget, result)) {
            bisect_toward_inside(problem, result);
          }
        }
        accept_along_segment(problem, result);
      }
    }
    if (running() && options_.poll_evaluations > 0) {
      poll_and_refine(problem, smoothing, context, budget, result);
    }
  }
}

namespace {

// The poll's view of the solver: Scores counted in the result under the solve's limits, and
// the smooth part's gradient from the refine objective.
class PollTarget : public detail::BoundaryPoll::Target {
 public:
  PollTarget(const csp::Problem& problem, detail::RefinementObjective& objective,
             Budget& budget, std::uint64_t max_evaluations, SolverResult& result)
      : problem_(problem), objective_(objective), budget_(budget),
        max_evaluations_(max_evaluations), result_(result) {}
  bool judge(std::span<const double> values, csp::Score& score) override {
    if ((max_evaluations_ && result_.evaluations >= max_evaluations_) ||
        budget_.exhausted(result_.evaluations, result_.iterations)) {
      result_.stop = max_evaluations_ && result_.evaluations >= max_evaluations_
                         ? StopReason::kEvaluationLimit
                         : budget_.reason();
      return false;
    }
    score = problem_.score(values);
    ++result_.evaluations;
    return true;
  }
  bool gradient(std::span<const double> values, std::span<double> g) override {
    if (max_evaluations_ && result_.evaluations >= max_evaluations_) return false;
    double cost;
    ++result_.evaluations;
    return objective_.evaluate_at(values, cost, g);
  }

 private:
  const csp::Problem& problem_;
  detail::RefinementObjective& objective_;
  Budget& budget_;
  std::uint64_t max_evaluations_;
  SolverResult& result_;
};

}  // namespace

void CeresRefineSolver::poll_and_refine(const csp::Problem& problem, double smoothing,
                                        const SolveContext& context, Budget& budget,
                                        SolverResult& result) {
  objective_.reset(problem, anchor_, Terms::kSoft, smoothing, false);
  if (objective_.num_terms() == 0) return;
  // Stationary (the scaled gradient, with the components that push out of the box at an
  // active bound removed, is ~0): a smooth optimum, no edge to follow.
  gradient_.resize(objective_.num_parameters());
  double cost = 0;
  if (max_evaluations_ && result.evaluations >= max_evaluations_) return;
  ++result.evaluations;
  if (!objective_.evaluate_at(anchor_, cost, gradient_)) return;
  const auto free = objective_.free_variables();
  const auto half = objective_.half_widths();
  double largest = 0;
  for (std::size_t i = 0; i < free.size(); ++i) {
    const csp::Domain& d = problem.domain(free[i]);
    const double x = anchor_[free[i]], g = gradient_[i];
    if ((x >= d.upper() && g < 0) || (x <= d.lower() && g > 0)) continue;
    largest = std::max(largest, std::abs(g) * half[i]);
  }
  if (!(largest > kStationaryGradient * (1 + std::abs(cost)))) return;
  result.message += (result.message.empty() ? "" : "; ") + std::string("poll:");
  detail::BoundaryPoll::Settings settings;
  settings.initial_step = options_.poll_step;
  settings.min_step = options_.poll_min_step;
  settings.max_evaluations = static_cast<std::uint64_t>(options_.poll_evaluations);
  settings.seed = context.seed;
  PollTarget target(problem, objective_, budget, max_evaluations_, result);
  const std::uint64_t before = result.evaluations;
  const bool moved = poll_.run(problem, free, half, settings, target, anchor_, anchor_score_);
  result.message += " " + std::to_string(result.evaluations - before) + " evaluations, " +
                    (moved ? "moved" : "no better point");
  if (!moved || result.stop != StopReason::kCompleted) return;
  result.message += "; refine (smoothing " + detail::format_real(smoothing) + "):";
  if (run_ceres(problem, anchor_, Terms::kSoft, smoothing, options_.guard_hard, context,
                budget, result)) {
    accept_along_segment(problem, result);
  }
}

bool CeresRefineSolver::run_ceres(const csp::Problem& problem, std::span<const double> from,
                                  Terms terms, double smoothing, bool guard,
                                  const SolveContext& context, Budget& budget,
                                  SolverResult& result) {
  auto note = [&result](const std::string& text) { result.message += " " + text; };
  objective_.reset(problem, from, terms, smoothing, guard, options_.hard_penalty);
  if (objective_.num_terms() == 0) {
    note("no term on a free variable");
    return false;
  }
  // Evaluations: Ceres', then at least its best point's Score (bisection probes stop at the
  // limit by themselves).
  const SolveLimits& limits = context.limits;
  const std::uint64_t reserve = 2;
  if (limits.max_evaluations) {
    if (limits.max_evaluations <= result.evaluations + reserve) {
      result.stop = StopReason::kEvaluationLimit;
      note("the evaluation limit leaves nothing for Ceres");
      return false;
    }
    objective_.set_evaluation_cap(limits.max_evaluations - result.evaluations - reserve);
  }
  std::int64_t max_iterations = options_.max_iterations;
  bool context_caps_iterations = false;
  if (limits.max_iterations) {
    const std::int64_t left = static_cast<std::int64_t>(limits.max_iterations) -
                              static_cast<std::int64_t>(result.iterations);
    if (left <= 0) {
      result.stop = StopReason::kIterationLimit;
      return false;
    }
    context_caps_iterations = left <= max_iterations;
    max_iterations = std::min(max_iterations, left);
  }

  ceres::GradientProblemSolver::Options ceres_options;
  parse_direction(options_.line_search_direction, ceres_options.line_search_direction_type);
  ceres_options.line_search_type = ceres::WOLFE;
  ceres_options.max_num_iterations = static_cast<int>(max_iterations);
  ceres_options.function_tolerance = options_.function_tolerance;
  ceres_options.gradient_tolerance = options_.gradient_tolerance;
  ceres_options.parameter_tolerance = options_.parameter_tolerance;
  if (limits.time_limit_seconds > 0) {
    ceres_options.max_solver_time_in_seconds =
        std::max(0.0, limits.time_limit_seconds - budget.elapsed_seconds());
  }
  ceres_options.logging_type = ceres::SILENT;
  BudgetCallback callback(&budget, &objective_, result.evaluations);
  ceres_options.callbacks.push_back(&callback);

  u_.resize(objective_.num_parameters());
  objective_.to_parameters(from, u_);
  ceres::GradientProblem gradient_problem(new CeresObjective(&objective_));
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(ceres_options, gradient_problem, u_.data(), &summary);
  const std::uint64_t iterations = summary.iterations.empty() ? 0 : summary.iterations.size() - 1;
  result.evaluations += objective_.evaluations();
  result.iterations += iterations;
  note(std::string("ceres ") + ceres::TerminationTypeToString(summary.termination_type) + ", " +
       std::to_string(iterations) + " iterations: " + summary.message);

  // Why Ceres stopped, in the solver interface's words.
  if (objective_.cap_reached()) {
    result.stop = StopReason::kEvaluationLimit;
  } else if (summary.termination_type == ceres::USER_SUCCESS) {
    result.stop = budget.reason();
  } else if (summary.termination_type == ceres::NO_CONVERGENCE) {
    if (iterations >= static_cast<std::uint64_t>(max_iterations)) {
      // The solver's own max_iterations is its course; the context's is a limit.
      if (context_caps_iterations) result.stop = StopReason::kIterationLimit;
    } else {
      result.stop = StopReason::kTimeLimit;
    }
  }
  // The best point Ceres evaluated, whatever its termination: a failed line search or an
  // abort still leaves the incumbent.
  if (!std::isfinite(objective_.best_cost())) return false;
  candidate_.resize(from.size());
  objective_.to_assignment(objective_.best_parameters(), candidate_);
  return true;
}

bool CeresRefineSolver::judge(const csp::Problem& problem, std::span<const double> values,
                              SolverResult& result, csp::Score& score) const {
  if (max_evaluations_ && result.evaluations >= max_evaluations_) {
    result.stop = StopReason::kEvaluationLimit;
    return false;
  }
  score = problem.score(values);
  ++result.evaluations;
  return true;
}

void CeresRefineSolver::bisect_toward_inside(const csp::Problem& problem, SolverResult& result) {
  // candidate_ (pushed out) at t = 0, inside_ at t = 1: the largest t whose point is as
  // feasible as the anchor.
  const double limit = detail::hard_tolerance(anchor_score_.hard);
  csp::Score score;
  if (!judge(problem, candidate_, result, score) || !(score.hard <= limit)) return;
  probe_.resize(anchor_.size());
  best_probe_ = candidate_;
  double low = 0, high = 1;
  for (std::int64_t k = 1; k <= options_.backoff_steps; ++k) {
    const double t = 0.5 * (low + high);
    for (std::size_t v = 0; v < anchor_.size(); ++v) {
      const double x = candidate_[v] + t * (inside_[v] - candidate_[v]);
      probe_[v] = problem.domain(static_cast<csp::VariableId>(v)).clamp(x);
    }
    if (!judge(problem, probe_, result, score)) break;
    if (score.hard <= limit) {
      low = t;
      best_probe_.swap(probe_);
    } else {
      high = t;
    }
  }
  candidate_.swap(best_probe_);
}

bool CeresRefineSolver::accept_along_segment(const csp::Problem& problem, SolverResult& result) {
  csp::Score score;
  if (!judge(problem, candidate_, result, score)) return false;
  if (detail::improves(score, anchor_score_)) {
    anchor_.swap(candidate_);
    anchor_score_ = score;
    return true;
  }
  // Bisect the segment x(t) = anchor + t (candidate - anchor) for the largest t whose point
  // beats the anchor: a probe that does moves the low end up, one that does not moves the
  // high end down, so a candidate just past a wall costs ~log2(1 / distance) probes and one
  // that is worse everywhere is probed at t = 1/2, 1/4, ... The box is convex, so every x(t)
  // is inside it (the clamp only absorbs round-off). The best probe that beats the anchor wins.
  probe_.resize(anchor_.size());
  double low = 0, high = 1;
  bool found = false;
  csp::Score best_score;
  for (std::int64_t k = 1; k <= options_.backoff_steps; ++k) {
    const double t = 0.5 * (low + high);
    for (std::size_t v = 0; v < anchor_.size(); ++v) {
      const double x = anchor_[v] + t * (candidate_[v] - anchor_[v]);
      probe_[v] = problem.domain(static_cast<csp::VariableId>(v)).clamp(x);
    }
    if (!judge(problem, probe_, result, score)) break;
    if (detail::improves(score, anchor_score_)) {
      low = t;
      if (!found || score.better_than(best_score)) {
        best_probe_ = probe_;
        best_score = score;
        found = true;
      }
    } else {
      high = t;
    }
  }
  if (!found) {
    result.message += " (kept its start: no point toward Ceres' point is better)";
    return false;
  }
  result.message += " (backed off to t = " + std::to_string(low) + ")";
  anchor_.swap(best_probe_);
  anchor_score_ = best_score;
  return true;
}

}  // namespace sightline::solvers
