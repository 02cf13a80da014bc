// Every registered solver that takes a composition problem, against a fine `grid` on tiny
// shots: the dedicated shot-search never ends above the grid's lattice optimum, and every
// solver's answer is scored by the independent evaluate() exactly as the problem scores it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

// alice at (-1, 0, 0) facing +z, bob at (1, 0, 0) facing -z; a pillar; a small region in
// front of alice, so a 9-point grid over position, yaw and pitch is fine.
Scene tiny_shot(const std::string& properties) {
  return parse_scene(csp::parse_yaml(
      "name: tiny\n"
      "boxes: [{min: [0.2, 0, 2], max: [0.6, 3, 2.4]}]\n"
      "actors:\n"
      "  - {name: alice, trajectory: [{t: 0, position: [-1, 0, 0], yaw: 0}]}\n"
      "  - {name: bob, trajectory: [{t: 0, position: [1, 0, 0], yaw: 180}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-2, 1, 3], max: [1, 2.5, 5]}\n"
      "  properties:\n" + properties,
      "tiny.yaml"));
}

const char* kShots[] = {
    "    - {kind: screen_position, target: alice, at: [0.4, 0.6]}\n"
    "    - {kind: size, target: alice, range: [0.3, 0.4]}\n"
    "    - {kind: angle_horizontal, target: alice, range: [-10, 10]}\n",
    "    - {kind: framed, target: alice, rect: [0, 0, 0.5, 1]}\n"
    "    - {kind: framed, target: bob, rect: [0.5, 0, 1, 1]}\n"
    "    - {kind: visible, target: bob, range: [0.9, 1]}\n"
    "    - {kind: order, targets: [alice, bob]}\n",
    // Not all can be met: alice 1-2 m away, seen from 30-40 degrees above, at (0.7, 0.5).
    "    - {kind: distance, target: alice, range: [1, 2], softness: 5}\n"
    "    - {kind: angle_vertical, target: alice, range: [30, 40]}\n"
    "    - {kind: screen_position, target: alice, at: [0.7, 0.5]}\n"
    "    - {kind: visible, target: alice, hard: true}\n",
};

TEST(CompositionSolvers, EverySolverAgainstAFineGridOnTinyShots) {
  solvers::SolverRegistry& registry = solver_registry();
  register_composition_solvers(registry);
  for (const char* properties : kShots) {
    const Scene scene = tiny_shot(properties);
    const CompositionProblem problem(scene, *scene.shot(), 0);
    solvers::SolveContext context;
    const solvers::SolverResult grid =
        registry.create("grid", {{"points", "9"}})->solve(problem.problem(), csp::Assignment{}, context);
    ASSERT_TRUE(grid.feasible());
    for (const std::string& name : registry.names()) {
      auto solver = registry.create(name);
      if (!solver->unsuitable_reason(problem.problem()).empty() || name == "grid") continue;
      solvers::SolveContext limited;
      limited.limits.time_limit_seconds = 0.05;
      // Local methods start from the middle of the region looking at alice.
      CameraPose middle;
      middle.position = scene.shot()->region.centre();
      middle.look_at = Eigen::Vector3d(-1, 1.5, 0);
      middle.fov = 50;
      middle.aspect = scene.shot()->aspect;
      const solvers::SolverResult r =
          solver->solve(problem.problem(), problem.assignment(middle), limited);
      const ShotEvaluation e = problem.evaluate(problem.pose(r.best));
      // The problem's cost is FORMATS.md's cost of the pose.
      EXPECT_NEAR(r.cost(), e.cost, 1e-9) << name;
      EXPECT_EQ(r.feasible(), e.feasible) << name << ": " << e.why_infeasible;
      std::printf("%-28s cost %.4f (grid %.4f)\n", name.c_str(), r.cost(), grid.cost());
      if (name == "shot-search") {
        EXPECT_TRUE(r.feasible());
        EXPECT_LE(r.cost(), grid.cost() + 1e-9) << properties;
      }
    }
  }
}

TEST(CompositionSolvers, ShotSearchIsDeterministic) {
  register_composition_solvers(solvers::SolverRegistry::global());
  const Scene scene = tiny_shot(kShots[1]);
  const CompositionProblem problem(scene, *scene.shot(), 0);
  auto a = solvers::SolverRegistry::global().create("shot-search")->solve(problem.problem(), {});
  auto b = solvers::SolverRegistry::global().create("shot-search")->solve(problem.problem(), {});
  EXPECT_EQ(a.best, b.best);
}

}  // namespace
}  // namespace sightline::camera
