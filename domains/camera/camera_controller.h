// CameraController: what anything that moves a game camera each frame offers, so the
// constraint camera and the baselines games ship (spring arm, pull-forward) run through the
// same experiments, traces and metrics.
//
// It sits in the camera domain, below both implementations: the constraint camera
// (control/) and the baselines (baselines/); experiments/runs/controllers.h creates either
// by name.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "sightline/csp/score.h"
#include "sightline/domains/camera/area_profile_switch.h"
#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/domains/camera/trajectory.h"

namespace sightline::camera {

enum class CutReason {
  kNone, kLeftEnclosedArea, kBackedUpToObstacle, kVisibilityLost, kStuck,
  kTooFast  // a baseline moved further than smooth motion allows in one frame
};
const char* to_string(CutReason reason);

struct CameraFrame {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // where the camera is this frame
  Eigen::Vector3d target = Eigen::Vector3d::Zero();    // the look-at point it aims at
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  Eigen::Vector3d solver_target = Eigen::Vector3d::Zero();  // where the method wanted it
  bool cut = false;
  CutReason cut_reason = CutReason::kNone;
  csp::Score score;             // of `position`, under this frame's camera problem
  bool look_at_visible = true;  // the controller's own sight-line query
  double solve_seconds = 0;     // the whole update
  // The lens, for a camera that composes shots (0 when the controller has no lens of its
  // own: the chase camera's fov is the viewer's).
  double fov = 0, roll = 0;     // degrees
  EffectiveProfile effective;   // desired values in force
};

class CameraController {
 public:
  virtual ~CameraController() = default;
  virtual std::string name() const = 0;
  // One frame; dt > 0 seconds since the previous one.
  virtual const CameraFrame& update(const CharacterState& character, double dt) = 0;
  // Puts the camera at `position`, at rest.
  virtual void reset(const Eigen::Vector3d& position) = 0;
  // The largest move a frame of length dt makes without being a cut.
  virtual double max_step(double dt) const = 0;
};

}  // namespace sightline::camera
