#include "sightline/domains/camera/constraints/future_visibility.h"

#include <algorithm>
#include <array>

namespace sightline::camera {

double FutureVisibleConstraint::hidden_fraction(std::span<const double> values, bool bounded,
                                                double cost_before, double bound,
                                                double cost_after) const {
  const MotionPrediction& p = *prediction_;
  if (p.size() == 0) return 0.0;
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  // The hidden weights are summed in sample order; a prefix of that sum is a lower bound of
  // the whole (adding non-negative terms never rounds down below a partial sum).
  double hidden = 0;
  if (p.geometry(0).packs_sight_lines()) {
    // A level: the K sight lines leave one point toward the character's path, so its
    // triangles answer them as one packet (the static geometry is the same at every sample's
    // time), and each sample's movers are asked for its own line. All K are traced, so
    // there is nothing to stop early: the full sum, in the same order.
    std::array<Eigen::Vector3d, Anticipation::kMaxSamples> ends;
    for (int k = 0; k < p.size(); ++k) ends[static_cast<std::size_t>(k)] = p.sample(k).look_at;
    const std::uint32_t blocked = p.geometry(0).static_blocked(
        camera, std::span<const Eigen::Vector3d>(ends.data(), static_cast<std::size_t>(p.size())));
    for (int k = 0; k < p.size(); ++k) {
      if ((blocked >> k & 1u) != 0 || p.geometry(k).mover_blocks(camera, p.sample(k).look_at)) {
        hidden += p.sample(k).weight;
      }
    }
    return hidden / p.total_weight();
  }
  for (int k = 0; k < p.size(); ++k) {
    if (p.geometry(k).line_of_sight(camera, p.sample(k).look_at)) continue;
    hidden += p.sample(k).weight;
    if (bounded && (cost_before + weight() * (hidden / p.total_weight())) + cost_after >= bound) {
      break;
    }
  }
  return hidden / p.total_weight();
}

double FutureVisibleConstraint::violation(std::span<const double> values) const {
  return hidden_fraction(values, false, 0, 0, 0);
}

double FutureVisibleConstraint::violation_until(std::span<const double> values,
                                                double cost_before, double bound,
                                                double cost_after) const {
  return hidden_fraction(values, true, cost_before, bound, cost_after);
}

double FutureVisibleConstraint::violation_and_gradient(std::span<const double> values,
                                                       std::span<double> gradient) const {
  std::fill(gradient.begin(), gradient.end(), 0.0);
  return violation(values);
}

}  // namespace sightline::camera
