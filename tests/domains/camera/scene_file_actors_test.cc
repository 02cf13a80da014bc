// Scene files' `actors:` block (FORMATS.md "Actors"): the example read back, actors blocking
// sight like movers at each time (judged by the test's own segment-box test), the followed
// character given as the actor named "character", and every bad actor an InputError with
// the line and what was expected.
#include <gtest/gtest.h>

#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/scene_at_time.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

Scene parse(const std::string& text) { return parse_scene(csp::parse_yaml(text, "scene.yaml"), ""); }

// The FORMATS.md example, in a scene with a trajectory.
const char* kFormatsActors = R"(name: talk
actors:                               # optional
  - name: bob                         # required; unique among the actors; "character" names the main one
    size: [0.6, 1.8, 0.6]             # optional, default as shown (the character's default)
    look_at_height: 1.5               # optional, default as shown
    trajectory:                       # required, keyframes as for the character
      - {t: 0.0, position: [1, 0, 2], yaw: 180}
      - {t: 4.0, position: [-3, 0, 2], yaw: 270}
trajectory:
  - {t: 0.0, position: [0, 0, -3], yaw: 0}
  - {t: 4.0, position: [0, 0, 3], yaw: 0}
)";

// The test's own slab test: does the segment a -> b touch the box [lo, hi]?
bool touches(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& lo,
             const Eigen::Vector3d& hi) {
  double t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const double d = b[k] - a[k];
    if (d == 0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double u = (lo[k] - a[k]) / d, v = (hi[k] - a[k]) / d;
    if (u > v) std::swap(u, v);
    t0 = std::max(t0, u);
    t1 = std::min(t1, v);
    if (t0 > t1) return false;
  }
  return true;
}

TEST(SceneFileActors, ReadsTheFormatsExample) {
  const Scene s = parse(kFormatsActors);
  ASSERT_EQ(s.actors().size(), 1u);
  const Actor& bob = s.actors()[0];
  EXPECT_EQ(bob.name, "bob");
  EXPECT_EQ(bob.shape.size, Eigen::Vector3d(0.6, 1.8, 0.6));
  EXPECT_EQ(bob.shape.look_at_height, 1.5);
  EXPECT_EQ(bob.where.line, 3);
  EXPECT_EQ(bob.aim_point(0), Eigen::Vector3d(1, 1.5, 2));
  EXPECT_NEAR((bob.aim_point(2) - Eigen::Vector3d(-1, 1.5, 2)).norm(), 0, 1e-12);
  EXPECT_NEAR(bob.state_at(2).yaw, 225, 1e-9);  // the shorter arc from 180 to 270
  // Bob is also a mover of his size on his path.
  ASSERT_EQ(s.movers().size(), 1u);
  EXPECT_EQ(s.movers()[0].name(), "bob");
}

TEST(SceneFileActors, ActorsBlockSightAtEachFramesTime) {
  const Scene s = parse(kFormatsActors);
  SceneAtTime at(s);
  const Actor& bob = s.actors()[0];
  int blocked = 0, clear = 0;
  // Sight lines across the room at the height of the chest, at several times: blocked
  // exactly when they touch Bob's box at that time.
  for (double t : {0.0, 1.0, 2.0, 3.0, 4.0}) {
    at.set_time(t);
    const Eigen::Vector3d feet = bob.state_at(t).position;
    const Eigen::Vector3d lo = feet - Eigen::Vector3d(0.3, 0, 0.3);
    const Eigen::Vector3d hi = feet + Eigen::Vector3d(0.3, 1.8, 0.3);
    for (double x : {-4.0, -2.0, -1.0, 0.0, 1.0, 2.0}) {
      const Eigen::Vector3d a(x, 1.2, -1), b(x + 0.5, 1.2, 5);
      EXPECT_EQ(at.line_of_sight(a, b), !touches(a, b, lo, hi)) << "t = " << t << ", x = " << x;
      ++(touches(a, b, lo, hi) ? blocked : clear);
    }
  }
  EXPECT_GT(blocked, 3);
  EXPECT_GT(clear, 3);
}

TEST(SceneFileActors, TheActorNamedCharacterIsFollowedWhenThereIsNoTrajectory) {
  const Scene s = parse(R"(name: duo
actors:
  - name: character
    size: [0.5, 1.7, 0.5]
    look_at_height: 1.6
    trajectory:
      - {t: 1.0, position: [0, 0, 0], yaw: 0}
      - {t: 3.0, position: [0, 0, 4], yaw: 0}
  - name: ann
    trajectory:
      - {t: 0.0, position: [2, 0, 2], yaw: 270}
)");
  EXPECT_EQ(s.character().size, Eigen::Vector3d(0.5, 1.7, 0.5));
  EXPECT_EQ(s.character().look_at_height, 1.6);
  EXPECT_EQ(s.trajectory().start_time(), 1.0);
  EXPECT_EQ(s.trajectory().end_time(), 3.0);
  ASSERT_EQ(s.actors().size(), 1u);  // the followed one is the character, not an actor
  EXPECT_EQ(s.actors()[0].name, "ann");
  ASSERT_EQ(s.movers().size(), 1u);
}

void expect_error(const std::string& text, int line, const std::string& words) {
  try {
    parse(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(SceneFileActors, BadActorsAreRefusedWithTheLine) {
  const std::string traj = "trajectory:\n  - {t: 0, position: [0, 0, 0], yaw: 0}\n";
  const std::string bob = "    trajectory: [{t: 0, position: [1, 0, 1], yaw: 0}]\n";
  expect_error("name: x\nactors:\n  - {size: [1, 1, 1]}\n" + traj, 3, "name");
  expect_error("name: x\nactors:\n  - name: ''\n" + bob + traj, 3, "non-empty");
  expect_error("name: x\nactors:\n  - name: bob\n" + bob + "  - name: bob\n" + bob + traj, 5,
               "taken by the actor on line 3");
  expect_error("name: x\nactors:\n  - name: character\n" + bob + traj, 3, "no actor may be named");
  expect_error("name: x\nactors:\n  - name: bob\n    size: [1, 0, 1]\n" + bob + traj, 4, "> 0");
  expect_error("name: x\nactors:\n  - name: bob\n    size: [1, 1, 1]\n" + bob + traj, 3,
               "look_at_height");
  expect_error("name: x\nactors:\n  - name: bob\n    trajectory:\n" + traj, 3, "at least one keyframe");
  expect_error("name: x\nactors:\n  - name: bob\n    mood: calm\n" + bob + traj, 4, "mood");
  expect_error("name: x\nactors:\n  - name: bob\n" + bob, 1, "shot:");
  expect_error("name: x\nactors: 3\n" + traj, 2, "list");
  expect_error("name: x\nactors:\n  - name: bob\n    trajectory: [{t: 1, position: [1, 0, 1], yaw: 0}, "
               "{t: 0, position: [1, 0, 1], yaw: 0}]\n" + traj, 4, "increase");
}

}  // namespace
}  // namespace sightline::camera
