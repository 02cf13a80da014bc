// The four smooth camera constraints of Bourne & Sattar (thesis tables 5-7): height,
// distance, orientation and frame coherence, as ordinary csp::Constraints.
//
// Each is soft, costs weight x |r| with r the residual of its functor in cost_terms.h (the
// equations are written there), and reads the frame from the problem's parameters, so the
// same constraint objects serve every frame. Scopes are as small as the equations allow
// (height reads only cam_y), which keeps one-variable deltas cheap for local search.
// Exact gradients come from the same functors with ceres::Jet (gradients.cc); the smooth
// stand-in for gradient-based solvers is smooth_abs(r, s) (see csp/constraint.h).
#pragma once

#include <cmath>

#include "csp/constraint.h"
#include "domains/camera/constraints/cost_terms.h"
#include "domains/camera/constraints/frame_parameters.h"

namespace sightline::camera {

// cost = weight x |desired_height - (cam_y - char_y)|; scope (cam_y).
class HeightConstraint : public csp::Constraint {
 public:
  HeightConstraint(csp::VariableId cam_y, const FrameParameters& frame, double weight)
      : Constraint({cam_y}, weight), frame_(frame) {}
  std::string_view kind() const override { return "camera.height"; }
  terms::HeightTerm term() const {
    return {frame_.char_y.value(), frame_.desired_height.value()};
  }
  double violation(std::span<const double> values) const override {
    const double y = values[scope()[0]];
    return std::abs(term()(&y));
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  double smooth_violation_and_gradient(std::span<const double> values, std::span<double> gradient,
                                       double smoothing) const override;

 private:
  FrameParameters frame_;
};

// cost = weight x |desired_distance - horizontal distance(camera, character)|;
// scope (cam_x, cam_z).
class DistanceConstraint : public csp::Constraint {
 public:
  DistanceConstraint(csp::VariableId cam_x, csp::VariableId cam_z, const FrameParameters& frame,
                     double weight)
      : Constraint({cam_x, cam_z}, weight), frame_(frame) {}
  std::string_view kind() const override { return "camera.distance"; }
  terms::DistanceTerm term() const {
    return {frame_.char_x.value(), frame_.char_z.value(), frame_.desired_distance.value()};
  }
  double violation(std::span<const double> values) const override {
    const double xz[2] = {values[scope()[0]], values[scope()[1]]};
    return std::abs(term()(xz));
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  double smooth_violation_and_gradient(std::span<const double> values, std::span<double> gradient,
                                       double smoothing) const override;

 private:
  FrameParameters frame_;
};

// cost = weight x |desired_orientation - angle(facing, camera -> character)| in degrees;
// scope (cam_x, cam_z).
class OrientationConstraint : public csp::Constraint {
 public:
  OrientationConstraint(csp::VariableId cam_x, csp::VariableId cam_z,
                        const FrameParameters& frame, double weight)
      : Constraint({cam_x, cam_z}, weight), frame_(frame) {}
  std::string_view kind() const override { return "camera.orientation"; }
  terms::OrientationTerm term() const {
    return {frame_.char_x.value(), frame_.char_z.value(), frame_.char_yaw.value(),
            frame_.desired_orientation.value()};
  }
  double violation(std::span<const double> values) const override {
    const double xz[2] = {values[scope()[0]], values[scope()[1]]};
    return std::abs(term()(xz));
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  double smooth_violation_and_gradient(std::span<const double> values, std::span<double> gradient,
                                       double smoothing) const override;

 private:
  FrameParameters frame_;
};

// cost = weight x |camera - last camera| / dt; scope (cam_x, cam_y, cam_z).
class FrameCoherenceConstraint : public csp::Constraint {
 public:
  FrameCoherenceConstraint(csp::VariableId cam_x, csp::VariableId cam_y, csp::VariableId cam_z,
                           const FrameParameters& frame, double weight)
      : Constraint({cam_x, cam_y, cam_z}, weight), frame_(frame) {}
  std::string_view kind() const override { return "camera.frame_coherence"; }
  terms::FrameCoherenceTerm term() const {
    return {frame_.last_cam_x.value(), frame_.last_cam_y.value(), frame_.last_cam_z.value(),
            frame_.dt.value()};
  }
  double violation(std::span<const double> values) const override {
    const double p[3] = {values[scope()[0]], values[scope()[1]], values[scope()[2]]};
    return term()(p);
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  double smooth_violation_and_gradient(std::span<const double> values, std::span<double> gradient,
                                       double smoothing) const override;

 private:
  FrameParameters frame_;
};

}  // namespace sightline::camera
