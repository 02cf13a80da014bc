#include "sightline/csp/kinds/linear_form.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sightline/csp/problem.h"
#include "sightline/csp/spec.h"

namespace sightline::csp {
namespace {

// Keeps s, the weighted sum at the current assignment.
class LinearFormState : public IncrementalState {
 public:
  LinearFormState(const LinearForm& c, double s) : c_(c), s_(s) {}

  double delta(std::span<const double> values, std::size_t position, double new_value) override {
    const double moved =
        s_ + c_.coefficients()[position] * (new_value - values[c_.scope()[position]]);
    return c_.violation_of_sum(moved) - c_.violation_of_sum(s_);
  }
  void commit(std::span<const double> values, std::size_t position, double new_value) override {
    s_ += c_.coefficients()[position] * (new_value - values[c_.scope()[position]]);
  }
  // A variable with coefficient 0 cannot repair anything, so it takes no part in the conflict.
  double involvement(std::span<const double>, std::size_t position) override {
    return c_.coefficients()[position] == 0 ? 0.0 : c_.violation_of_sum(s_);
  }

 private:
  const LinearForm& c_;
  double s_;
};

}  // namespace

LinearForm::LinearForm(std::vector<VariableId> scope, std::vector<double> coefficients,
                       double weight, bool hard)
    : Constraint(std::move(scope), weight, hard), coefficients_(std::move(coefficients)) {
  if (coefficients_.size() != this->scope().size()) {
    throw std::invalid_argument("a linear form needs one coefficient per variable: " +
                                std::to_string(coefficients_.size()) + " coefficients for " +
                                std::to_string(this->scope().size()) + " variables");
  }
  for (double a : coefficients_) {
    if (!std::isfinite(a)) throw std::invalid_argument("coefficients must be finite numbers");
  }
}

double LinearForm::sum(std::span<const double> values) const {
  const auto vars = scope();
  double s = 0;
  for (std::size_t i = 0; i < vars.size(); ++i) s += coefficients_[i] * values[vars[i]];
  return s;
}

std::unique_ptr<IncrementalState> LinearForm::make_incremental_state(
    std::span<const double> values) const {
  return std::make_unique<LinearFormState>(*this, sum(values));
}

double LinearForm::violation_and_gradient(std::span<const double> values,
                                          std::span<double> gradient) const {
  const double s = sum(values);
  const double slope = slope_at(s);
  for (std::size_t i = 0; i < coefficients_.size(); ++i) gradient[i] = slope * coefficients_[i];
  return violation_of_sum(s);
}

double LinearForm::smooth_violation_and_gradient(std::span<const double> values,
                                                 std::span<double> gradient,
                                                 double smoothing) const {
  double slope = 0;
  const double value = smooth_violation_of_sum(sum(values), smoothing, slope);
  for (std::size_t i = 0; i < coefficients_.size(); ++i) gradient[i] = slope * coefficients_[i];
  return value;
}

void LinearForm::set_variable_bounds(std::vector<double> lower, std::vector<double> upper) {
  if (lower.size() != coefficients_.size() || upper.size() != coefficients_.size()) {
    throw std::invalid_argument("variable bounds need one entry per scope variable");
  }
  lower_ = std::move(lower);
  upper_ = std::move(upper);
}

double LinearForm::min_violation(std::span<const double> values,
                                 std::span<const std::uint8_t> assigned) const {
  if (lower_.empty()) return Constraint::min_violation(values, assigned);
  const auto vars = scope();
  double lo = 0, hi = 0;
  for (std::size_t i = 0; i < vars.size(); ++i) {
    const double a = coefficients_[i];
    if (assigned[vars[i]]) {
      lo += a * values[vars[i]];
      hi += a * values[vars[i]];
    } else {
      lo += std::min(a * lower_[i], a * upper_[i]);
      hi += std::max(a * lower_[i], a * upper_[i]);
    }
  }
  return violation_of_sum(std::clamp(minimiser_of_sum(), lo, hi));
}

void set_bounds_from_domains(LinearForm& form, const Problem& problem) {
  std::vector<double> lower, upper;
  for (VariableId v : form.scope()) {
    lower.push_back(problem.domain(v).lower());
    upper.push_back(problem.domain(v).upper());
  }
  form.set_variable_bounds(std::move(lower), std::move(upper));
}

std::vector<double> read_coefficients(const Spec& entry, std::size_t arity) {
  const Spec* field = entry.find("coefficients");
  if (field == nullptr) return std::vector<double>(arity, 1.0);
  std::vector<double> a = field->as_numbers("a list of numbers for 'coefficients'");
  if (a.size() != arity) {
    field->fail("expected one coefficient per scope variable: " + std::to_string(arity) +
                " numbers, got " + std::to_string(a.size()));
  }
  return a;
}

}  // namespace sightline::csp
