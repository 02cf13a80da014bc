// ceres-refine's objective in unbounded parameters (detail::RefinementObjective) and the
// acceptance rules shared by its phases; no Ceres type here (ceres_refine.cc adapts it).
#include "sightline/solvers/ceres_refine.h"

#include <algorithm>
#include <cmath>
#include <limits>

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
    const csp::Domain& d = problem.domain(v);
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
    const csp::Domain& d = problem_->domain(free_[i]);
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
  double f = 0;
  if (!smooth_cost(f)) return false;
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

bool RefinementObjective::smooth_cost(double& cost) {
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
  return true;
}

bool RefinementObjective::evaluate_at(std::span<const double> values, double& cost,
                                      std::span<double> gradient_x) {
  if (cap_ && evaluations_ >= cap_) {
    cap_reached_ = true;
    return false;
  }
  ++evaluations_;
  std::copy(values.begin(), values.end(), values_.begin());
  if (!smooth_cost(cost)) return false;
  std::copy(gradient_x_.begin(), gradient_x_.end(), gradient_x.begin());
  return true;
}

}  // namespace detail
}  // namespace sightline::solvers
