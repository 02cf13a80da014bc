// The exact two-subject solver (`toric`, Lino & Christie 2012): on random feasible cases
// (two people, a camera that sees them, with roll 0, at screen points; the shot asks for
// exactly those points) it puts both subjects within 0.001 screen units of their points,
// as measured by the shot's own definitions.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <sstream>
#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

TEST(ToricFraming, PutsBothSubjectsOnTheirPointsOnRandomFeasibleCases) {
  register_composition_solvers(solvers::SolverRegistry::global());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int cases = 0, attempts = 0;
  double worst = 0;
  while (cases < 60 && attempts < 2000) {
    ++attempts;
    const Eigen::Vector3d feet_a(4 * u(rng), 0.5 * (u(rng) + 1), 4 * u(rng));
    const Eigen::Vector3d feet_b = feet_a + Eigen::Vector3d(3 * u(rng), 0.3 * u(rng), 3 * u(rng));
    if ((feet_b - feet_a).norm() < 0.8) continue;
    const Eigen::Vector3d mid = (feet_a + feet_b) / 2 + Eigen::Vector3d(0, 1.5, 0);
    const Eigen::Vector3d dir = Eigen::Vector3d(u(rng), 0.4 * u(rng), u(rng)).normalized();
    CameraPose truth;
    truth.position = mid + (4 + 4 * (u(rng) + 1)) * dir;
    truth.look_at = mid + Eigen::Vector3d(0.5 * u(rng), 0.3 * u(rng), 0.5 * u(rng));
    truth.fov = 50;
    const std::optional<View> view = View::of(truth);
    if (!view) continue;
    const auto sa = view->project(feet_a + Eigen::Vector3d(0, 1.5, 0));
    const auto sb = view->project(feet_b + Eigen::Vector3d(0, 1.5, 0));
    auto inside = [](const std::optional<Eigen::Vector2d>& s) {
      return s && s->minCoeff() > 0.05 && s->maxCoeff() < 0.95;
    };
    if (!inside(sa) || !inside(sb) || (*sa - *sb).norm() < 0.05) continue;
    std::ostringstream yaml;
    yaml.precision(17);
    yaml << "name: toric\nactors:\n"
         << "  - {name: a, trajectory: [{t: 0, position: [" << feet_a.x() << ", " << feet_a.y()
         << ", " << feet_a.z() << "], yaw: 0}]}\n"
         << "  - {name: b, trajectory: [{t: 0, position: [" << feet_b.x() << ", " << feet_b.y()
         << ", " << feet_b.z() << "], yaw: 0}]}\n"
         << "shot:\n  fov: 50\n  region: {min: [-40, -20, -40], max: [40, 30, 40]}\n"
         << "  properties:\n"
         << "    - {kind: screen_position, target: a, at: [" << sa->x() << ", " << sa->y() << "]}\n"
         << "    - {kind: screen_position, target: b, at: [" << sb->x() << ", " << sb->y() << "]}\n";
    const Scene scene = parse_scene(csp::parse_yaml(yaml.str(), "toric.yaml"));
    const CompositionProblem problem(scene, *scene.shot(), 0);
    const auto solver = solvers::SolverRegistry::global().create("toric");
    ASSERT_EQ(solver->unsuitable_reason(problem.problem()), "");
    const solvers::SolverResult r = solver->solve(problem.problem(), {});
    const ShotEvaluation e = problem.evaluate(problem.pose(r.best));
    ASSERT_TRUE(e.feasible) << e.why_infeasible << "\n" << yaml.str();
    EXPECT_EQ(problem.pose(r.best).roll, 0);
    EXPECT_LE(e.measures[0], 0.001) << yaml.str();
    EXPECT_LE(e.measures[1], 0.001) << yaml.str();
    worst = std::max({worst, e.measures[0], e.measures[1]});
    ++cases;
  }
  EXPECT_EQ(cases, 60);
  std::printf("%d cases, worst screen error %.3g\n", cases, worst);
}

TEST(ToricFraming, RefusesAShotWithoutTwoScreenPositions) {
  register_composition_solvers(solvers::SolverRegistry::global());
  const Scene scene = parse_scene(csp::parse_yaml(
      "name: one\nactors:\n  - {name: a, trajectory: [{t: 0, position: [0, 0, 0], yaw: 0}]}\n"
      "shot:\n  region: {min: [-5, 0, -5], max: [5, 3, 5]}\n"
      "  properties: [{kind: screen_position, target: a, at: [0.5, 0.5]}]\n",
      "one.yaml"));
  const CompositionProblem problem(scene, *scene.shot(), 0);
  EXPECT_NE(solvers::SolverRegistry::global().create("toric")->unsuitable_reason(problem.problem()),
            "");
}

}  // namespace
}  // namespace sightline::camera
