// GroupFraming (`group-framing`): the group camera game engines ship, as a baseline for
// tracking shots (like Cinemachine's Group Framing with a follow offset and a deoccluder).
//
// Each frame it aims at the centre of the people the shot wants in the image and stands
// back along a fixed direction far enough that the sphere round their boxes fits the
// vertical field of view (with a 10% margin), then pulls in along that line to just short of
// the first solid it meets from the centre (the spring arm's deoccluder), and moves there
// through a first-order spring (0.2 s) bounded by max_speed; moves beyond it are flagged as
// cuts. The direction is what an engine user would set for the shot: from the first
// target's angle properties (the middle of their ranges), else from their front, 15 degrees
// up. It knows nothing of the shot's other properties.
#pragma once

#include <string>
#include <vector>

#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/composition/composition_problem.h"

namespace sightline::camera {

class GroupFraming : public CameraController {
 public:
  GroupFraming(const Scene& scene, double max_speed);
  std::string name() const override { return "group-framing"; }
  const CameraFrame& update(const CharacterState& character, double dt) override;
  void reset(const Eigen::Vector3d& position) override;
  double max_step(double dt) const override { return max_speed_ * dt; }

 private:
  const Scene* scene_;
  double max_speed_;
  CompositionProblem problem_;  // for the people at the frame's time and the evaluation
  Eigen::Vector3d offset_;      // unit: from the group's centre toward the camera
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  bool started_ = false;
  CameraFrame frame_;
};

}  // namespace sightline::camera
