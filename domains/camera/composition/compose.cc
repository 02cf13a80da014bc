#include "sightline/domains/camera/composition/compose.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sightline::camera {

double earliest_keyframe(const Scene& scene) {
  double t = scene.trajectory().start_time();
  for (const Actor& a : scene.actors()) t = std::min(t, a.trajectory.start_time());
  return t;
}

const Shot& shot_to_compose(const Scene& scene, const std::string& origin) {
  if (!scene.shot()) {
    throw std::invalid_argument(origin + ": the scene has no shot: block to compose "
                                "(FORMATS.md \"Shots\")");
  }
  return *scene.shot();
}

double compose_time(const Scene& scene, std::optional<double> time, const std::string& what) {
  const double t = time ? *time : earliest_keyframe(scene);
  if (!std::isfinite(t)) throw std::invalid_argument(what + ": expected a finite time in seconds");
  return t;
}

CameraPose compose_start(const CompositionProblem& problem) {
  const Shot& shot = problem.shot();
  CameraPose start;
  start.position = shot.region.centre();
  start.look_at = problem.world().people()[static_cast<std::size_t>(
                      problem.targets().front().front())].aim;
  if ((start.look_at - start.position).norm() < 1e-6) start.look_at += Eigen::Vector3d::UnitZ();
  start.fov = (shot.fov.lo + shot.fov.hi) / 2;
  start.roll = std::clamp(0.0, shot.roll.lo, shot.roll.hi);
  start.aspect = shot.aspect;
  return start;
}

Composed compose(const CompositionProblem& problem, solvers::Solver& solver,
                 const solvers::SolveContext& context) {
  if (std::string why = solver.unsuitable_reason(problem.problem()); !why.empty()) {
    throw std::invalid_argument("solver '" + solver.name() + "' cannot compose this shot: " + why);
  }
  Composed out;
  out.result = solver.solve(problem.problem(), problem.assignment(compose_start(problem)), context);
  out.pose = problem.pose(out.result.best);
  out.evaluation = problem.evaluate(out.pose);
  return out;
}

}  // namespace sightline::camera
