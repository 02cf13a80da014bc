// FutureVisibleConstraint ("camera.future_visible"): is the character's predicted look-at
// point visible from the candidate over the coming second? The anticipating camera's
// constraint (profile block `anticipation:`), after Burg, Lino and Christie (2020), who keep
// the character's future positions visible over a time window.
//
// With the K predictions of MotionPrediction (look-at point L_k at ahead_k seconds, its
// weight w_k = exp(-ahead_k / decay), and the geometry G_k at that time, movers included):
//
//   violation(camera) = sum_k w_k [segment camera -> L_k blocked in G_k] / sum_k w_k
//
// in [0, 1]; cost = weight x violation. Each predicted point is tested from the candidate
// position itself, not from where the camera will be then: a candidate that already sees
// where the character is going is one the camera can hold through the turn, which is what
// moving early means. Soft (a prediction is a guess; it must never make a frame infeasible),
// and like the look-at constraint a step function: its gradient is 0 almost everywhere,
// reported as exact so no solver estimates noise at the steps. K sight lines per candidate
// (fewer through violation_until when a search only needs to know it lost), no allocation. With lookahead none the prediction is empty and the violation is 0.
// Scope (cam_x, cam_y, cam_z). The prediction must outlive the constraint; its owner
// (CameraProblem) updates it each frame.
#pragma once

#include "sightline/csp/constraint.h"
#include "sightline/domains/camera/motion_prediction.h"

namespace sightline::camera {

class FutureVisibleConstraint : public csp::Constraint {
 public:
  FutureVisibleConstraint(csp::VariableId cam_x, csp::VariableId cam_y, csp::VariableId cam_z,
                          const MotionPrediction& prediction, double weight)
      : Constraint({cam_x, cam_y, cam_z}, weight), prediction_(&prediction) {}
  std::string_view kind() const override { return "camera.future_visible"; }
  double query_cost() const override { return 2; }  // K sight lines, asked as one packet
  const MotionPrediction& prediction() const { return *prediction_; }
  double violation(std::span<const double> values) const override;
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  bool has_exact_gradient() const override { return true; }
  // Stops once the hidden samples' weight is enough (csp::Constraint::violation_until).
  double violation_until(std::span<const double> values, double cost_before, double bound,
                         double cost_after) const override;

 private:
  // The loop of both: stops early only when `bounded`.
  double hidden_fraction(std::span<const double> values, bool bounded, double cost_before,
                         double bound, double cost_after) const;

  const MotionPrediction* prediction_;
};

}  // namespace sightline::camera
