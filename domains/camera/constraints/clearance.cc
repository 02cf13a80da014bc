#include "sightline/domains/camera/constraints/clearance.h"

#include <algorithm>

namespace sightline::camera {

Eigen::Vector3d signed_distance_gradient(const Aabb& box, const Eigen::Vector3d& p) {
  const Eigen::Vector3d nearest = p.cwiseMax(box.min).cwiseMin(box.max);
  const Eigen::Vector3d away = p - nearest;
  const double norm = away.norm();
  if (norm > 0) return away / norm;  // outside: d = |p - nearest point|
  // Inside: d = -(distance to the nearest face); moving toward that face raises d by 1 per
  // metre, so the gradient is that face's outward normal.
  int axis = 0;
  double sign = -1;
  double best = INFINITY;
  for (int i = 0; i < 3; ++i) {
    if (p[i] - box.min[i] < best) {
      best = p[i] - box.min[i];
      axis = i;
      sign = -1;
    }
    if (box.max[i] - p[i] < best) {
      best = box.max[i] - p[i];
      axis = i;
      sign = 1;
    }
  }
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  g[axis] = sign;
  return g;
}

double ClearanceConstraint::violation(std::span<const double> values) const {
  const double r = frame_.clearance_radius.value();
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  return std::max(0.0, r - scene_->clearance(camera, r));
}

double ClearanceConstraint::evaluate(std::span<const double> values, std::span<double> gradient,
                                     double smoothing) const {
  std::fill(gradient.begin(), gradient.end(), 0.0);
  const double r = frame_.clearance_radius.value();
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  const auto nearest = scene_->nearest_surface(camera, r);
  if (!nearest) return 0.0;  // nothing within r: satisfied, flat
  const double excess = r - nearest->signed_distance;  // > 0
  const double value = smoothing > 0 ? csp::smooth_hinge(excess, smoothing) : excess;
  const double slope = smoothing > 0 ? csp::smooth_hinge_slope(excess, smoothing) : 1.0;
  const Eigen::Vector3d g = -slope * nearest->gradient;
  for (int i = 0; i < 3; ++i) gradient[i] = g[i];
  return value;
}

double ClearanceConstraint::violation_and_gradient(std::span<const double> values,
                                                   std::span<double> gradient) const {
  return evaluate(values, gradient, 0);
}

double ClearanceConstraint::smooth_violation_and_gradient(std::span<const double> values,
                                                          std::span<double> gradient,
                                                          double smoothing) const {
  return evaluate(values, gradient, smoothing);
}

}  // namespace sightline::camera
