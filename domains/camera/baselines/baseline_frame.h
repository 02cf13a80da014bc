// What every game-camera baseline reports the same way as the chase camera, once it has
// decided where to put the camera: the cut flag, the score under this frame's camera
// problem, the controller's own sight-line query and the desired values in force. Shared so
// the spring arm and the pull-forward camera are judged exactly like ChaseCamera.
#pragma once

#include <Eigen/Core>

#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

// Writes frame.position = `position`, frame.target = `look`, and:
//   cut / cut_reason: a move from `previous` longer than `max_step` is a jump the viewer
//     sees as a cut, so it is flagged (CutReason::kTooFast);
//   score: `problem`'s score at `position` (the problem must already be set to this frame,
//     with `previous` as the last camera, so frame coherence measures this move);
//   look_at_visible: problem.scene_at_time().line_of_sight(position, look) (movers count); effective: problem.effective().
// solve_seconds is left to the caller, which times the whole update.
void describe_baseline_frame(const CameraProblem& problem, const Eigen::Vector3d& previous,
                             const Eigen::Vector3d& position, const Eigen::Vector3d& look,
                             double max_step, CameraFrame& frame);

}  // namespace sightline::camera
