#include "sightline/csp/constraint.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sightline::csp {

namespace {
[[noreturn]] void partial_unsupported() {
  throw std::logic_error(
      "this constraint's incremental state does not support partial assignments");
}
}  // namespace

double IncrementalState::retract(std::span<const double>, std::size_t) { partial_unsupported(); }
double IncrementalState::retract_all(std::span<const double> values, std::size_t arity) {
  double change = 0;
  for (std::size_t position = 0; position < arity; ++position) change += retract(values, position);
  return change;
}
double IncrementalState::place_delta(std::span<const double>, std::size_t, double) {
  partial_unsupported();
}
void IncrementalState::place(std::span<const double>, std::size_t, double) {
  partial_unsupported();
}
double IncrementalState::place_free(std::span<const double> values, std::size_t position,
                                    double new_value) {
  const double change = place_delta(values, position, new_value);
  place(values, position, new_value);
  return change;
}

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

double Constraint::violation_until(std::span<const double> values, double /*cost_before*/,
                                   double /*bound*/, double /*cost_after*/) const {
  return violation(values);
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
  // Central differences with a step scaled to the magnitude of each coordinate. The probe
  // is a per-thread buffer that grows to the largest assignment seen and is then reused, so
  // the per-frame camera path (a user `expression` term) does not allocate; per-thread keeps
  // constraints safe to differentiate from several threads at once.
  thread_local std::vector<double> probe;
  probe.assign(values.begin(), values.end());
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

}  // namespace sightline::csp
