#include "csp/constraint.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sightline::csp {

Constraint::Constraint(std::vector<VariableId> scope, double weight, bool hard)
    : scope_(std::move(scope)), weight_(weight), hard_(hard) {
  if (!std::isfinite(weight) || weight < 0) {
    throw std::invalid_argument("constraint weight must be a finite number >= 0");
  }
}

Constraint::~Constraint() = default;

std::unique_ptr<IncrementalState> Constraint::make_incremental_state(
    std::span<const double>) const {
  return nullptr;
}

double Constraint::min_violation(std::span<const double> values,
                                 std::span<const std::uint8_t> assigned) const {
  for (VariableId v : scope()) {
    if (!assigned[v]) return 0.0;
  }
  return violation(values);
}

double Constraint::violation_and_gradient(std::span<const double> values,
                                          std::span<double> gradient) const {
  // Central differences with a step scaled to the magnitude of each coordinate.
  std::vector<double> probe(values.begin(), values.end());
  for (std::size_t i = 0; i < scope_.size(); ++i) {
    const VariableId v = scope_[i];
    const double x = probe[v];
    const double h = 1e-6 * std::max(1.0, std::abs(x));
    probe[v] = x + h;
    const double up = violation(probe);
    probe[v] = x - h;
    const double down = violation(probe);
    probe[v] = x;
    gradient[i] = (up - down) / (2 * h);
  }
  return violation(values);
}

double Constraint::smooth_violation_and_gradient(std::span<const double> values,
                                                 std::span<double> gradient,
                                                 double /*smoothing*/) const {
  return violation_and_gradient(values, gradient);
}

std::string Constraint::describe() const {
  std::string out(kind());
  out += "(";
  for (std::size_t i = 0; i < scope_.size(); ++i) {
    if (i) out += ", ";
    if (i == 6 && scope_.size() > 8) {
      out += "... " + std::to_string(scope_.size()) + " variables";
      break;
    }
    out += "x" + std::to_string(scope_[i]);
  }
  return out + ")";
}

}  // namespace sightline::csp
