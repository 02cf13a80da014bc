// PullForward: the other camera games ship, as Cinemachine's deoccluder (CinemachineDeoccluder,
// formerly CinemachineCollider) does with its PullCameraForward strategy: a baseline the
// constraint camera is measured against.
//
// The camera's preferred spot is the profile's (desired height, distance and orientation
// behind the facing, so every controller aims for the same shot). Each frame:
//   1. obstacle query: a ray from the look-at point (starting `minimum_distance_from_target`
//      out, so the character's own surroundings are ignored) toward the preferred spot; at
//      the first box it hits the camera is pulled in front of it (a hair short: `slush`);
//   2. camera radius: while the corrected spot is nearer than `camera_radius` to a box it is
//      pulled further along the same line toward the target (never nearer than the minimum
//      distance). Cinemachine pushes out along the obstacle's normal instead; along the line
//      keeps the spot on the clear part of the sight line;
//   3. damping: the correction c = corrected - preferred is eased in, as Cinemachine's Damper:
//        c_shown += (c - c_shown) x (1 - exp(-ln(100) x dt / T)),
//      T = damping_when_occluded while the correction grows (pulling in), `damping` while it
//      shrinks (returning); after T seconds 99% of a step is done. T = 0: no damping.
// The camera looks at the look-at point. A damped pull-in leaves the camera behind the
// obstacle for a few frames: that is how the shipped camera behaves. Moves longer than
// max_speed x dt are flagged as cuts (CutReason::kTooFast).
#pragma once

#include <Eigen/Core>
#include <string>

#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

struct PullForwardOptions {
  double camera_radius = 0.2;                  // m: kept from obstacles; the thesis' clearance
  double minimum_distance_from_target = 0.2;   // m: obstacles nearer the target are ignored
  double damping = 0.5;                        // s: easing back out after a correction
  double damping_when_occluded = 0.2;          // s: easing in front of an obstacle
  double slush = 1e-3;                         // m: stop this short of a hit (Cinemachine's)
  double max_speed = 8.0;                      // m/s: longer moves are flagged as cuts
  // Empty when usable, else which field is wrong and why.
  std::string validate() const;
};

class PullForward : public CameraController {
 public:
  // `scene` and `profile` must outlive the camera. Throws std::invalid_argument for options
  // or a profile that do not validate().
  PullForward(const Scene& scene, const CameraProfile& profile, PullForwardOptions options = {});
  std::string name() const override { return "pull-forward"; }
  const CameraFrame& update(const CharacterState& character, double dt) override;
  // Puts the camera at `position`; the damped correction restarts at the next update.
  void reset(const Eigen::Vector3d& position) override;
  double max_step(double dt) const override { return options_.max_speed * dt; }

  const PullForwardOptions& options() const { return options_; }
  const CameraFrame& frame() const { return frame_; }
  // This frame's preferred spot, and where the obstacle query (steps 1 and 2) put it.
  const Eigen::Vector3d& preferred() const { return preferred_; }
  const Eigen::Vector3d& corrected() const { return corrected_; }
  // True when this frame's obstacle query found the preferred spot's sight line blocked.
  bool occluded() const { return occluded_; }

 private:
  Eigen::Vector3d pull_in_front(const Eigen::Vector3d& preferred, const Eigen::Vector3d& look);

  const Scene* scene_;
  const CameraProfile* profile_;
  PullForwardOptions options_;
  CameraProblem problem_;
  bool first_update_ = true;
  Eigen::Vector3d shown_correction_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d preferred_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d corrected_ = Eigen::Vector3d::Zero();
  bool occluded_ = false;
  CameraFrame frame_;
};

}  // namespace sightline::camera
