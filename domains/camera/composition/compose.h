// Composing one shot at one instant (FORMATS.md "The compose command"), as a library call:
// the `compose` command and the Python module are its clients. The solver starts from the
// middle of the shot's region looking at its first target, at the middle of the fov range
// and the roll nearest 0; the pose found is judged by the shot's measures.
#pragma once

#include <optional>
#include <string>

#include "sightline/domains/camera/composition/camera_pose.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/solvers/solver.h"

namespace sightline::camera {

// FORMATS.md: the default time of a shot, the earliest keyframe of any actor (or of the
// character).
double earliest_keyframe(const Scene& scene);
// The scene's shot: block; std::invalid_argument naming `origin` (its file) when it has none.
const Shot& shot_to_compose(const Scene& scene, const std::string& origin);
// The time to compose at: `time`, or the earliest keyframe when it is not given;
// std::invalid_argument naming `what` (the option that gave it) when it is not finite.
double compose_time(const Scene& scene, std::optional<double> time, const std::string& what);

// The pose the solvers start from (see above).
CameraPose compose_start(const CompositionProblem& problem);

struct Composed {
  CameraPose pose;
  ShotEvaluation evaluation;
  solvers::SolverResult result;
};

// Solves `problem` with `solver` within `context`'s limits and judges the pose found.
// Throws std::invalid_argument when the solver cannot take composition problems.
Composed compose(const CompositionProblem& problem, solvers::Solver& solver,
                 const solvers::SolveContext& context);

}  // namespace sightline::camera
