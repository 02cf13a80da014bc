// LinearForm: the shared base of constraints whose violation depends on one weighted sum
//
//     s = sum_i a_i x_i      (x_i = values[scope[i]], a_i = coefficients[i])
//
// through a piecewise-linear function g: violation = g(s). `linear` (s <= rhs, s = rhs,
// s >= rhs) and `abs_deviation` (|s + c - target|) are such constraints. Keeping the sum in
// the incremental state makes every one-variable delta O(1):
//
//     delta = g(s + a_k (new - x_k)) - g(s),
//
// and the gradient exact: d violation / d x_i = g'(s) a_i, where at a kink of g (s exactly on
// the boundary) g' is the subgradient 0, which is what a minimiser standing on the optimum
// wants to hear. For solvers that stall on kinks, smooth_violation_and_gradient rounds g
// (see Constraint::smooth_violation_and_gradient) while keeping it 0 where g is 0.
#pragma once

#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/csp/spec.h"

namespace sightline::csp {

class Problem;

class LinearForm : public Constraint {
 public:
  // coefficients.size() == scope.size(); throws std::invalid_argument otherwise or when a
  // coefficient is not finite.
  LinearForm(std::vector<VariableId> scope, std::vector<double> coefficients, double weight,
             bool hard);

  const std::vector<double>& coefficients() const { return coefficients_; }
  // s = sum_i a_i x_i over the whole assignment (O(arity)).
  double sum(std::span<const double> values) const;

  // g(s) and a (sub)gradient g'(s), defined by each kind.
  virtual double violation_of_sum(double s) const = 0;
  virtual double slope_at(double s) const = 0;
  // A smooth stand-in for g (smooth_hinge / smooth_abs of constraint.h, `smoothing` wide),
  // for gradient-based solvers; writes its derivative in `slope`.
  virtual double smooth_violation_of_sum(double s, double smoothing, double& slope) const = 0;
  // A sum at which g is smallest (g is convex, so over an interval [lo, hi] of sums its
  // minimum is g(clamp(minimiser, lo, hi))).
  virtual double minimiser_of_sum() const = 0;

  // The domains' bounds of the scope's variables, in scope order, so that min_violation can
  // bound partial assignments; factories set them from the problem's domains. Without them
  // min_violation is the base class's (0 until the whole scope is assigned).
  void set_variable_bounds(std::vector<double> lower, std::vector<double> upper);
  // Lower bound over completions: the assigned part of s plus, for each unassigned x_i in
  // [lo_i, hi_i], a_i x_i ranging over [min(a_i lo_i, a_i hi_i), max(...)], gives an interval
  // [s_lo, s_hi] holding every completion's sum (integrality relaxed, so it is a valid lower
  // bound); g's minimum over it is g(clamp(minimiser, s_lo, s_hi)).
  double min_violation(std::span<const double> values,
                       std::span<const std::uint8_t> assigned) const final;

  double violation(std::span<const double> values) const final {
    return violation_of_sum(sum(values));
  }
  std::unique_ptr<IncrementalState> make_incremental_state(
      std::span<const double> values) const final;
  bool has_exact_gradient() const final { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const final;
  double smooth_violation_and_gradient(std::span<const double> values, std::span<double> gradient,
                                       double smoothing) const final;

 private:
  std::vector<double> coefficients_;
  std::vector<double> lower_, upper_;  // empty when unknown
};

// The bounds of the scope's variables in `problem`, for LinearForm::set_variable_bounds.
void set_bounds_from_domains(LinearForm& form, const Problem& problem);

// Reads the optional `coefficients` field of a constraint entry: a list of numbers as long as
// the scope, or absent (every coefficient 1). Throws InputError at the field otherwise.
std::vector<double> read_coefficients(const Spec& entry, std::size_t arity);

}  // namespace sightline::csp
