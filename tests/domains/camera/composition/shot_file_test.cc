// Reading shot:, shots: and script: blocks (FORMATS.md "Shots", "Script and named shots"):
// what the format allows is read, everything else refused at its line with what was
// expected; a hard property no pose can meet gives an infeasible pose that names it.
#include <gtest/gtest.h>

#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

const std::string kPeople =
    "name: shots\n"
    "actors:\n"
    "  - {name: alice, trajectory: [{t: 0, position: [-1, 0, 0], yaw: 0}, {t: 4, position: [-1, 0, 2], yaw: 0}]}\n"
    "  - {name: bob, trajectory: [{t: 0, position: [1, 0, 0], yaw: 180}]}\n";

Scene scene_of(const std::string& rest) {
  return parse_scene(csp::parse_yaml(kPeople + rest, "shots.yaml"));
}

// Refused at `line` with a message holding `words`.
void expect_refused(const std::string& rest, int line, const std::string& words) {
  try {
    scene_of(rest);
    ADD_FAILURE() << "accepted:\n" << rest;
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("shots.yaml"), std::string::npos) << e.what();
  }
}

TEST(ShotFile, ReadsEveryFieldTheFormatHas) {
  const Scene s = scene_of(
      "shot:\n"
      "  fov: [30, 60]\n"
      "  aspect: 2\n"
      "  roll: [-10, 10]\n"
      "  region: {min: [-10, 0.3, -10], max: [10, 6, 10]}\n"
      "  clearance: 0.5\n"
      "  properties:\n"
      "    - {kind: screen_position, target: alice, at: [0.333, 0.667]}\n"
      "    - {kind: size, target: alice, measure: height, range: [0.35, 0.5]}\n"
      "    - {kind: angle_horizontal, target: alice, range: [150, -150], weight: 2}\n"
      "    - {kind: visible, target: alice, range: [0.8, 1], hard: true}\n"
      "    - {kind: framed, target: bob, rect: [0.5, 0, 1, 1], range: [0.3, 1]}\n"
      "    - {kind: order, targets: [alice, bob], axis: horizontal}\n"
      "    - {kind: distance, target: bob, range: [2, .inf], softness: 0.5}\n"
      "    - {kind: angle_vertical, target: bob, range: [-5, 20]}\n");
  ASSERT_NE(s.shot(), nullptr);
  const Shot& shot = *s.shot();
  EXPECT_EQ(shot.fov.lo, 30);
  EXPECT_EQ(shot.fov.hi, 60);
  EXPECT_EQ(shot.aspect, 2);
  EXPECT_EQ(shot.roll.lo, -10);
  EXPECT_EQ(shot.clearance, 0.5);
  ASSERT_EQ(shot.properties.size(), 8u);
  EXPECT_EQ(shot.properties[0].at, Eigen::Vector2d(0.333, 0.667));
  EXPECT_EQ(shot.properties[0].range.hi, 0.02);       // default range
  EXPECT_EQ(shot.properties[0].softness, 0.25);       // default softness
  EXPECT_EQ(shot.properties[2].range.lo, 150);         // hi < lo: through 180
  EXPECT_EQ(shot.properties[2].weight, 2);
  EXPECT_TRUE(shot.properties[3].hard);
  EXPECT_EQ(shot.properties[4].rect, Eigen::Vector4d(0.5, 0, 1, 1));
  EXPECT_EQ(shot.properties[5].range.hi, std::numeric_limits<double>::infinity());
  EXPECT_EQ(shot.properties[5].softness, 0.1);
  EXPECT_EQ(shot.properties[6].range.hi, std::numeric_limits<double>::infinity());
  EXPECT_EQ(shot.properties[6].softness, 0.5);
  // Nobody is chased: the frames follow the first target, alice.
  EXPECT_FALSE(s.has_character());
  EXPECT_EQ(s.trajectory().end_time(), 4);
}

TEST(ShotFile, DefaultsAreTheFormats) {
  const Scene s = scene_of("shot:\n  region: {min: [-5, 0, -5], max: [5, 3, 5]}\n"
                           "  properties:\n    - {kind: size, target: bob, range: [0.1, 0.2], measure: area}\n"
                           "    - {kind: order, targets: [bob, alice], axis: depth}\n");
  const Shot& shot = *s.shot();
  EXPECT_EQ(shot.fov.lo, 50);
  EXPECT_NEAR(shot.aspect, 16.0 / 9, 1e-12);
  EXPECT_EQ(shot.roll.lo, 0);
  EXPECT_EQ(shot.clearance, 0.2);
  EXPECT_EQ(shot.properties[0].softness, 0.1);  // area
  EXPECT_EQ(shot.properties[1].softness, 1);    // depth
}

TEST(ShotFile, BadShotsAreRefusedAtTheirLine) {
  const std::string region = "  region: {min: [-5, 0, -5], max: [5, 3, 5]}\n";
  // Line numbers: kPeople is 4 lines; "shot:" is line 5.
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: size, target: carol, range: [0, 1]}\n",
                 8, "unknown person 'carol'");
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: size, target: bob, range: [0.5, 0.2]}\n",
                 8, "lo <= hi");
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: size, target: bob, range: [.nan, 1]}\n",
                 8, "low end");
  expect_refused("shot:\n  region: {min: [0, 0, 0], max: [0, 3, 5]}\n  properties:\n"
                 "    - {kind: size, target: bob, range: [0, 1]}\n",
                 6, "min < max");
  expect_refused("shot:\n  aspect: 0\n" + region + "  properties:\n    - {kind: visible, target: bob}\n",
                 6, "aspect");
  expect_refused("shot:\n  fov: 180\n" + region + "  properties:\n    - {kind: visible, target: bob}\n",
                 6, "field of view");
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: charm, target: bob}\n", 8,
                 "unknown shot property kind 'charm'");
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: size, target: bob}\n", 8,
                 "range");
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: visible, target: bob, mood: calm}\n",
                 8, "mood");
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: order, targets: [bob]}\n", 8,
                 "2 people");
  expect_refused("shot:\n" + region + "  properties:\n    - {kind: framed, target: bob, rect: [1, 0, 0, 1]}\n",
                 8, "x0 <= x1");
  expect_refused("shot:\n" + region + "  properties: []\n", 7, "at least one property");
  // A missing field is reported at the block's first line.
  expect_refused("shot:\n  properties:\n    - {kind: visible, target: bob}\n", 6, "region");
}

TEST(ShotFile, NamedShotsAndScripts) {
  const std::string shot_entry =
      "  - name: two-shot\n    region: {min: [-5, 0, -5], max: [5, 3, 5]}\n"
      "    properties: [{kind: visible, target: alice}]\n";
  const Scene s = scene_of("shot:\n  region: {min: [-5, 0, -5], max: [5, 3, 5]}\n"
                           "  properties: [{kind: visible, target: bob}]\n"
                           "shots:\n" + shot_entry +
                           "script:\n  - {t: [0, 2], speaker: alice, to: bob}\n"
                           "  - {t: [1, 3], speaker: bob, to: alice}\n  - {t: [3, 4], action: bob}\n");
  ASSERT_EQ(s.named_shots().size(), 1u);
  EXPECT_EQ(s.named_shots()[0]->name, "two-shot");
  ASSERT_NE(s.script(), nullptr);
  EXPECT_EQ(s.script()->size(), 3u);
  const std::string shot = "shot:\n  region: {min: [-5, 0, -5], max: [5, 3, 5]}\n"
                           "  properties: [{kind: visible, target: bob}]\n";
  expect_refused(shot + "shots:\n  - name: empty\n    region: {min: [-5, 0, -5], max: [5, 3, 5]}\n"
                        "    properties: []\n",
                 11, "at least one property");
  expect_refused(shot + "script:\n  - {t: [0, 2], speaker: carol, to: bob}\n", 9,
                 "unknown person 'carol'");
  expect_refused(shot + "script:\n  - {t: [0, 2], speaker: alice, to: bob}\n"
                        "  - {t: [1, 3], speaker: alice, to: bob}\n",
                 10, "overlaps");
  expect_refused(shot + "script:\n  - {t: [2, 1], action: bob}\n", 9, "t0 < t1");
}

TEST(ShotFile, AHardPropertyNoPoseMeetsGivesAnInfeasiblePoseNamingIt) {
  // bob must be 100-200 m away, in a region 10 m wide.
  const Scene s = scene_of("shot:\n  region: {min: [-5, 0.3, -5], max: [5, 3, 5]}\n"
                           "  properties:\n    - {kind: visible, target: alice}\n"
                           "    - {kind: distance, target: bob, range: [100, 200], hard: true}\n");
  const CompositionProblem problem(s, *s.shot(), 0);
  register_composition_solvers(solvers::SolverRegistry::global());
  const auto solver = solvers::SolverRegistry::global().create("shot-search");
  const solvers::SolverResult r = solver->solve(problem.problem(), csp::Assignment{});
  EXPECT_FALSE(r.feasible());
  const ShotEvaluation e = problem.evaluate(problem.pose(r.best));
  EXPECT_FALSE(e.feasible);
  EXPECT_NE(e.why_infeasible.find("distance of bob"), std::string::npos) << e.why_infeasible;
  EXPECT_NE(e.why_infeasible.find("line 9"), std::string::npos) << e.why_infeasible;
}

}  // namespace
}  // namespace sightline::camera
