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
#include <utility>
#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/domains/camera/constraints/cost_terms.h"
#include "sightline/domains/camera/constraints/frame_parameters.h"

namespace sightline::camera {

// What the four share: violation = |term(the scope's values)|, with the functor that
// Derived::term() builds from this frame's parameters, and exact gradients (plain and
// smoothed) from the same functor with ceres::Jet. N is the scope's size. The gradient
// members are defined and instantiated for the four in gradients.cc.
template <class Derived, int N>
class AbsTermConstraint : public csp::Constraint {
 public:
  AbsTermConstraint(std::vector<csp::VariableId> scope, const FrameParameters& frame, double weight)
      : Constraint(std::move(scope), weight), frame_(frame) {}
  double violation(std::span<const double> values) const override {
    double x[N];
    for (int i = 0; i < N; ++i) x[i] = values[scope()[i]];
    return std::abs(static_cast<const Derived&>(*this).term()(x));
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  double smooth_violation_and_gradient(std::span<const double> values, std::span<double> gradient,
                                       double smoothing) const override;

 protected:
  FrameParameters frame_;
};

// cost = weight x |desired_height - (cam_y - char_y)|; scope (cam_y).
class HeightConstraint : public AbsTermConstraint<HeightConstraint, 1> {
 public:
  HeightConstraint(csp::VariableId cam_y, const FrameParameters& frame, double weight)
      : AbsTermConstraint({cam_y}, frame, weight) {}
  std::string_view kind() const override { return "camera.height"; }
  terms::HeightTerm term() const { return {frame_.char_y.value(), frame_.desired_height.value()}; }
};

// cost = weight x |desired_distance - horizontal distance(camera, character)|;
// scope (cam_x, cam_z).
class DistanceConstraint : public AbsTermConstraint<DistanceConstraint, 2> {
 public:
  DistanceConstraint(csp::VariableId cam_x, csp::VariableId cam_z, const FrameParameters& frame,
                     double weight)
      : AbsTermConstraint({cam_x, cam_z}, frame, weight) {}
  std::string_view kind() const override { return "camera.distance"; }
  terms::DistanceTerm term() const {
    return {frame_.char_x.value(), frame_.char_z.value(), frame_.desired_distance.value()};
  }
};

// cost = weight x |desired_orientation - angle(facing, camera -> character)| in degrees;
// scope (cam_x, cam_z).
class OrientationConstraint : public AbsTermConstraint<OrientationConstraint, 2> {
 public:
  OrientationConstraint(csp::VariableId cam_x, csp::VariableId cam_z, const FrameParameters& frame,
                        double weight)
      : AbsTermConstraint({cam_x, cam_z}, frame, weight) {}
  std::string_view kind() const override { return "camera.orientation"; }
  terms::OrientationTerm term() const {
    return {frame_.char_x.value(), frame_.char_z.value(), frame_.char_yaw.value(),
            frame_.desired_orientation.value()};
  }
};

// cost = weight x |camera - last camera| / dt (the term is a length, so |r| = r);
// scope (cam_x, cam_y, cam_z).
class FrameCoherenceConstraint : public AbsTermConstraint<FrameCoherenceConstraint, 3> {
 public:
  FrameCoherenceConstraint(csp::VariableId cam_x, csp::VariableId cam_y, csp::VariableId cam_z,
                           const FrameParameters& frame, double weight)
      : AbsTermConstraint({cam_x, cam_y, cam_z}, frame, weight) {}
  std::string_view kind() const override { return "camera.frame_coherence"; }
  terms::FrameCoherenceTerm term() const {
    return {frame_.last_cam_x.value(), frame_.last_cam_y.value(), frame_.last_cam_z.value(),
            frame_.dt.value()};
  }
};

}  // namespace sightline::camera
