// The pose file `compose` writes (FORMATS.md "Shots"): a JSON object with the pose
// ({"position": [x, y, z], "look_at": [x, y, z], "roll": r, "fov": f, "aspect": a}) and,
// after it, how the pose does on the shot: feasibility, satisfaction, cost, and each
// property's measured value and score (a measure that is infinite or undefined is null).
#pragma once

#include <string>

#include "sightline/domains/camera/composition/camera_pose.h"
#include "sightline/domains/camera/composition/composition_problem.h"

namespace sightline::camera {

struct PoseFileExtras {
  double time = 0;          // the shot's time, seconds
  std::string solver;       // which solver found it
  double solve_seconds = 0;
};

std::string pose_json(const CameraPose& pose, const CompositionProblem& problem,
                      const ShotEvaluation& evaluation, const PoseFileExtras& extras);

}  // namespace sightline::camera
