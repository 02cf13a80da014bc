// The camera problem: built once from a scene and a profile, re-parameterised every frame;
// its costs are the weighted violations computed by hand; profile extras take part; and the
// generic solvers can work on it.
#include "sightline/domains/camera/camera_problem.h"

#include <gtest/gtest.h>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/solvers/registry.h"

namespace sightline::camera {
namespace {

Scene open_scene() {
  return Scene("open", {}, {}, {}, Trajectory({{0, {0, 0, 0}, 0}, {1, {0, 0, 1}, 0}}));
}

CharacterState standing(Eigen::Vector3d feet, double yaw) {
  CharacterState s;
  s.position = feet;
  s.yaw = yaw;
  return s;
}

TEST(CameraProblem, HasTheCameraVariablesAndTheProfilesConstraints) {
  const Scene scene = open_scene();
  const CameraProfile profile;
  const CameraProblem cp(scene, profile);
  const csp::Problem& p = cp.problem();
  ASSERT_EQ(p.num_variables(), 3u);
  EXPECT_EQ(p.variable(0).name, "cam_x");
  EXPECT_EQ(p.variable(1).name, "cam_y");
  EXPECT_EQ(p.variable(2).name, "cam_z");
  EXPECT_TRUE(p.all_continuous());
  EXPECT_EQ(p.num_constraints(), 7u);
  EXPECT_EQ(p.constraint(cp.ids().height).kind(), "camera.height");
  EXPECT_EQ(p.constraint(cp.ids().orientation).kind(), "camera.orientation");
  EXPECT_TRUE(p.constraint(cp.ids().look_at).is_hard());
  EXPECT_TRUE(p.constraint(cp.ids().clearance).is_hard());
  EXPECT_FALSE(p.constraint(cp.ids().height).is_hard());
  ASSERT_TRUE(cp.ids().visible_fraction);
  for (const char* name : {"char_x", "char_yaw", "look_y", "last_cam_z", "dt", "desired_height"}) {
    EXPECT_TRUE(p.parameters().find(name)) << name;
  }
}

TEST(CameraProblem, OptionalPartsFollowTheProfile) {
  const Scene scene = open_scene();
  CameraProfile profile;
  profile.visible_fraction_weight = 0;
  profile.look_at_hard = false;
  profile.look_at_weight = 3;
  const CameraProblem cp(scene, profile);
  EXPECT_EQ(cp.problem().num_constraints(), 6u);
  EXPECT_FALSE(cp.ids().visible_fraction);
  EXPECT_FALSE(cp.problem().constraint(cp.ids().look_at).is_hard());
  EXPECT_EQ(cp.problem().constraint(cp.ids().look_at).weight(), 3);
}

TEST(CameraProblem, CostIsTheWeightedSumOfTheViolations) {
  const Scene scene = open_scene();
  const CameraProfile profile;  // height 2.5 (weight 1), distance 4 (weight 1)
  CameraProblem cp(scene, profile);
  cp.set_frame(standing({0, 0, 0}, 0), {0, 3.5, -3}, 1.0 / 60);
  // Height off by 1, distance off by 1, right behind, not moving, all visible.
  const csp::Score at_rest = cp.problem().score(std::vector<double>{0, 3.5, -3});
  EXPECT_DOUBLE_EQ(at_rest.hard, 0);
  EXPECT_DOUBLE_EQ(at_rest.soft, 2.0);
  // 0.1 m nearer: distance off by 1.1, and a speed of 0.1 m x 60 = 6 m/s.
  const csp::Score moved = cp.problem().score(std::vector<double>{0, 3.5, -2.9});
  EXPECT_NEAR(moved.soft, 1.0 + 1.1 + profile.frame_coherence_weight * 6, 1e-12);
}

TEST(CameraProblem, SetFrameReparameterisesInPlace) {
  const Scene scene = open_scene();
  const CameraProfile profile;
  CameraProblem cp(scene, profile);
  const csp::Constraint* first = &cp.problem().constraint(0);
  const std::size_t constraints = cp.problem().num_constraints();
  CharacterState s = standing({1, 0.5, 2}, 30);
  s.velocity = {0.5, 0, 1};
  s.t = 4;
  cp.set_frame(s, {3, 2, -1}, 0.02);
  EXPECT_EQ(&cp.problem().constraint(0), first);
  EXPECT_EQ(cp.problem().num_constraints(), constraints);
  const csp::Parameters& p = cp.problem().parameters();
  EXPECT_EQ(p.get("char_x"), 1);
  EXPECT_EQ(p.get("char_y"), 0.5);
  EXPECT_EQ(p.get("char_yaw"), 30);
  EXPECT_EQ(p.get("char_vz"), 1);
  EXPECT_EQ(p.get("look_y"), 2.0);  // 0.5 + 1.5
  EXPECT_EQ(p.get("last_cam_x"), 3);
  EXPECT_EQ(p.get("dt"), 0.02);
  EXPECT_EQ(p.get("t"), 4);
  EXPECT_EQ(p.get("desired_distance"), 4);
  // The search cube is centred on the last camera position.
  EXPECT_EQ(cp.problem().variable(0).domain.lower(), 3 - profile.search_half_size);
  EXPECT_EQ(cp.problem().variable(1).domain.upper(), 2 + profile.search_half_size);
  cp.set_search_box({0, 0, 0}, 0.5);
  EXPECT_EQ(cp.problem().variable(2).domain.lower(), -0.5);
  EXPECT_THROW(cp.set_frame(s, {0, 0, 0}, 0), std::invalid_argument);
}

TEST(CameraProblem, TheIdealPositionMeetsHeightDistanceAndOrientation) {
  const Scene scene = open_scene();
  CameraProfile profile;
  for (double orientation : {0.0, 30.0, 90.0, 180.0}) {
    profile.orientation.desired = orientation;
    CameraProblem cp(scene, profile);
    for (double yaw : {0.0, 45.0, 200.0}) {
      cp.set_frame(standing({1, 0, -2}, yaw), {0, 2, 0}, 1.0 / 60);
      const Eigen::Vector3d ideal = cp.ideal_position();
      const auto values = CameraProblem::assignment(ideal);
      for (csp::ConstraintId id : {cp.ids().height, cp.ids().distance, cp.ids().orientation}) {
        EXPECT_NEAR(cp.problem().constraint(id).violation(values), 0, 1e-9)
            << cp.problem().constraint(id).kind() << " yaw " << yaw;
      }
    }
  }
}

TEST(CameraProblem, AreasAdaptTheDesiredValuesAndReportTransitions) {
  std::vector<Area> areas = {{"room", AreaKind::kEnclosed, {{-3, 0, -3}, {3, 2.6, 3}}, {}}};
  const Scene scene("room", {}, std::move(areas), {}, Trajectory({{0, {-10, 0, 0}, 90}}));
  const CameraProfile profile;
  CameraProblem cp(scene, profile);
  const csp::Parameters& p = cp.problem().parameters();
  EXPECT_EQ(p.get("desired_height"), 2.5);
  AreaTransition t = cp.set_frame(standing({0, 0, 0}, 0), {0, 2, -2}, 1.0 / 60);
  ASSERT_TRUE(t.entered);
  EXPECT_NEAR(p.get("desired_height"), 2.1, 1e-12);    // 2.6 - 0.5
  EXPECT_NEAR(p.get("desired_distance"), 2.1, 1e-12);  // 0.35 x 6
  t = cp.set_frame(standing({-10, 0, 0}, 0), {0, 2, -2}, 1.0 / 60);
  ASSERT_TRUE(t.left);
  EXPECT_EQ(p.get("desired_height"), 2.5);
  EXPECT_EQ(p.get("desired_distance"), 4.0);
}

TEST(CameraProblem, ProfileExtrasAreOrdinaryConstraintsOverTheFrame) {
  const Scene scene = open_scene();
  const CameraProfile profile = parse_profile(csp::parse_yaml(R"(name: above
extras:
  - {kind: expression, scope: [cam_y], formula: "char_y + 1.2 - cam_y", hard: true,
     label: above the head}
)", "profile.yaml"));
  CameraProblem cp(scene, profile);
  ASSERT_EQ(cp.ids().extras.size(), 1u);
  const csp::Constraint& extra = cp.problem().constraint(cp.ids().extras[0]);
  EXPECT_TRUE(extra.is_hard());
  EXPECT_EQ(extra.label(), "above the head");
  cp.set_frame(standing({0, 0, 0}, 0), {0, 2, -4}, 1.0 / 60);
  EXPECT_NEAR(extra.violation(std::vector<double>{0, 1.0, -4}), 0.2, 1e-12);
  EXPECT_EQ(extra.violation(std::vector<double>{0, 2.0, -4}), 0.0);
  cp.set_frame(standing({0, 1, 0}, 0), {0, 2, -4}, 1.0 / 60);  // the character went up 1 m
  EXPECT_NEAR(extra.violation(std::vector<double>{0, 2.0, -4}), 0.2, 1e-12);
  EXPECT_FALSE(cp.problem().is_feasible(std::vector<double>{0, 2.0, -4}));
}

TEST(CameraProblem, ExampleSceneWithAnInlineExtraBuilds) {
  const Scene scene =
      read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) + "/examples/scenes/room-with-door.yaml");
  const CameraProblem cp(scene);
  EXPECT_EQ(cp.ids().extras.size(), 1u);
  EXPECT_EQ(scene.profile().name, "close-follow-above-1.2");
}

// Any solver that takes continuous problems can place the camera: from a poor start in an
// open scene it must end feasible and much nearer the ideal than it started.
TEST(CameraProblem, GenericSolversCanSolveIt) {
  const Scene scene = open_scene();
  const CameraProfile profile;
  CameraProblem cp(scene, profile);
  cp.set_frame(standing({0, 0, 0}, 0), {1, 3, -2}, 1.0 / 60);
  const auto start = CameraProblem::assignment({1, 3, -2});
  const double start_cost = cp.problem().score(start).soft;
  int solved = 0;
  for (const char* name : {"grid", "sliding-octree", "sls"}) {
    if (!solvers::SolverRegistry::global().contains(name)) continue;
    auto solver = solvers::SolverRegistry::global().create(name);
    if (!solver->unsuitable_reason(cp.problem()).empty()) continue;
    const solvers::SolverResult r = solver->solve(cp.problem(), start);
    EXPECT_TRUE(r.feasible()) << name;
    EXPECT_LT(r.cost(), 0.8 * start_cost) << name;
    ++solved;
  }
  if (solved == 0) GTEST_SKIP() << "no continuous solver registered yet";
}

}  // namespace
}  // namespace sightline::camera
