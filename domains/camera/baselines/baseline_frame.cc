#include "sightline/domains/camera/baselines/baseline_frame.h"

namespace sightline::camera {

void describe_baseline_frame(const CameraProblem& problem, const Eigen::Vector3d& previous,
                             const Eigen::Vector3d& position, const Eigen::Vector3d& look,
                             double max_step, CameraFrame& frame) {
  frame.position = position;
  frame.target = look;
  frame.solver_target = position;
  frame.cut = (position - previous).norm() > max_step * (1 + 1e-9);
  frame.cut_reason = frame.cut ? CutReason::kTooFast : CutReason::kNone;
  const double values[3] = {position.x(), position.y(), position.z()};
  frame.score = problem.problem().score(values);
  frame.look_at_visible = problem.scene_at_time().line_of_sight(position, look);
  frame.effective = problem.effective();
}

}  // namespace sightline::camera
