// A composition problem's foresight (composition_problem.h): the shot's framed and visible
// properties scored again where the people will be, the camera carried along with them.
// Checked on a walker about to pass behind a pillar: a pose that sees her now but not in a
// second costs more than one that sees her both times, by the foresight term alone; the
// shift is her displacement; FORMATS.md's verdict (evaluate) never counts foresight; and
// evaluate_into gives evaluate's answer while reusing its storage.
#include <gtest/gtest.h>

#include <random>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

// ann walks along +x at 1 m/s; a 2 m pillar stands 2 m in front of her path at x = -1.
const Scene& walker_scene() {
  static const Scene scene = parse_scene(csp::parse_yaml(
      "name: walker\n"
      "boxes:\n"
      "  - {name: pillar, min: [-1.2, 0, -2.2], max: [-0.8, 2, -1.8]}\n"
      "actors:\n"
      "  - name: ann\n"
      "    trajectory:\n"
      "      - {t: 0, position: [-2, 0, 0], yaw: 90}\n"
      "      - {t: 10, position: [8, 0, 0], yaw: 90}\n"
      "shot:\n"
      "  region: {min: [-10, 0.5, -10], max: [10, 8, -1]}\n"
      "  properties:\n"
      "    - {kind: visible, target: ann}\n",
      "walker.yaml"));
  return scene;
}

CameraPose looking_at_ann(const Eigen::Vector3d& from) {
  CameraPose p;
  p.position = from;
  p.look_at = Eigen::Vector3d(-2, 0.9, 0);
  p.fov = 50;
  p.aspect = 16.0 / 9.0;
  return p;
}

TEST(Foresight, APoseAboutToLoseSomeoneCostsMoreThanOneThatKeepsThem) {
  const Scene& scene = walker_scene();
  CompositionProblem now(scene, *scene.shot(), 0);
  CompositionProblem ahead(scene, *scene.shot(), 0, Foresight{{1.0}, 1.0});
  ASSERT_EQ(ahead.problem().num_constraints(), now.problem().num_constraints() + 1);
  // Carried along with ann: 1 m along +x in one second.
  EXPECT_NEAR(ahead.future_shift(0).x(), 1.0, 1e-9);
  EXPECT_NEAR(ahead.future_shift(0).z(), 0.0, 1e-9);
  // Low and straight in front: clear now; in a second the pillar is on the sight line.
  const CameraPose low = looking_at_ann({-2, 1.5, -5});
  // High: over the pillar now and in a second.
  const CameraPose high = looking_at_ann({-2, 6, -5});
  for (const CameraPose* p : {&low, &high}) {
    EXPECT_EQ(now.evaluate(*p).scores[0], 1.0);
    EXPECT_EQ(ahead.evaluate(*p).satisfaction, now.evaluate(*p).satisfaction);  // the verdict ignores foresight
  }
  const double low_now = now.problem().score(now.assignment(low)).soft;
  const double high_now = now.problem().score(now.assignment(high)).soft;
  EXPECT_EQ(low_now, 0);
  EXPECT_EQ(high_now, 0);
  const double low_ahead = ahead.problem().score(ahead.assignment(low)).soft;
  const double high_ahead = ahead.problem().score(ahead.assignment(high)).soft;
  EXPECT_EQ(high_ahead, 0);
  EXPECT_GT(low_ahead, 0.3);  // most of her samples are behind the pillar in a second
  // Independently: from the low pose shifted 1 m, the segment to her middle at t = 1 enters
  // the pillar.
  ahead.set_time(1);
  EXPECT_FALSE(ahead.world().clear(Eigen::Vector3d(-1, 1.5, -5), Eigen::Vector3d(-1, 0.9, 0), -1));
}

TEST(Foresight, EvaluateIntoGivesEvaluatesAnswer) {
  const Scene& scene = walker_scene();
  const CompositionProblem problem(scene, *scene.shot(), 0.5);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  ShotEvaluation reused;
  for (int trial = 0; trial < 200; ++trial) {
    const CameraPose p = looking_at_ann({9 * u(rng), 4 + 4 * u(rng), -5 + 6 * u(rng)});
    const ShotEvaluation fresh = problem.evaluate(p);
    problem.evaluate_into(p, reused);
    EXPECT_EQ(reused.feasible, fresh.feasible);
    EXPECT_EQ(reused.satisfaction, fresh.satisfaction);
    EXPECT_EQ(reused.scores, fresh.scores);
    EXPECT_EQ(reused.why_infeasible, fresh.why_infeasible);
    EXPECT_EQ(reused.clearance, fresh.clearance);
  }
}

}  // namespace
}  // namespace sightline::camera
