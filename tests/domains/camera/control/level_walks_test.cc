// The chase camera on walks through real Quake III maps (experiments/scenes/levels/, made by
// `sightline level walk` on Debian's OpenArena maps), judged independently: the look-at point
// visible in every frame, the camera never within its clearance radius of a surface, never
// inside solid matter or outside the world, every jump flagged as a cut. The judge is
// independent_judge.h (a brute-force grid of its own over the level's triangles, not Embree),
// never the controller's own flag. The default camera's cuts are held to issue 24's bound
// (never two within 1 s, at most 2 in any 60 s), but on the one walk known to break it;
// the share of frames with half the body visible to the spring arm's on the same walk, and
// the jerk p99 to the thesis camera's (baselines.h), but on the walks known to fall short.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/sources/scene_files.h"
#include "tests/domains/camera/control/baselines.h"
#include "tests/domains/camera/control/cut_bound.h"
#include "tests/domains/camera/control/independent_judge.h"

namespace sightline {
namespace {

const std::string kLevels = std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/levels";

std::vector<std::string> level_walks() {
  std::vector<std::string> out;
  if (!std::filesystem::is_directory(kLevels)) return out;
  for (const std::string& path : experiments::scene_files(kLevels)) {
    out.push_back(std::filesystem::path(path).stem().string());
  }
  return out;
}

// Measured 2026-11-27: half the body on oa_thor-walk2, 3 and 5 (98.0, 96.5 and 98.5%
// against the arm's 99.5, 98.9 and 99.8: pillars and ledges that hide the legs), and the
// jerk of oa_thor-walk3 (327 against 296 m/s^3: escapes round its pillars).
const KnownShortfalls kKnown{{"oa_thor-walk2", "oa_thor-walk3", "oa_thor-walk5"}, {"oa_thor-walk3"}};

class OcclusionOctreeOnLevelWalk : public ::testing::TestWithParam<std::string> {};

TEST_P(OcclusionOctreeOnLevelWalk, KeepsTheCharacterVisibleAndTheCameraInTheOpenInEveryFrame) {
  const camera::Scene scene = camera::read_scene_file(kLevels + "/" + GetParam() + ".yaml");
  ASSERT_NE(scene.level(), nullptr);
  camera::ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  const experiments::CameraRun run = experiments::run_camera(scene, scene.profile(), options);
  ASSERT_EQ(run.trace.size(), scene.frame_count());
  const Violations v = independent_violations(scene, options, run);
  EXPECT_EQ(v.hidden, 0);
  EXPECT_EQ(v.too_close, 0);
  EXPECT_EQ(v.in_solid, 0);
  EXPECT_EQ(v.unflagged, 0);
  const std::vector<double> cuts = cut_times(run.trace);
  // On ctf_compromise-walk2 she turns 60-90 degrees on the spot 4 times in 80 s and walks
  // on round an edge, each time with the camera 2.5-4 m to her side: 4 forced cuts
  // (docs/EXPERIMENTS.md). Held to still breaking the bound, so that the day it stops, this
  // exception goes.
  if (GetParam() == "ctf_compromise-walk2") {
    EXPECT_FALSE(cut_bound_breaches(cuts).empty())
        << "within the bound now: drop the exception";
  } else {
    expect_within_cut_bound(GetParam(), cuts);
  }
  const experiments::CameraRun arm = spring_arm_run(scene, scene.profile());
  const experiments::CameraRun thesis = thesis_run(scene);
  expect_no_worse_than_baselines(GetParam(), run.metrics.body_half_visible_percent,
                                 arm.metrics.body_half_visible_percent, run.metrics.jerk_p99,
                                 thesis.metrics.jerk_p99, kKnown);
  const auto& m = run.metrics;
  std::printf("%s: %d frames, %d cuts, visible fraction %.2f, distance dev %.2f m, solve p99 %.0f us\n",
              GetParam().c_str(), m.frames, m.cuts, m.visible_fraction_mean,
              m.distance_deviation_mean, m.solve_us_p99);
}

INSTANTIATE_TEST_SUITE_P(ShippedWalks, OcclusionOctreeOnLevelWalk, ::testing::ValuesIn(level_walks()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(OcclusionOctreeOnLevelWalk);

TEST(LevelWalks, AtLeastThreeAreShipped) { EXPECT_GE(level_walks().size(), 3u); }

}  // namespace
}  // namespace sightline
