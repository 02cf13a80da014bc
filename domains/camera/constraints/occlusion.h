// Occlusion: can the camera see the character? Two constraints, both answered by the scene's
// BVH (O(log n) per sight line), both re-parameterised through the frame's parameters.
//
// LookAtVisibleConstraint (hard by default): the segment from the camera to the look-at
// point touches no solid box. Its violation is 0 when clear and 1 when blocked. We do not
// grade it: the quantities a cheap query could add (how far along the sight line the first
// wall is, how much wall the line crosses) do not measure how far the camera is from a
// clear view, so they would steer search in arbitrary directions; a 0/1 violation simply
// ranks blocked candidates below clear ones, which is what a solver needs from it.
//
// BodyVisibilityConstraint (soft): the fraction of the character's body the camera sees,
// estimated with kBodySamples = 9 sight lines: to the centre of the body box and to its 8
// corners pulled 20% of the way in toward the centre (the points centre +- 0.4 x size).
//   - The 8 corners are the fewest points that probe every extreme of the box on all three
//     axes, so a low wall hiding the legs, a beam hiding the head and a pillar hiding one
//     side each remove a different subset and the fraction grades partial occlusion.
//   - Pulling them in keeps them off the faces: a character standing on a floor box or with
//     its back against a wall would otherwise have corners touching that geometry, and since
//     touching counts as blocked they would read as hidden from everywhere.
//   - The centre makes the count odd and weights the body's core; 9 any-hit queries with
//     early exit cost about 9 x O(log n), cheap enough for every candidate of every frame.
// violation = 1 - visible fraction, in {0, 1/9, ..., 1}; cost = weight x violation.
#pragma once

#include <Eigen/Core>
#include <array>

#include "sightline/csp/constraint.h"
#include "sightline/domains/camera/constraints/frame_parameters.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::camera {

constexpr int kBodySamples = 9;

// The sample points of a body box: its centre, then the 8 pulled-in corners.
std::array<Eigen::Vector3d, kBodySamples> body_sample_points(const Aabb& body);
// Fraction of the sample points of `body` that `camera` has a clear line of sight to, in
// `geometry`: a Scene (static geometry only) or a SceneAtTime (movers at its time included).
template <class Geometry>
double visible_fraction(const Geometry& geometry, const Eigen::Vector3d& camera,
                        const Aabb& body) {
  int visible = 0;
  for (const Eigen::Vector3d& p : body_sample_points(body)) {
    visible += geometry.line_of_sight(camera, p);
  }
  return static_cast<double>(visible) / kBodySamples;
}

// Violation 1 when the sight line camera -> look-at point is blocked, else 0.
// Scope (cam_x, cam_y, cam_z). The geometry is the scene at the frame's time (the owner,
// CameraProblem, sets its time with the frame); it must outlive the constraint.
class LookAtVisibleConstraint : public csp::Constraint {
 public:
  LookAtVisibleConstraint(csp::VariableId cam_x, csp::VariableId cam_y, csp::VariableId cam_z,
                          const SceneAtTime& scene, const FrameParameters& frame, double weight = 1,
                          bool hard = true)
      : Constraint({cam_x, cam_y, cam_z}, weight, hard), scene_(&scene), frame_(frame) {}
  std::string_view kind() const override { return "camera.look_at_visible"; }
  double query_cost() const override { return 1; }  // one sight line
  // The geometry the sight line is tested against, at the frame's time (camera-aware
  // solvers use it).
  const SceneAtTime& scene() const { return *scene_; }
  double violation(std::span<const double> values) const override;
  // A step function: its gradient is 0 almost everywhere, which finite differences would
  // estimate as noise at the step; say so instead.
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  bool has_exact_gradient() const override { return true; }

 private:
  const SceneAtTime* scene_;
  FrameParameters frame_;
};

// Violation 1 - visible fraction of the character's body. Scope (cam_x, cam_y, cam_z).
// violation_until stops counting once enough samples are hidden (csp::Constraint::violation_until).
class BodyVisibilityConstraint : public csp::Constraint {
 public:
  BodyVisibilityConstraint(csp::VariableId cam_x, csp::VariableId cam_y, csp::VariableId cam_z,
                           const SceneAtTime& scene, const FrameParameters& frame, double weight)
      : Constraint({cam_x, cam_y, cam_z}, weight), scene_(&scene), frame_(frame) {}
  std::string_view kind() const override { return "camera.visible_fraction"; }
  double query_cost() const override { return 3; }  // nine sight lines
  double violation(std::span<const double> values) const override;
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  bool has_exact_gradient() const override { return true; }
  double violation_until(std::span<const double> values, double cost_before, double bound,
                         double cost_after) const override;

 private:
  const SceneAtTime* scene_;
  FrameParameters frame_;
};

}  // namespace sightline::camera
