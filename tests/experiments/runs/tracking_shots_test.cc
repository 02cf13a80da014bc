// Tracking shots (scenes with a shot: block filmed frame by frame) on every shipped shot
// scene (experiments/scenes/shots/): no unflagged jump, no two cuts within the minimum shot
// length, every frame's pose within the shot's rules; the people shown (by the independent
// check of shot_metrics.h), the satisfaction and the cuts are printed for the record. And
// the independent check agrees with the shot's own `visible` measure on random poses: two
// implementations of FORMATS.md's rule, sharing no code.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/shot_metrics.h"
#include "sightline/experiments/sources/tracking_shot_generator.h"
#include "tests/shipped_files.h"

namespace sightline::experiments {
namespace {

TEST(TrackingShots, EveryShippedShotSceneIsFilmedSmoothlyWithinTheShotsRules) {
  const std::vector<std::string> scenes = shipped_yaml_files("experiments/scenes/shots");
  ASSERT_GE(scenes.size(), 5u);
  for (const std::string& path : scenes) {
    const camera::Scene scene = camera::read_scene_file(path);
    ASSERT_NE(scene.shot(), nullptr) << path;
    camera::ChaseCameraOptions options;
    options.solver = "";  // the recommended composition solver
    const CameraRun run = run_camera(scene, scene.profile(), options);
    ASSERT_TRUE(run.shot.has_value());
    const RunMetrics& m = run.metrics;
    EXPECT_EQ(m.unflagged_jumps, 0) << path;
    if (m.cuts > 1) {
      EXPECT_GE(m.shortest_shot_seconds, 1.0 - 1e-9) << path;
    }
    EXPECT_EQ(run.shot->feasible_percent, 100) << path;
    // Every frame holds the lens columns.
    for (const TraceRow& r : run.trace) ASSERT_GT(r.fov, 0) << path;
    std::printf("%-20s", scene.name().c_str());
    for (const PersonShown& p : run.shot->people) std::printf(" %s %.1f%%", p.name.c_str(), p.shown_percent);
    std::printf("; satisfaction mean %.3f p10 %.3f; %d cuts\n", run.shot->satisfaction_mean,
                run.shot->satisfaction_p10, m.cuts);
    // The target: every person the shot names shown in at least 99% of frames.
    EXPECT_GE(run.shot->shown_percent_min, 99) << path;
    // The engines' group camera on the same scene, for the record.
    camera::ChaseCameraOptions group;
    group.solver = "group-framing";
    const CameraRun baseline = run_camera(scene, scene.profile(), group);
    std::printf("%-20s", "  group-framing");
    for (const PersonShown& p : baseline.shot->people) std::printf(" %s %.1f%%", p.name.c_str(), p.shown_percent);
    std::printf("; satisfaction mean %.3f p10 %.3f; %d cuts\n", baseline.shot->satisfaction_mean,
                baseline.shot->satisfaction_p10, baseline.metrics.cuts);
  }
}

// Generated tracking shots (experiments/sources/tracking_shot_generator.h: streets past
// columns with vehicles, chases round corners, crossings, circling), shots nobody tuned the
// camera for: smooth (no unflagged jump, no two cuts within 1 s), within the shot's region
// and clearance almost always, and the people shown (independent check) -- printed per seed,
// with the family's mean, median and worst least-shown person as a floor against regressions
// (2026-11-27: 99.4, 100 and 95.3; the 99% is met on 13 of these 16).
TEST(TrackingShots, GeneratedTrackingShotsAreFilmedSmoothlyAndKeepThePeopleShown) {
  std::vector<double> least;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    TrackingShotOptions o;
    o.seed = seed;
    const camera::Scene scene = generate_tracking_shot(o);
    camera::ChaseCameraOptions options;
    options.solver = "";
    const CameraRun run = run_camera(scene, scene.profile(), options);
    ASSERT_TRUE(run.shot.has_value());
    EXPECT_EQ(run.metrics.unflagged_jumps, 0) << "seed " << seed;
    if (run.metrics.cuts > 1) {
      EXPECT_GE(run.metrics.shortest_shot_seconds, 1.0 - 1e-9) << "seed " << seed;
    }
    EXPECT_GE(run.shot->feasible_percent, 95) << "seed " << seed;
    EXPECT_GT(run.shot->shown_percent_min, 50) << "seed " << seed;
    std::printf("seed %2d %-62.62s", static_cast<int>(seed), scene.description().c_str());
    for (const PersonShown& p : run.shot->people) std::printf(" %s %.1f%%", p.name.c_str(), p.shown_percent);
    std::printf("; %d cuts\n", run.metrics.cuts);
    least.push_back(run.shot->shown_percent_min);
  }
  std::sort(least.begin(), least.end());
  double sum = 0;
  for (double v : least) sum += v;
  const double mean = sum / static_cast<double>(least.size()), median = least[least.size() / 2];
  std::printf("least-shown person: mean %.1f%%, median %.1f%%, worst %.1f%%\n", mean, median, least.front());
  EXPECT_GE(median, 99);
  EXPECT_GE(mean, 98);
  EXPECT_GE(least.front(), 90);
}

TEST(TrackingShots, TheIndependentCheckAgreesWithTheShotsVisibleMeasure) {
  // Two people among boxes that hide parts of them from many places; a visible property per
  // person asking half their samples.
  const camera::Scene scene = camera::parse_scene(csp::parse_yaml(
      "name: agree\n"
      "boxes:\n"
      "  - {min: [-1, 0, 2], max: [1, 1.2, 2.5]}\n"
      "  - {min: [2, 0, -1], max: [2.4, 3, 1]}\n"
      "  - {min: [-3, 1, -3], max: [-2, 2, 3]}\n"
      "actors:\n"
      "  - {name: ann, trajectory: [{t: 0, position: [0, 0, 0], yaw: 0}]}\n"
      "  - {name: ben, trajectory: [{t: 0, position: [0.5, 0, -1.5], yaw: 0}]}\n"
      "shot:\n  region: {min: [-8, 0.2, -8], max: [8, 4, 8]}\n  properties:\n"
      "    - {kind: visible, target: ann, range: [0.5, 1]}\n"
      "    - {kind: visible, target: ben, range: [0.5, 1]}\n",
      "agree.yaml"));
  const camera::CompositionProblem problem(scene, *scene.shot(), 0);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    TraceRow row;
    row.camera = Eigen::Vector3d(7 * u(rng), 2 + 1.8 * u(rng), 7 * u(rng));
    row.target = Eigen::Vector3d(0, 1, 0);
    row.fov = 170;  // everyone in the image, so only sight decides
    // The shot's measure: the fraction of each person's samples seen.
    camera::CameraPose pose;
    pose.position = row.camera;
    pose.look_at = row.target;
    pose.fov = 170;
    pose.aspect = scene.shot()->aspect;
    const camera::ShotEvaluation e = problem.evaluate(pose);
    // The independent check counts a person shown when the half the shot asks for is seen:
    // compare that verdict with the shot's measured fraction.
    const ShotMetrics m = shot_metrics(scene, {row});
    for (std::size_t i = 0; i < 2; ++i) {
      const bool half_seen = e.measures[i] * camera::kPersonSamples >= 0.5 * camera::kPersonSamples - 1e-9;
      const camera::PersonAtTime& person = problem.world().people()[i];
      const std::optional<camera::View> view = camera::View::of(pose);
      const bool in_front = view && view->depth((person.body.min + person.body.max) / 2) > 0.05;
      if (!in_front) continue;
      EXPECT_EQ(m.people[i].shown_percent == 100, half_seen)
          << "trial " << trial << " person " << i << " measure " << e.measures[i] << " camera "
          << row.camera.transpose();
      ++compared;
    }
  }
  EXPECT_GT(compared, 300);
}

}  // namespace
}  // namespace sightline::experiments
