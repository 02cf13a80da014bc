// Issue 24's two comparisons of the default camera with baselines filmed on the same walk:
// at least half the character's body visible in at least as many frames as the spring arm
// shows it, and a jerk p99 no higher than the thesis' reactive camera's. Both figures are
// the suite's metrics (experiments/runs/metrics.h: the body's visible share by sight lines
// of its own to the body's samples, the jerk by differences of the trace skipping cuts),
// never the controller's own flags.
//
// The runs known to fall short are named by each test, with the figures they had when
// listed: each of them is held to still falling short, so that the day one stops, its
// exception goes; every other run is held to the comparison. docs/EXPERIMENTS.md ("The
// default camera against the thesis camera and the spring arm") says why they fall short.
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "sightline/domains/camera/profile_file.h"
#include "sightline/experiments/runs/camera_run.h"

namespace sightline {

struct KnownShortfalls {
  std::set<std::string> body;  // runs showing half the body less often than the spring arm
  std::set<std::string> jerk;  // runs with a higher jerk p99 than the thesis camera
};

// One comparison of `run`: `met` whether it holds, `known` whether the run is listed as
// falling short of it; `what` says which, with the two figures.
inline void expect_comparison(const std::string& run, bool known, bool met, const std::string& what,
                              double value, double baseline) {
  if (known) {
    EXPECT_FALSE(met) << run << ": " << what << ": " << value << " against " << baseline
                      << ", met now: drop it from the known shortfalls";
  } else {
    EXPECT_TRUE(met) << run << ": " << what << ": " << value << " against " << baseline;
  }
}

// `body` and `arm_body`: percent of frames with at least half the body visible (the
// default camera's, the spring arm's); `jerk` and `thesis_jerk`: jerk p99, m/s^3.
inline void expect_no_worse_than_baselines(const std::string& run, double body, double arm_body,
                                           double jerk, double thesis_jerk,
                                           const KnownShortfalls& known) {
  expect_comparison(run, known.body.count(run) > 0, body >= arm_body,
                    "% of frames with half the body visible, against the spring arm's", body, arm_body);
  expect_comparison(run, known.jerk.count(run) > 0, jerk <= thesis_jerk,
                    "jerk p99 (m/s^3), against the thesis camera's", jerk, thesis_jerk);
}

// The baselines filming `scene`: the spring arm under `profile` (the default camera's), and
// the thesis' reactive camera (preset `thesis`, occlusion-octree).
inline experiments::CameraRun spring_arm_run(const camera::Scene& scene,
                                             const camera::CameraProfile& profile) {
  camera::ChaseCameraOptions options;
  options.solver = "spring-arm";
  return experiments::run_camera(scene, profile, options);
}
inline experiments::CameraRun thesis_run(const camera::Scene& scene) {
  camera::ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  return experiments::run_camera(scene, camera::preset_profile("thesis"), options);
}

}  // namespace sightline
