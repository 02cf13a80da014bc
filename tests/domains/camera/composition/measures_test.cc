// The shot properties' measures and satisfaction (FORMATS.md "Shots"), against values worked
// out by hand here: a target at screen centre, a known projected height, angles at 0, 90 and
// 180 degrees, a wall hiding a third or two thirds of the samples (touching a face does not
// hide), roll 90, the order of two people.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/property_kinds.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/composition/shot_world.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

CameraPose pose(Eigen::Vector3d p, Eigen::Vector3d a, double fov = 90, double aspect = 1,
                double roll = 0) {
  CameraPose c;
  c.position = p;
  c.look_at = a;
  c.fov = fov;
  c.aspect = aspect;
  c.roll = roll;
  return c;
}

TEST(ShotView, ProjectsAsFormatsSays) {
  // Looking along +z with a 90-degree fov and aspect 1: tan(fov/2) = 1. The right of the
  // image is f x up = -x.
  const auto view = View::of(pose({0, 0, 0}, {0, 0, 1}));
  ASSERT_TRUE(view);
  auto s = view->project({0, 0, 5});
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->x(), 0.5, 1e-12);
  EXPECT_NEAR(s->y(), 0.5, 1e-12);
  s = view->project({5, 0, 5});  // +x: the left edge
  EXPECT_NEAR(s->x(), 0.0, 1e-12);
  s = view->project({-5, 0, 5});
  EXPECT_NEAR(s->x(), 1.0, 1e-12);
  s = view->project({0, 5, 5});  // up: the top edge
  EXPECT_NEAR(s->y(), 1.0, 1e-12);
  s = view->project({-2.5, -1, 5});  // sx = (1 + 2.5 / 5) / 2, sy = (1 - 1 / 5) / 2
  EXPECT_NEAR(s->x(), 0.75, 1e-12);
  EXPECT_NEAR(s->y(), 0.4, 1e-12);
  EXPECT_FALSE(view->project({0, 0, -1}));    // behind
  EXPECT_FALSE(view->project({0, 0, 0.05}));  // not deeper than 0.05 m
  EXPECT_TRUE(view->project({0, 0, 0.051}));
  // Aspect 2 halves the horizontal offsets.
  s = View::of(pose({0, 0, 0}, {0, 0, 1}, 90, 2))->project({-2.5, 0, 5});
  EXPECT_NEAR(s->x(), 0.625, 1e-12);
}

TEST(ShotView, Roll90TurnsTheImageAQuarter) {
  // r = u0 = +y, u = -r0 = +x.
  const auto view = View::of(pose({0, 0, 0}, {0, 0, 1}, 90, 1, 90));
  auto s = view->project({0, 5, 5});
  EXPECT_NEAR(s->x(), 1.0, 1e-12);
  EXPECT_NEAR(s->y(), 0.5, 1e-12);
  s = view->project({5, 0, 5});
  EXPECT_NEAR(s->x(), 0.5, 1e-12);
  EXPECT_NEAR(s->y(), 1.0, 1e-12);
}

TEST(ShotView, AVerticalOrEmptyDirectionHasNoView) {
  EXPECT_FALSE(View::of(pose({0, 0, 0}, {0, 3, 0})));
  EXPECT_FALSE(View::of(pose({0, 0, 0}, {0, -3, 0})));
  EXPECT_FALSE(View::of(pose({1, 1, 1}, {1, 1, 1})));
  EXPECT_FALSE(View::of(pose({0, 0, 0}, {0, 0, 1}, 180)));
  EXPECT_FALSE(View::of(pose({0, 0, 0}, {0, 0, 1}, 50, 0)));
}

TEST(ShotSatisfaction, LinearOutsideTheRange) {
  const ValueRange r{1, 2};
  EXPECT_EQ(satisfaction(1.5, r, 0.5, false), 1);
  EXPECT_EQ(satisfaction(1, r, 0.5, false), 1);
  EXPECT_NEAR(satisfaction(2.25, r, 0.5, false), 0.5, 1e-12);
  EXPECT_NEAR(satisfaction(0.9, r, 0.5, false), 0.8, 1e-12);
  EXPECT_EQ(satisfaction(3, r, 0.5, false), 0);
  EXPECT_EQ(satisfaction(kInf, r, 0.5, false), 0);
  EXPECT_EQ(satisfaction(std::nan(""), r, 0.5, false), 0);
  EXPECT_EQ(satisfaction(kInf, ValueRange{0, kInf}, 0.1, false), 1);
}

TEST(ShotSatisfaction, AnglesAreComparedModulo360) {
  EXPECT_EQ(satisfaction(370, {-40, 40}, 30, true), 1);
  EXPECT_NEAR(satisfaction(60, {-40, 40}, 30, true), 1 - 20.0 / 30, 1e-12);
  EXPECT_NEAR(satisfaction(-60, {-40, 40}, 30, true), 1 - 20.0 / 30, 1e-12);
  EXPECT_EQ(satisfaction(90, {-40, 40}, 30, true), 0);
  // hi < lo: the arc from 150 up through 180 to 210.
  EXPECT_EQ(satisfaction(180, {150, -150}, 30, true), 1);
  EXPECT_EQ(satisfaction(-170, {150, -150}, 30, true), 1);
  EXPECT_NEAR(satisfaction(140, {150, -150}, 30, true), 1 - 10.0 / 30, 1e-12);
  EXPECT_NEAR(satisfaction(-140, {150, -150}, 30, true), 1 - 10.0 / 30, 1e-12);
  // The gap goes the shorter way round: 0 is 150 away from 150 and from 210, and 359 is 1
  // from 0 in [0, 10].
  EXPECT_NEAR(satisfaction(359, {0, 10}, 30, true), 1 - 1.0 / 30, 1e-12);
}

// A scene of two people facing +z (alice at x = -1, bob at x = +1, both at z = 0) and a
// shot over them; `boxes` and `properties` are YAML lines.
Scene people_scene(const std::string& boxes, const std::string& properties) {
  const std::string text =
      "name: measures\n"
      "boxes:\n" + (boxes.empty() ? std::string("  []\n") : boxes) +
      "actors:\n"
      "  - {name: alice, trajectory: [{t: 0, position: [-1, 0, 0], yaw: 0}]}\n"
      "  - {name: bob, trajectory: [{t: 0, position: [1, 0, 0], yaw: 0}]}\n"
      "shot:\n"
      "  fov: 90\n"
      "  aspect: 1\n"
      "  region: {min: [-20, -20, -20], max: [20, 20, 20]}\n"
      "  properties:\n" + properties;
  return parse_scene(csp::parse_yaml(text, "measures.yaml"));
}

struct Measured {
  double measure, score;
};

Measured measure(const Scene& scene, const CameraPose& p, std::size_t property = 0) {
  CompositionProblem problem(scene, *scene.shot(), 0);
  const ShotEvaluation e = problem.evaluate(p);
  return {e.measures.at(property), e.scores.at(property)};
}

TEST(ShotMeasures, ATargetAtScreenCentreIsAtDistanceZero) {
  const Scene s = people_scene("", "    - {kind: screen_position, target: alice, at: [0.5, 0.5]}\n");
  // alice's aim point is (-1, 1.5, 0).
  Measured m = measure(s, pose({-1, 1.5, -6}, {-1, 1.5, 0}));
  EXPECT_NEAR(m.measure, 0, 1e-12);
  EXPECT_EQ(m.score, 1);
  // Looking 45 degrees to the right of her (toward -x): she sits at the left edge, 0.5 away.
  m = measure(s, pose({-1, 1.5, -6}, {-7, 1.5, 0}));
  EXPECT_NEAR(m.measure, 0.5, 1e-9);
  EXPECT_EQ(m.score, 0);  // softness 0.25
  m = measure(s, pose({-1, 1.5, 6}, {-1, 1.5, 12}));  // she is behind the camera
  EXPECT_EQ(m.measure, kInf);
  EXPECT_EQ(m.score, 0);
}

TEST(ShotMeasures, ProjectedHeightOfTheSamples) {
  const Scene s = people_scene("", "    - {kind: size, target: bob, range: [0.05, 0.06]}\n"
                                   "    - {kind: size, target: bob, measure: width, range: [0, 1]}\n"
                                   "    - {kind: size, target: bob, measure: area, range: [0, 1]}\n");
  // bob's box: x in [0.7, 1.3], y in [0, 1.8], z in [-0.3, 0.3]; samples at 0.1, 0.5, 0.9 of
  // it: y in {0.18, 0.9, 1.62}, nearest z = -0.24. Camera at (1, 0.9, -10) looking +z at
  // height 0.9: sy = 0.5 + (y - 0.9) / (2 z), extreme at z = 9.76: height 1.44 / (2 x 9.76).
  const CameraPose p = pose({1, 0.9, -10}, {1, 0.9, 0});
  const double height = 0.72 / 9.76, width = 0.24 / 9.76;  // half the extents / z
  EXPECT_NEAR(measure(s, p, 0).measure, height, 1e-12);
  EXPECT_NEAR(measure(s, p, 0).score, 1 - (height - 0.06) / 0.25, 1e-12);
  EXPECT_NEAR(measure(s, p, 1).measure, width, 1e-12);
  EXPECT_NEAR(measure(s, p, 2).measure, width * height, 1e-12);
  // A sample behind the camera: infinite.
  EXPECT_EQ(measure(s, pose({1, 0.9, 0}, {1, 0.9, 5}), 0).measure, kInf);
}

TEST(ShotMeasures, HorizontalAngleIsFromTheTargetsFront) {
  const Scene s = people_scene("", "    - {kind: angle_horizontal, target: alice, range: [-40, 40]}\n"
                                   "    - {kind: angle_vertical, target: alice, range: [0, 10]}\n");
  const Eigen::Vector3d aim(-1, 1.5, 0);
  // In front of her (she faces +z): 0. At her left (+x when facing +z): 90. Behind: 180.
  EXPECT_NEAR(measure(s, pose(aim + Eigen::Vector3d(0, 0, 5), aim)).measure, 0, 1e-9);
  Measured left = measure(s, pose(aim + Eigen::Vector3d(5, 0, 0), aim));
  EXPECT_NEAR(left.measure, 90, 1e-9);
  EXPECT_EQ(left.score, 0);
  EXPECT_NEAR(std::abs(measure(s, pose(aim + Eigen::Vector3d(0, 0, -5), aim)).measure), 180, 1e-9);
  // 60 degrees round: 20 outside the range, softness 30.
  const double a = 60 * M_PI / 180;
  const Measured sixty = measure(s, pose(aim + 5 * Eigen::Vector3d(std::sin(a), 0, std::cos(a)), aim));
  EXPECT_NEAR(sixty.measure, 60, 1e-9);
  EXPECT_NEAR(sixty.score, 1 - 20.0 / 30, 1e-9);
  // Vertical: 45 degrees above her aim point; 10 below the horizontal.
  EXPECT_NEAR(measure(s, pose(aim + Eigen::Vector3d(0, 5, 5), aim), 1).measure, 45, 1e-9);
  const double b = 10 * M_PI / 180;
  EXPECT_NEAR(measure(s, pose(aim + 5 * Eigen::Vector3d(0, -std::sin(b), std::cos(b)), aim), 1).measure,
              -10, 1e-9);
}

TEST(ShotMeasures, AWallHidesTheSamplesWhoseSightLineEntersIt) {
  // Camera at (-1, 0.9, -10) looking at alice (samples at x in {-1.24, -1, -0.76}). A wall
  // at z in [-5, -4] covering x < -1 hides the column x = -1.24 (9 of 27); the column x = -1
  // only touches its face x = -1, which does not hide (FORMATS.md).
  const std::string properties = "    - {kind: visible, target: alice}\n";
  const CameraPose p = pose({-1, 0.9, -10}, {-1, 0.9, 0});
  const Scene touching = people_scene("  - {min: [-6, 0, -5], max: [-1, 3, -4]}\n", properties);
  EXPECT_NEAR(measure(touching, p).measure, 18.0 / 27, 1e-12);
  EXPECT_NEAR(measure(touching, p).score, 18.0 / 27, 1e-12);  // range [1, 1], softness 1
  // A millimetre further, the middle column goes too: a third visible.
  const Scene over = people_scene("  - {min: [-6, 0, -5], max: [-0.999, 3, -4]}\n", properties);
  EXPECT_NEAR(measure(over, p).measure, 9.0 / 27, 1e-12);
  EXPECT_EQ(measure(people_scene("", properties), p).measure, 1);
}

TEST(ShotMeasures, OtherPeopleHideButNotTheTargetItself) {
  // From (3, 0.9, 0), on the line through both: bob (x in [0.7, 1.3]) stands between the
  // camera and alice and hides all of her; her own box never hides her samples.
  const Scene s = people_scene("", "    - {kind: visible, target: alice}\n"
                                   "    - {kind: visible, target: bob}\n");
  const CameraPose p = pose({3, 0.9, 0}, {-1, 0.9, 0});
  EXPECT_EQ(measure(s, p, 0).measure, 0);
  EXPECT_EQ(measure(s, p, 1).measure, 1);
}

TEST(ShotMeasures, DistanceAndOrderOnScreen) {
  const Scene s = people_scene("", "    - {kind: distance, target: alice, range: [2, 3]}\n"
                                   "    - {kind: order, targets: [alice, bob]}\n"
                                   "    - {kind: order, targets: [alice, bob], axis: depth}\n");
  // From (0, 1.5, -5) looking +z: the image's right is -x, so alice (x = -1) is right of bob:
  // sx(alice) = (1 + 1 / 5) / 2 = 0.6, sx(bob) = 0.4; bob - alice = -0.2, 0.2 below the
  // range [0, inf] with softness 0.1.
  const CameraPose p = pose({0, 1.5, -5}, {0, 1.5, 0});
  EXPECT_NEAR(measure(s, p, 0).measure, std::sqrt(26.0), 1e-12);
  EXPECT_NEAR(measure(s, p, 1).measure, -0.2, 1e-12);
  EXPECT_EQ(measure(s, p, 1).score, 0);
  EXPECT_NEAR(measure(s, p, 2).measure, 0, 1e-12);
  // From behind them (z = +5, looking -z) the order flips.
  const CameraPose q = pose({0, 1.5, 5}, {0, 1.5, 0});
  EXPECT_NEAR(measure(s, q, 1).measure, 0.2, 1e-12);
  EXPECT_EQ(measure(s, q, 1).score, 1);
  // Either aim point not in front: scores 0.
  EXPECT_EQ(measure(s, pose({-1, 1.5, 0.5}, {-1, 1.5, 5}), 1).score, 0);
}

TEST(ShotMeasures, FramedCountsTheSamplesInsideTheRectangle) {
  const Scene s = people_scene("", "    - {kind: framed, target: alice, rect: [0.5, 0, 1, 1]}\n");
  // Looking along +z at alice's centre column (the image's right is -x): the samples at
  // x = -1 project to sx = 0.5 (on the rectangle's edge: inside), those at x = -1.24 to the
  // right half, those at x = -0.76 to the left half: 18 of 27 inside.
  EXPECT_NEAR(measure(s, pose({-1, 0.9, -10}, {-1, 0.9, 0})).measure, 18.0 / 27, 1e-12);
}

// framed settles from the eight outer samples when they are all inside the rectangle or all
// beyond one edge of it, and counts the 27 otherwise: from random poses round alice (near
// and far, from all sides, some with her behind the camera or half out of the image, rolls
// and narrow rectangles), the measure must be this test's own count of her 27 samples
// (FORMATS.md's pinhole, worked here) to the bit, and every kind of case must occur.
TEST(ShotMeasures, FramedIsTheCountOfAllTwentySevenSamplesFromAnyPose) {
  const Scene s = people_scene("", "    - {kind: framed, target: alice, rect: [0.2, 0.1, 0.7, 0.95]}\n");
  CompositionProblem problem(s, *s.shot(), 0);
  const PersonAtTime& alice = problem.world().people()[*problem.world().find("alice")];
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  int all = 0, none = 0, some = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    CameraPose c = pose(alice.aim + Eigen::Vector3d(6 * unit(rng), 2 * unit(rng), 6 * unit(rng)),
                        alice.aim + Eigen::Vector3d(1.5 * unit(rng), 1.5 * unit(rng), 1.5 * unit(rng)),
                        40 + 30 * unit(rng), 1, trial % 3 == 0 ? 25 * unit(rng) : 0);
    const std::optional<View> view = View::of(c);
    if (!view) continue;
    // The count, by FORMATS.md: d = q - p, depth d.f > 0.05, sx and sy from the view's axes.
    const Eigen::Vector3d f = (c.look_at - c.position).normalized();
    const Eigen::Vector3d r0 = f.cross(Eigen::Vector3d::UnitY()).normalized();
    const Eigen::Vector3d u0 = r0.cross(f);
    const double roll = c.roll * 3.14159265358979323846 / 180;
    const Eigen::Vector3d r = std::cos(roll) * r0 + std::sin(roll) * u0;
    const Eigen::Vector3d u = std::cos(roll) * u0 - std::sin(roll) * r0;
    const double t = std::tan(c.fov * 3.14159265358979323846 / 360);
    const Eigen::Vector3d size = alice.body.max - alice.body.min;
    int inside = 0;
    for (double i : {0.1, 0.5, 0.9}) {
      for (double j : {0.1, 0.5, 0.9}) {
        for (double k : {0.1, 0.5, 0.9}) {
          const Eigen::Vector3d d = alice.body.min + Eigen::Vector3d(i * size.x(), j * size.y(), k * size.z()) - c.position;
          const double z = d.dot(f);
          if (!(z > 0.05)) continue;
          const double sx = (1 + d.dot(r) / (z * t)) / 2, sy = (1 + d.dot(u) / (z * t)) / 2;
          inside += sx >= 0.2 && sx <= 0.7 && sy >= 0.1 && sy <= 0.95;
        }
      }
    }
    ASSERT_EQ(measure(s, c).measure, inside / 27.0) << trial;
    (inside == 27 ? all : inside == 0 ? none : some) += 1;
  }
  EXPECT_GT(all, 100);
  EXPECT_GT(none, 100);
  EXPECT_GT(some, 100);
}

TEST(ShotMeasures, CountClearAgreesWithEachSightLine) {
  // count_clear gathers the boxes near a person once for all their samples; it must answer
  // as clear() does sample by sample: the followed character, two actors and random boxes,
  // few (every box gathered) and many (more than it gathers: sample by sample), from random
  // camera positions, and with `enough` stopping the count.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-6, 6), h(0, 3);
  for (auto [boxes, largest] : {std::pair{12, 1.5}, std::pair{400, 0.3}}) {
    std::uniform_real_distribution<double> size(0.05, largest);
    std::string text =
        "name: sight\ncharacter: {size: [0.6, 1.8, 0.6], look_at_height: 1.5}\n"
        "trajectory: [{t: 0, position: [0, 0, 0], yaw: 0}]\nboxes:\n";
    for (int i = 0; i < boxes; ++i) {
      const double x = u(rng), y = h(rng), z = u(rng);
      if (std::abs(x) < 2 && std::abs(z) < 2) continue;  // keep the people out of the boxes
      text += "  - {min: [" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
              "], max: [" + std::to_string(x + size(rng)) + ", " + std::to_string(y + size(rng)) + ", " +
              std::to_string(z + size(rng)) + "]}\n";
    }
    text +=
        "actors:\n"
        "  - {name: alice, trajectory: [{t: 0, position: [-1, 0, 1], yaw: 0}]}\n"
        "  - {name: bob, trajectory: [{t: 0, position: [1, 0, -1], yaw: 0}]}\n";
    const Scene scene = parse_scene(csp::parse_yaml(text, "sight.yaml"));
    const ShotWorld world(scene, 0);
    ASSERT_EQ(world.people().size(), 3u);
    int partly = 0;
    for (int trial = 0; trial < 300; ++trial) {
      const Eigen::Vector3d p(2 * u(rng), 1 + 2 * h(rng), 2 * u(rng));
      for (int who = 0; who < 3; ++who) {
        int expected = 0;
        for (const Eigen::Vector3d& q : person_samples(world.people()[static_cast<std::size_t>(who)].body)) {
          if (world.clear(p, q, who)) ++expected;
        }
        ASSERT_EQ(world.count_clear(p, who), expected) << boxes << " boxes, trial " << trial << ", person " << who;
        for (int enough : {1, 9, 27}) {
          ASSERT_EQ(world.count_clear(p, who, enough), std::min(enough, expected));
        }
        if (expected > 0 && expected < kPersonSamples) ++partly;
      }
    }
    EXPECT_GT(partly, 50) << boxes << " boxes: too few positions see part of someone";
  }
}

}  // namespace
}  // namespace sightline::camera
