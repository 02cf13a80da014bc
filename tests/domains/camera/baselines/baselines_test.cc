// The game-camera baselines (domains/camera/baselines/): Unreal-style spring arm and
// Cinemachine-style pull-forward, on hand-made scenes with known answers, against brute
// force (experiments/runs/independent_check.h: every box, no BVH), and on the thesis scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "sightline/domains/camera/baselines/pull_forward.h"
#include "sightline/domains/camera/baselines/sphere_probe.h"
#include "sightline/domains/camera/baselines/spring_arm.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/independent_check.h"
#include "sightline/experiments/sources/scene_files.h"

namespace sightline {
namespace {

using camera::CharacterState;
using Eigen::Vector3d;

camera::Scene scene_with(std::vector<camera::Aabb> boxes) {
  std::vector<camera::SolidBox> solids;
  for (const auto& b : boxes) solids.push_back({"", b, {}});
  camera::Trajectory walk({{0, Vector3d::Zero(), 0}, {1, Vector3d::Zero(), 0}});
  return camera::Scene("hand-made", std::move(solids), {}, camera::CharacterShape{},
                       std::move(walk), 60);
}

std::vector<experiments::SolidBox> brute_boxes(const camera::Scene& scene) {
  std::vector<experiments::SolidBox> out;
  for (const auto& s : scene.solids()) out.push_back({s.box.min, s.box.max});
  return out;
}

CharacterState standing_at(const Vector3d& feet, double yaw = 0) {
  CharacterState c;
  c.position = feet;
  c.yaw = yaw;
  return c;
}

// A profile whose arm is level: the preferred spot is at the look-at height (1.5 m), 4 m
// behind, so "distance along the arm" is plain distance along -z.
camera::CameraProfile level_profile() {
  camera::CameraProfile p;
  p.height.desired = 1.5;
  p.distance.desired = 4.0;
  return p;
}

constexpr double kDt = 1.0 / 60;

TEST(SpringArmOptions, DefaultsAreValidAndBadFieldsAreNamed) {
  EXPECT_EQ(camera::SpringArmOptions{}.validate(), "");
  camera::SpringArmOptions bad;
  bad.probe_radius = 0;
  EXPECT_NE(bad.validate().find("probe_radius"), std::string::npos);
  bad = {};
  bad.lag_speed = -1;
  EXPECT_NE(bad.validate().find("lag_speed"), std::string::npos);
  EXPECT_EQ(camera::PullForwardOptions{}.validate(), "");
  camera::PullForwardOptions bad_pull;
  bad_pull.damping = NAN;
  EXPECT_NE(bad_pull.validate().find("damping"), std::string::npos);
}

TEST(SphereProbe, FirstContactIsWhereTheBruteForceDistanceFirstReachesTheRadius) {
  // Random boxes and segments: before the reported contact every sampled centre is farther
  // than r from every box; at it the sphere touches (distance r, to the tolerance).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-5, 5), size(0.2, 2);
  int contacts = 0, stopped_early = 0;
  for (int scene_id = 0; scene_id < 20; ++scene_id) {
    std::vector<camera::Aabb> boxes;
    for (int i = 0; i < 12; ++i) {
      const Vector3d lo(pos(rng), pos(rng), pos(rng));
      boxes.push_back({lo, lo + Vector3d(size(rng), size(rng), size(rng))});
    }
    const camera::Scene scene = scene_with(boxes);
    const auto brute = brute_boxes(scene);
    const double r = 0.3;
    const camera::SceneAtTime at(scene);
    const camera::SphereProbe probe(at, r);
    for (int k = 0; k < 30; ++k) {
      const Vector3d a(pos(rng) * 1.4, pos(rng) * 1.4, pos(rng) * 1.4);
      const Vector3d b(pos(rng) * 1.4, pos(rng) * 1.4, pos(rng) * 1.4);
      const auto t = probe.first_contact(a, b);
      const double end = t ? *t : 1.0;
      const int samples = 400;
      for (int i = 0; i < samples; ++i) {
        const double u = end * i / samples;
        if (t && u >= *t - 1e-9) break;
        ASSERT_GT(experiments::distance_to_geometry(brute, a + u * (b - a)), r - 1e-9)
            << "scene " << scene_id << " segment " << k << " passes through at u=" << u;
      }
      if (t) {
        const double d = experiments::distance_to_geometry(brute, a + *t * (b - a));
        if (*t == 0) {
          EXPECT_LE(d, r);
        } else {
          // Never inside; exact, except for the rare grazing walk stopped early (still clear).
          EXPECT_GE(d, r - 1e-9) << "scene " << scene_id << " segment " << k;
          ++contacts;
          if (d > r + 1e-6) ++stopped_early;
        }
      } else {
        EXPECT_GT(experiments::distance_to_geometry(brute, b), r - 1e-9);
      }
    }
  }
  EXPECT_GT(contacts, 100);
  EXPECT_LE(stopped_early * 50, contacts) << stopped_early << " of " << contacts;  // <= 2%
}

TEST(SpringArm, PullsInToTheFirstHitMinusTheProbeRadius) {
  // Wall behind the character: its front face 2.8 m behind the look-at point. The arm is
  // level, so the camera stops at 2.8 - 0.2 = 2.6 m, at once on the first frame.
  const camera::Scene scene = scene_with({{Vector3d(-5, 0, -3.5), Vector3d(5, 5, -2.8)}});
  const camera::CameraProfile profile = level_profile();
  camera::SpringArm arm(scene, profile);
  const camera::CameraFrame& f = arm.update(standing_at(Vector3d::Zero()), kDt);
  const Vector3d look(0, 1.5, 0);
  EXPECT_TRUE(arm.pulled_in());
  EXPECT_NEAR((f.position - look).norm(), 2.8 - arm.options().probe_radius, 1e-6);
  EXPECT_NEAR(f.position.x(), 0, 1e-9);
  EXPECT_NEAR(f.position.y(), 1.5, 1e-9);
  EXPECT_TRUE(f.look_at_visible);
  EXPECT_EQ(f.target, look);
  EXPECT_GE(experiments::distance_to_geometry(brute_boxes(scene), f.position),
            arm.options().probe_radius - 1e-6);
  EXPECT_EQ(f.score.hard, 0);  // clear and visible: no hard constraint broken
}

TEST(SpringArm, PullsInOnASlopedArmWhereTheSphereTouchesTheWall) {
  // The default profile raises the arm 1 m over 4 m: the sphere's centre touches the wall
  // face z = -2.8 when its z is -2.6, i.e. at 2.6 / 4 of the arm.
  const camera::Scene scene = scene_with({{Vector3d(-5, 0, -3.5), Vector3d(5, 5, -2.8)}});
  const camera::CameraProfile profile;  // height 2.5, distance 4
  camera::SpringArm arm(scene, profile);
  const camera::CameraFrame& f = arm.update(standing_at(Vector3d::Zero()), kDt);
  const Vector3d expected = Vector3d(0, 1.5, 0) + (2.6 / 4) * Vector3d(0, 1, -4);
  EXPECT_NEAR((f.position - expected).norm(), 0, 1e-6);
}

TEST(SpringArm, WithoutObstaclesSitsAtThePreferredSpot) {
  const camera::Scene scene = scene_with({});
  const camera::CameraProfile profile;
  camera::SpringArm arm(scene, profile);
  const CharacterState c = standing_at(Vector3d(1, 0, 2), 90);
  const camera::CameraFrame& f = arm.update(c, kDt);
  EXPECT_FALSE(arm.pulled_in());
  EXPECT_NEAR((f.position - camera::ideal_camera_position(c, 2.5, 4, 0)).norm(), 0, 1e-12);
}

TEST(SpringArm, LagClosesAFixedFractionOfTheGapEachFrameAndConverges) {
  // Unreal's VInterpTo at 60 Hz with lag speed 10: each frame closes 10/60 of the gap.
  const camera::Scene scene = scene_with({});
  const camera::CameraProfile profile;
  camera::SpringArm arm(scene, profile);
  arm.update(standing_at(Vector3d::Zero()), kDt);
  const CharacterState moved = standing_at(Vector3d(0, 0, 1));  // a 1 m step forward
  const Vector3d goal = camera::ideal_camera_position(moved, 2.5, 4, 0);
  double gap = (arm.frame().position - goal).norm();
  EXPECT_NEAR(gap, 1.0, 1e-12);
  for (int i = 0; i < 60; ++i) {
    const double next = (arm.update(moved, kDt).position - goal).norm();
    EXPECT_NEAR(next, gap * (1 - 10.0 / 60), 1e-12) << "frame " << i;
    gap = next;
  }
  EXPECT_LT(gap, 1e-4);
}

TEST(SpringArm, CollisionPullInIsImmediateEvenWhileTheArmLags) {
  // The camera rests 0.3 m in front of a wall (face z = -4.3). The character backs up
  // 1.5 m in one step: the lagged end only moves to z = -4.25, which puts the probe in
  // contact; the sweep runs from the real pivot (z = -1.5), so on this very frame the camera
  // is at the contact, z = -4.3 + 0.2, not easing toward it.
  const camera::Scene scene = scene_with({{Vector3d(-5, 0, -5), Vector3d(5, 5, -4.3)}});
  const camera::CameraProfile profile = level_profile();
  camera::SpringArm arm(scene, profile);
  arm.update(standing_at(Vector3d::Zero()), kDt);
  EXPECT_FALSE(arm.pulled_in());
  EXPECT_NEAR(arm.frame().position.z(), -4, 1e-12);
  const camera::CameraFrame& f = arm.update(standing_at(Vector3d(0, 0, -1.5)), kDt);
  EXPECT_NEAR(arm.desired_end().z(), -4.25, 1e-12);  // the lagged arm
  EXPECT_TRUE(arm.pulled_in());
  EXPECT_NEAR(f.position.z(), -4.3 + arm.options().probe_radius, 1e-6);
  EXPECT_TRUE(f.look_at_visible);
}

TEST(SpringArm, FlagsThePullInJumpAsACut) {
  // A wall appears between frames (two scenes, same arm options): the camera moves 2 m in
  // one frame, far more than max_speed x dt, so the frame is a flagged cut.
  const camera::Scene open = scene_with({});
  const camera::CameraProfile profile = level_profile();
  camera::SpringArm arm(open, profile);
  arm.update(standing_at(Vector3d::Zero()), kDt);
  arm.update(standing_at(Vector3d(0, 0, 0.01)), kDt);
  EXPECT_FALSE(arm.frame().cut);  // 1 cm at 60 Hz: smooth
  const camera::Scene walled = scene_with({{Vector3d(-5, 0, -3), Vector3d(5, 5, -2.2)}});
  camera::SpringArm walled_arm(walled, profile);
  walled_arm.reset(arm.frame().position);
  const camera::CameraFrame& f = walled_arm.update(standing_at(Vector3d(0, 0, 0.01)), kDt);
  EXPECT_TRUE(f.cut);
  EXPECT_EQ(f.cut_reason, camera::CutReason::kTooFast);
}

// A pillar between the character and the preferred spot (0, 2.5, -4).
camera::Scene pillar_scene() {
  return scene_with({{Vector3d(-0.5, 0, -2.2), Vector3d(0.5, 10, -1.8)}});
}

TEST(PullForward, EndsInFrontOfThePillarWithTheCharacterVisible) {
  const camera::Scene scene = pillar_scene();
  const camera::CameraProfile profile;
  camera::PullForward cam(scene, profile);
  const CharacterState c = standing_at(Vector3d::Zero());
  for (int i = 0; i < 120; ++i) cam.update(c, kDt);
  const camera::CameraFrame& f = cam.frame();
  EXPECT_TRUE(cam.occluded());
  // On the sight line from the look-at point to the preferred spot, in front of the pillar.
  const Vector3d look(0, 1.5, 0);
  const Vector3d dir = (Vector3d(0, 2.5, -4) - look).normalized();
  EXPECT_NEAR(((f.position - look) - (f.position - look).dot(dir) * dir).norm(), 0, 1e-9);
  EXPECT_GT(f.position.z(), -1.8);
  EXPECT_TRUE(f.look_at_visible);
  EXPECT_FALSE(experiments::segment_blocked(brute_boxes(scene), f.position, look));
  EXPECT_GE(experiments::distance_to_geometry(brute_boxes(scene), f.position),
            cam.options().camera_radius - 1e-4);
  EXPECT_NEAR((f.position - cam.corrected()).norm(), 0, 1e-9);
}

TEST(PullForward, EasesInWithOccludedDampingAndOutWithReturnDamping) {
  const camera::Scene scene = pillar_scene();
  const camera::CameraProfile profile;
  camera::PullForward cam(scene, profile);
  const CharacterState clear = standing_at(Vector3d(10, 0, 0));
  const CharacterState blocked = standing_at(Vector3d::Zero());
  cam.update(clear, kDt);
  EXPECT_FALSE(cam.occluded());
  EXPECT_NEAR((cam.frame().position - cam.preferred()).norm(), 0, 1e-12);
  // In: each frame covers 1 - exp(-ln(100) dt / 0.2) of the remaining correction.
  const double in = 1 - std::exp(-std::log(100.0) * kDt / cam.options().damping_when_occluded);
  cam.update(blocked, kDt);
  double remaining = (cam.frame().position - cam.corrected()).norm();
  const double full = (cam.corrected() - cam.preferred()).norm();
  EXPECT_NEAR(remaining, full * (1 - in), 1e-9);
  EXPECT_FALSE(cam.frame().look_at_visible);  // still behind the pillar: by design
  for (int i = 0; i < 30; ++i) {
    cam.update(blocked, kDt);
    const double next = (cam.frame().position - cam.corrected()).norm();
    EXPECT_NEAR(next, remaining * (1 - in), 1e-9);
    remaining = next;
  }
  EXPECT_LT(remaining, 1e-3);
  // Out: back to the preferred spot with the slower return damping.
  const double out = 1 - std::exp(-std::log(100.0) * kDt / cam.options().damping);
  const Vector3d shown = cam.frame().position - cam.preferred();
  cam.update(standing_at(Vector3d(10, 0, 0)), kDt);
  const Vector3d now = cam.frame().position - cam.preferred();
  EXPECT_NEAR((now - shown * (1 - out)).norm(), 0, 1e-9);
}

// --- the thesis scenes ---

std::vector<std::string> thesis_scenes() {
  std::vector<std::string> out;
  for (const std::string& path :
       experiments::scene_files(std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes")) {
    out.push_back(std::filesystem::path(path).stem().string());
  }
  return out;
}

camera::Scene thesis_scene(const std::string& name) {
  return camera::read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/" + name +
                                 ".yaml");
}

TEST(Baselines, RunOnEveryThesisSceneAndFlagEveryJump) {
  std::printf("\n%-18s %-13s %8s %6s %6s %9s %9s\n", "scene", "camera", "visible%", "cuts", "jumps",
              "clear-vio", "cost-mean");
  for (const std::string& name : thesis_scenes()) {
    const camera::Scene scene = thesis_scene(name);
    for (const char* baseline : {"spring-arm", "pull-forward"}) {
      camera::ChaseCameraOptions options;
      options.solver = baseline;
      const experiments::CameraRun run = experiments::run_camera(scene, scene.profile(), options);
      ASSERT_EQ(run.trace.size(), scene.frame_count());
      const experiments::RunMetrics& m = run.metrics;
      EXPECT_EQ(m.unflagged_jumps, 0) << name << " " << baseline;
      std::printf("%-18s %-13s %8.1f %6d %6d %9d %9.3f\n", name.c_str(), baseline,
                  m.visible_percent, m.cuts, m.unflagged_jumps, m.clearance_violations,
                  m.cost_mean);
    }
  }
}

TEST(SpringArm, NeverEndsInsideGeometryOnTheThesisScenes) {
  // By design the probe keeps the camera's sphere clear, unless the pivot itself is within
  // the probe radius of a box (then the camera stays at the pivot, as Unreal's does).
  for (const std::string& name : thesis_scenes()) {
    const camera::Scene scene = thesis_scene(name);
    const auto brute = brute_boxes(scene);
    camera::SpringArm arm(scene, scene.profile());
    const double r = arm.options().probe_radius;
    for (std::size_t i = 0; i < scene.frame_count(); ++i) {
      const camera::CameraFrame& f =
          arm.update(scene.character_at(scene.frame_time(i)), 1.0 / scene.frame_rate());
      if (experiments::distance_to_geometry(brute, arm.pivot()) < r) {
        EXPECT_EQ(f.position, arm.pivot());
        continue;
      }
      ASSERT_GE(experiments::distance_to_geometry(brute, f.position), r - 1e-6)
          << name << " frame " << i;
    }
  }
}

TEST(PullForward, SeesTheCharacterWhenSettledOnAClearSightLineOnTheThesisScenes) {
  // Whenever the damping has settled (the camera is where its obstacle query put it) and the
  // ignored stretch next to the target is clear, the sight line is clear: the query is right.
  int settled = 0;
  for (const std::string& name : thesis_scenes()) {
    const camera::Scene scene = thesis_scene(name);
    const auto brute = brute_boxes(scene);
    camera::PullForward cam(scene, scene.profile());
    for (std::size_t i = 0; i < scene.frame_count(); ++i) {
      const camera::CameraFrame& f =
          cam.update(scene.character_at(scene.frame_time(i)), 1.0 / scene.frame_rate());
      if ((f.position - cam.corrected()).norm() > 1e-9) continue;
      const Vector3d dir = (cam.preferred() - f.target).normalized();
      const Vector3d near_end = f.target + cam.options().minimum_distance_from_target * dir;
      if (experiments::segment_blocked(brute, f.target, near_end)) continue;
      ++settled;
      EXPECT_FALSE(experiments::segment_blocked(brute, f.position, f.target))
          << name << " frame " << i;
      EXPECT_TRUE(f.look_at_visible) << name << " frame " << i;
    }
  }
  EXPECT_GT(settled, 100);  // the property was actually exercised
}

}  // namespace
}  // namespace sightline
