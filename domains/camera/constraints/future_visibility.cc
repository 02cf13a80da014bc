#include "domains/camera/constraints/future_visibility.h"

#include <algorithm>

namespace sightline::camera {

double FutureVisibleConstraint::violation(std::span<const double> values) const {
  const MotionPrediction& p = *prediction_;
  if (p.size() == 0) return 0.0;
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  double hidden = 0;
  for (int k = 0; k < p.size(); ++k) {
    if (!p.geometry(k).line_of_sight(camera, p.sample(k).look_at)) hidden += p.sample(k).weight;
  }
  return hidden / p.total_weight();
}

double FutureVisibleConstraint::violation_and_gradient(std::span<const double> values,
                                                       std::span<double> gradient) const {
  std::fill(gradient.begin(), gradient.end(), 0.0);
  return violation(values);
}

}  // namespace sightline::camera
