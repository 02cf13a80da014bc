#include "domains/camera/constraints/future_visibility.h"

#include <algorithm>

namespace sightline::camera {

double FutureVisibleConstraint::hidden_fraction(std::span<const double> values, bool bounded,
                                                double cost_before, double bound) const {
  const MotionPrediction& p = *prediction_;
  if (p.size() == 0) return 0.0;
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  // The hidden weights are summed in sample order; a prefix of that sum is a lower bound of
  // the whole (adding non-negative terms never rounds down below a partial sum).
  double hidden = 0;
  for (int k = 0; k < p.size(); ++k) {
    if (p.geometry(k).line_of_sight(camera, p.sample(k).look_at)) continue;
    hidden += p.sample(k).weight;
    if (bounded && cost_before + weight() * (hidden / p.total_weight()) >= bound) break;
  }
  return hidden / p.total_weight();
}

double FutureVisibleConstraint::violation(std::span<const double> values) const {
  return hidden_fraction(values, false, 0, 0);
}

double FutureVisibleConstraint::violation_until(std::span<const double> values,
                                                double cost_before, double bound) const {
  return hidden_fraction(values, true, cost_before, bound);
}

double FutureVisibleConstraint::violation_and_gradient(std::span<const double> values,
                                                       std::span<double> gradient) const {
  std::fill(gradient.begin(), gradient.end(), 0.0);
  return violation(values);
}

}  // namespace sightline::camera
