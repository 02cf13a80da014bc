// SpringArm: the camera most third-person games ship, as Unreal's USpringArmComponent builds
// it: a baseline the constraint camera is measured against.
//
// The arm hangs from a pivot (the character's look-at point plus `target_offset`) toward the
// profile's preferred spot (desired height, distance and orientation behind the facing, so
// every controller aims for the same shot). Each frame:
//   1. camera lag: the arm's end follows with exponential lag, as Unreal's VInterpTo does,
//        lagged_pivot += (pivot - lagged_pivot) x min(1, lag_speed x dt)   (per substep of at
//        most 1/60 s), and the arm's yaw likewise (rotation lag, RInterpTo on the shorter
//        arc); the desired end = lagged_pivot + arm(lagged_yaw);
//   2. probe: a sphere of `probe_radius` is swept from the real (unlagged) pivot to the
//      desired end; at the first blocking contact the camera goes to the sphere's centre
//      there (for a wall faced squarely: the wall's distance along the arm minus the radius).
//      The pull-in is immediate, never lagged: lag applies to the arm, not to collisions.
// The camera always looks at the look-at point. Pull-ins and releases are real jumps: any
// move longer than max_speed x dt is flagged as a cut (CutReason::kTooFast).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "sightline/domains/camera/baselines/sphere_probe.h"
#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

struct SpringArmOptions {
  double probe_radius = 0.2;          // m: Unreal's ProbeSize; the thesis' clearance radius
  double lag_speed = 10.0;            // 1/s: Unreal's CameraLagSpeed; 0 = no position lag
  double rotation_lag_speed = 10.0;   // 1/s: CameraRotationLagSpeed; 0 = no rotation lag
  Eigen::Vector3d target_offset = Eigen::Vector3d::Zero();  // m, world: pivot - look-at point
  double max_speed = 8.0;             // m/s: longer moves are flagged as cuts (as ChaseCamera)
  // Empty when usable, else which field is wrong and why.
  std::string validate() const;
};

class SpringArm : public CameraController {
 public:
  // `scene` and `profile` must outlive the arm. Throws std::invalid_argument for options that
  // do not validate() or a profile that does not.
  SpringArm(const Scene& scene, const CameraProfile& profile, SpringArmOptions options = {});
  std::string name() const override { return "spring-arm"; }
  const CameraFrame& update(const CharacterState& character, double dt) override;
  // Puts the camera at `position`; the arm's lag state restarts at the next update.
  void reset(const Eigen::Vector3d& position) override;
  double max_step(double dt) const override { return options_.max_speed * dt; }

  const SpringArmOptions& options() const { return options_; }
  const CameraFrame& frame() const { return frame_; }
  // This frame's pivot (the sweep's start) and the arm's lagged, unobstructed end.
  const Eigen::Vector3d& pivot() const { return pivot_; }
  const Eigen::Vector3d& desired_end() const { return desired_end_; }
  // True when the probe pulled the camera in this frame.
  bool pulled_in() const { return pulled_in_; }

 private:
  const Scene* scene_;
  const CameraProfile* profile_;
  SpringArmOptions options_;
  CameraProblem problem_;
  SphereProbe probe_;
  bool first_update_ = true;
  Eigen::Vector3d lagged_pivot_ = Eigen::Vector3d::Zero();
  double lagged_yaw_ = 0;  // degrees
  Eigen::Vector3d pivot_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d desired_end_ = Eigen::Vector3d::Zero();
  bool pulled_in_ = false;
  CameraFrame frame_;
};

}  // namespace sightline::camera
