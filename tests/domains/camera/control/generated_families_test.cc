// The anticipating camera (preset `anticipating`, solver occlusion-octree) on seeded scene
// families nobody tuned it on (experiments/sources/scene_families.h): corridors with L turns, U turns
// and zigzags under ceilings as low as 2.2 m, T and X junctions, rooms joined by doorways,
// colonnades, a street with traffic crossing behind the character, stairs up and down.
//
// Each generated walk is first checked valid here, independently of the generator (its own
// interior-overlap test of the body against every box at every frame, movers 0.3 m or more
// from the body, the camera's start clear). Each run is then judged with the independent
// checker (experiments/runs/independent_check.h through experiments::metrics_input: every box
// and every mover at the frame's time, never the controller's flag): the look-at point
// visible in every frame, no frame within the clearance radius, no move longer than
// max_speed x dt without the cut flag, and at most 2 discretionary cuts (any reason but
// "visibility-lost") per minute of each walk; all cuts pooled over each family at most 2
// per minute; the share of frames with half the body visible held to the spring arm's on the
// same walk and the jerk p99 to the thesis camera's (baselines.h), but on the walks known to
// fall short (kKnown). The seeds are fixed: 1-20 of each family. Without the planner's trail
// (horizon_planner.h) colonnade seed 6 and rooms seed 12 fail the discretionary-cut check.
//
// SIGHTLINE_FAMILIES_TABLE=N (N seeds per family) prints instead the table of
// docs/EXPERIMENTS.md ("Generated families"): anticipating, anticipating-path and the
// reactive thesis-default on seeds 1..N, the metrics' figures per family.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "sightline/domains/camera/profile_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/independent_check.h"
#include "sightline/experiments/runs/metrics.h"
#include "sightline/experiments/sources/scene_families.h"
#include "sightline/experiments/runs/trace.h"
#include "tests/domains/camera/control/baselines.h"
#include "tests/domains/camera/control/family_checks.h"

namespace sightline {
namespace {

using experiments::SceneFamily;

experiments::CameraRun run(camera::Scene& scene, const std::string& preset) {
  scene.set_profile(camera::preset_profile(preset), "preset " + preset);
  camera::ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  experiments::CameraRun r = experiments::run_camera(scene, scene.profile(), options);
  if (const char* dir = std::getenv("SIGHTLINE_FAMILIES_TRACES")) {
    experiments::write_trace_csv(std::string(dir) + "/" + scene.name() + "-" + preset + ".csv",
                                 r.trace);
  }
  return r;
}

// The walks of seeds 1-20 known to fall short (measured 2026-11-28; docs/EXPERIMENTS.md).
// The body (default camera against spring arm, % of frames): colonnade 7 (98.9 / 100) and
// 19 (99.4 / 100), corridor 6 (97.6 / 100) and 10 (95.9 / 100), rooms 2, 4, 9 and 20
// (98.8-99.9 / 100), stairs 18 (92.5 / 98.9), traffic 4 (98.6 / 100) and 17 (99.7 / 100).
// The jerk p99 (default against thesis camera, m/s^3, escapes): colonnade 1 (360 / 252), 3
// (19 / 17), 7 (5,678 / 312) and 19 (12,438 / 1,304), corridor 2 (1,164 / 237), 5 (2,069 /
// 330), 8 (306 / 242) and 20 (336 / 221), rooms 7 (3,106 / 310) and 10 (35,235 / 267),
// stairs 8 (2,099 / 223).
const KnownShortfalls kKnown{
    {"colonnade-seed-7", "colonnade-seed-19", "corridor-seed-6", "corridor-seed-10",
     "rooms-seed-2", "rooms-seed-4", "rooms-seed-9", "rooms-seed-20", "stairs-seed-18",
     "traffic-seed-4", "traffic-seed-17"},
    {"colonnade-seed-1", "colonnade-seed-3", "colonnade-seed-7", "colonnade-seed-19",
     "corridor-seed-2", "corridor-seed-5", "corridor-seed-8", "corridor-seed-20", "rooms-seed-7",
     "rooms-seed-10", "stairs-seed-8"}};

// The anticipating camera on `seeds` of `family`, every walk checked.
void check_family(SceneFamily family, std::uint64_t first, std::uint64_t last) {
  int cuts = 0;
  double seconds = 0;
  for (std::uint64_t seed = first; seed <= last; ++seed) {
    camera::Scene scene = experiments::generate_family(family, seed);
    expect_valid_walk(scene);
    const experiments::CameraRun r = run(scene, "anticipating");
    camera::ChaseCameraOptions options;
    const Judged j = judge(scene, options, r, true);
    EXPECT_EQ(j.hidden, 0) << scene.name() << " (" << scene.description() << ")";
    EXPECT_EQ(j.too_close, 0) << scene.name() << " (" << scene.description() << ")";
    EXPECT_EQ(j.unflagged, 0) << scene.name();
    EXPECT_LE(j.discretionary, 2.0 * j.seconds / 60.0)
        << scene.name() << ": " << j.discretionary << " discretionary cuts in " << j.seconds
        << " s";
    const experiments::CameraRun arm = spring_arm_run(scene, scene.profile());
    const experiments::CameraRun thesis = thesis_run(scene);
    expect_no_worse_than_baselines(scene.name(), r.metrics.body_half_visible_percent,
                                   arm.metrics.body_half_visible_percent, r.metrics.jerk_p99,
                                   thesis.metrics.jerk_p99, kKnown);
    cuts += j.cuts;
    seconds += j.seconds;
    std::printf("[families] %-22s %5.1f s  cuts %d  hidden %d  jerk p99 %.0f  (%s)\n",
                scene.name().c_str(), j.seconds, j.cuts, j.hidden, r.metrics.jerk_p99,
                scene.description().c_str());
  }
  EXPECT_LE(cuts / (seconds / 60), 2.0)
      << to_string(family) << ": " << cuts << " cuts in " << seconds << " s";
}

// The table of docs/EXPERIMENTS.md: per family and camera, the metrics' figures over seeds.
void print_table(std::uint64_t seeds) {
  std::printf(
      "| family | camera | walks (s) | look-at visible %% (worst walk) | unflagged jumps | "
      "frames within clearance | cuts forced / discretionary per min | jerk p99 median "
      "(max) m/s^3 | distance dev (m) | height dev (m) | failing walks |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (SceneFamily family : experiments::all_scene_families()) {
    for (const char* preset : {"anticipating", "anticipating-path", "thesis-default"}) {
      double seconds = 0, worst = 100, distance = 0, height = 0, visible = 0;
      int unflagged = 0, close = 0, forced = 0, discretionary = 0, failing = 0;
      std::vector<double> jerks;
      std::string failed;
      for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        camera::Scene scene = experiments::generate_family(family, seed);
        // SIGHTLINE_FAMILIES_ONLY=name runs only the scenes whose name holds it (to trace one).
        const char* only = std::getenv("SIGHTLINE_FAMILIES_ONLY");
        if (only != nullptr && scene.name().find(only) == std::string::npos) continue;
        const experiments::CameraRun r = run(scene, preset);
        const experiments::RunMetrics& m = r.metrics;
        seconds += m.duration_seconds;
        visible += m.visible_percent * m.duration_seconds;
        worst = std::min(worst, m.visible_percent);
        unflagged += m.unflagged_jumps;
        close += m.clearance_violations;
        forced += m.forced_cuts;
        discretionary += m.discretionary_cuts;
        jerks.push_back(m.jerk_p99);
        distance += m.distance_deviation_mean * m.duration_seconds;
        height += m.height_deviation_mean * m.duration_seconds;
        const bool fails = m.visible_percent < 100 || m.unflagged_jumps > 0 ||
                           m.clearance_violations > 0 ||
                           m.discretionary_cuts > 2.0 * m.duration_seconds / 60.0;
        if (fails) {
          ++failing;
          failed += " " + std::to_string(seed);
        }
      }
      if (jerks.empty()) continue;
      std::sort(jerks.begin(), jerks.end());
      const double minutes = seconds / 60;
      std::printf(
          "| %s | %s | %llu (%.0f) | %.2f (%.1f) | %d | %d | %.2f / %.2f | %.0f (%.0f) | "
          "%.2f | %.2f | %d%s%s |\n",
          to_string(family).c_str(), preset, static_cast<unsigned long long>(seeds), seconds,
          visible / seconds, worst, unflagged, close, forced / minutes, discretionary / minutes,
          jerks[jerks.size() / 2], jerks.back(), distance / seconds, height / seconds, failing,
          failed.empty() ? "" : ": seeds", failed.c_str());
      std::fflush(stdout);
    }
  }
}

TEST(GeneratedFamilies, TableWhenAsked) {
  const char* n = std::getenv("SIGHTLINE_FAMILIES_TABLE");
  if (n == nullptr) GTEST_SKIP() << "set SIGHTLINE_FAMILIES_TABLE=N to print the table";
  print_table(std::strtoull(n, nullptr, 10));
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(GeneratedFamilies, AnticipatingCameraOnCorridorsKeepsTheLookAtVisibleClearAndCutsRarely) {
  check_family(SceneFamily::kCorridor, 1, 20);
}
TEST(GeneratedFamilies, AnticipatingCameraOnJunctionsKeepsTheLookAtVisibleClearAndCutsRarely) {
  check_family(SceneFamily::kJunction, 1, 20);
}
TEST(GeneratedFamilies, AnticipatingCameraOnRoomsKeepsTheLookAtVisibleClearAndCutsRarely) {
  check_family(SceneFamily::kRooms, 1, 20);
}
TEST(GeneratedFamilies, AnticipatingCameraOnColonnadesKeepsTheLookAtVisibleClearAndCutsRarely) {
  check_family(SceneFamily::kColonnade, 1, 20);
}
TEST(GeneratedFamilies, AnticipatingCameraInTrafficKeepsTheLookAtVisibleClearAndCutsRarely) {
  check_family(SceneFamily::kTraffic, 1, 20);
}
TEST(GeneratedFamilies, AnticipatingCameraOnStairsKeepsTheLookAtVisibleClearAndCutsRarely) {
  check_family(SceneFamily::kStairs, 1, 20);
}

}  // namespace
}  // namespace sightline
