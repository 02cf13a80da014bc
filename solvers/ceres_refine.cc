// ceres-refine: the objective in unbounded parameters, its adapter to Ceres, the back-off.
// This is the one translation unit of solvers/ that includes Ceres.
#include "solvers/ceres_refine.h"

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

namespace detail {

double hard_tolerance(double hard) {
  // Feasible stays exactly feasible (Score::feasible() is hard <= 0); an infeasible level may
  // drift by Score::better_than's relative tolerance, so round-off is not "breaking" it more.
  return hard <= 0 ? 0.0 : hard + 1e-12 * (1 + hard);
}

bool improves(const csp::Score& score, const csp::Score& anchor) {
  if (anchor.feasible() && !score.feasible()) return false;
  return score.better_than(anchor);
}

void RefinementObjective::reset(const csp::Problem& problem, std::span<const double> start,
                                Terms terms, double smoothing, bool guard_hard,
                                double hard_penalty) {
  problem_ = &problem;
  smoothing_ = smoothing;
  guard_hard_ = guard_hard && terms == Terms::kSoft;
  values_.assign(start.begin(), start.end());
  free_.clear();
  centre_.clear();
  radius_.clear();
  free_index_.assign(problem.num_variables(), -1);
  for (csp::VariableId v = 0; v < problem.num_variables(); ++v) {
    const csp::Domain& d = problem.variable(v).domain;
    if (!d.is_continuous() || !(d.upper() > d.lower())) continue;
    free_index_[v] = static_cast<std::int32_t>(free_.size());
    free_.push_back(v);
    centre_.push_back(0.5 * (d.lower() + d.upper()));
    radius_.push_back(0.5 * (d.upper() - d.lower()));
  }
  terms_.clear();
  term_weights_.clear();
  hard_.clear();
  std::size_t max_arity = 0;
  double start_hard = 0;
  for (csp::ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const csp::Constraint& c = problem.constraint(id);
    if (c.weight() <= 0) continue;
    const auto scope = c.scope();
    const bool touches_free = std::any_of(scope.begin(), scope.end(),
                                          [&](csp::VariableId v) { return free_index_[v] >= 0; });
    if (!touches_free) continue;  // constant while refining
    if (c.is_hard()) {
      hard_.push_back(id);
      start_hard += c.weight() * c.violation(values_);
    }
    const bool penalised = terms == Terms::kSoftAndPenalisedHard && c.is_hard();
    if (penalised || c.is_hard() == (terms == Terms::kHard)) {
      terms_.push_back(id);
      // A penalised hard term enters as hard_penalty w v^2, stored as a negative weight.
      term_weights_.push_back(penalised ? -hard_penalty * c.weight() : c.weight());
      max_arity = std::max(max_arity, scope.size());
    }
  }
  hard_limit_ = hard_tolerance(start_hard);
  scope_gradient_.assign(max_arity, 0.0);
  gradient_x_.assign(free_.size(), 0.0);
  best_u_.assign(free_.size(), 0.0);
  best_cost_ = std::numeric_limits<double>::infinity();
  evaluations_ = 0;
  cap_ = 0;
  cap_reached_ = false;
  guard_rejections_ = 0;
}

void RefinementObjective::to_parameters(std::span<const double> values, std::span<double> u) const {
  // u = r asin((x - c) / r), with the angle kept kNudgeRadians inside +-pi/2.
  constexpr double kMaxAngle = 1.5707963267948966 - kNudgeRadians;
  for (std::size_t i = 0; i < free_.size(); ++i) {
    const double ratio = std::clamp((values[free_[i]] - centre_[i]) / radius_[i], -1.0, 1.0);
    u[i] = radius_[i] * std::clamp(std::asin(ratio), -kMaxAngle, kMaxAngle);
  }
}

void RefinementObjective::to_assignment(std::span<const double> u, std::span<double> values) const {
  std::copy(values_.begin(), values_.end(), values.begin());  // fixed variables: the start
  for (std::size_t i = 0; i < free_.size(); ++i) {
    const csp::Domain& d = problem_->variable(free_[i]).domain;
    // x = c + r sin(u / r); the clamp only absorbs round-off at the bounds.
    values[free_[i]] =
        std::clamp(centre_[i] + radius_[i] * std::sin(u[i] / radius_[i]), d.lower(), d.upper());
  }
}

bool RefinementObjective::evaluate(std::span<const double> u, double& cost,
                                   std::span<double> gradient) {
  if (cap_ && evaluations_ >= cap_) {
    cap_reached_ = true;
    return false;
  }
  ++evaluations_;
  to_assignment(u, values_);
  if (guard_hard_ && !hard_.empty()) {
    double hard = 0;
    for (const csp::ConstraintId id : hard_) {
      const csp::Constraint& c = problem_->constraint(id);
      hard += c.weight() * c.violation(values_);
    }
    if (!(hard <= hard_limit_)) {
      ++guard_rejections_;
      return false;
    }
  }
  // f = sum_c w_c smooth_c(x);  df/dx_v = sum over c with v in scope of w_c d smooth_c/dx_v.
  double f = 0;
  std::fill(gradient_x_.begin(), gradient_x_.end(), 0.0);
  // A penalised hard term is p w v^2 (d/dx: 2 p w v dv/dx), with the exact violation: a
  // hinge-shaped v = max(0, r) makes v^2 = max(0, r)^2 continuously differentiable whatever
  // the constraint's own smooth form, and a 0/1 violation stays flat, costing nothing.
  for (std::size_t k = 0; k < terms_.size(); ++k) {
    const csp::Constraint& c = problem_->constraint(terms_[k]);
    const bool squared = term_weights_[k] < 0;
    const auto scope = c.scope();
    const std::span<double> g(scope_gradient_.data(), scope.size());
    const double v = smoothing_ > 0 && !squared
                         ? c.smooth_violation_and_gradient(values_, g, smoothing_)
                         : c.violation_and_gradient(values_, g);
    const double w = squared ? -term_weights_[k] * v : term_weights_[k];
    f += w * v;
    const double slope = squared ? 2 * w : w;
    for (std::size_t j = 0; j < scope.size(); ++j) {
      const std::int32_t i = free_index_[scope[j]];
      if (i >= 0) gradient_x_[i] += slope * g[j];
    }
  }
  if (!std::isfinite(f)) return false;
  cost = f;
  // Chain rule through the sine map: df/du = df/dx cos(u / r).
  if (!gradient.empty()) {
    for (std::size_t i = 0; i < free_.size(); ++i) {
      gradient[i] = gradient_x_[i] * std::cos(u[i] / radius_[i]);
      if (!std::isfinite(gradient[i])) return false;
    }
  }
  if (f < best_cost_) {
    best_cost_ = f;
    std::copy(u.begin(), u.end(), best_u_.begin());
  }
  return true;
}

}  // namespace detail

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
  return "";
}

CeresRefineSolver::CeresRefineSolver(std::string name, Options options)
    : name_(std::move(name)), options_(std::move(options)) {}

std::string CeresRefineSolver::unsuitable_reason(const csp::Problem& problem) const {
  for (const auto& variable : problem.variables()) {
    if (variable.domain.is_continuous() && variable.domain.upper() > variable.domain.lower()) {
      return "";
    }
  }
  return "needs at least one continuous variable with a non-empty interval";
}

void CeresRefineSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                   const SolveContext& context, SolverResult& result) {
  Budget budget(context.limits, 1);
  max_evaluations_ = context.limits.max_evaluations;
  anchor_.assign(start.begin(), start.end());  // a copy: `start` may alias result.best
  anchor_score_ = problem.score(anchor_);
  result.evaluations = 1;
  result.iterations = 0;
  result.solutions_at_best = 0;
  result.stop = StopReason::kCompleted;
  result.message.clear();
  auto note = [&result](const std::string& text) {
    result.message += (result.message.empty() ? "" : "; ") + text;
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
  }
  result.best = anchor_;
  finish_result(problem, context, budget, result);
  if (result.stop == StopReason::kCompleted && result.score.feasible() && result.score.soft <= 0) {
    result.stop = StopReason::kTargetReached;
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
      probe_[v] = problem.variable(static_cast<csp::VariableId>(v)).domain.clamp(x);
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
      probe_[v] = problem.variable(static_cast<csp::VariableId>(v)).domain.clamp(x);
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
