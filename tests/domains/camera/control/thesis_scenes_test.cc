// The chase camera on every thesis scene (experiments/scenes/), judged independently.
//
// Visibility and clearance are checked with experiments/runs/independent_check.h (every box, a
// separate clipping routine), never with the controller's own flag. Every frame-to-frame
// move longer than the smooth-motion bound must carry the cut flag.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/independent_check.h"
#include "tests/domains/camera/control/independent_judge.h"
#include "sightline/experiments/sources/scene_files.h"

namespace sightline {
namespace {

std::vector<std::string> thesis_scenes() {
  std::vector<std::string> out;
  for (const std::string& path :
       experiments::scene_files(std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes")) {
    out.push_back(std::filesystem::path(path).stem().string());
  }
  return out;
}

std::string scene_path(const std::string& name) {
  return std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/" + name + ".yaml";
}

class OcclusionOctreeOnThesisScene : public ::testing::TestWithParam<std::string> {};

TEST_P(OcclusionOctreeOnThesisScene, KeepsTheCharacterVisibleAndTheCameraClearInEveryFrame) {
  const camera::Scene scene = camera::read_scene_file(scene_path(GetParam()));
  camera::ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  const experiments::CameraRun run = experiments::run_camera(scene, scene.profile(), options);
  ASSERT_EQ(run.trace.size(), scene.frame_count());
  const Violations v = independent_violations(scene, options, run);
  EXPECT_EQ(v.hidden, 0);
  EXPECT_EQ(v.too_close, 0);
  EXPECT_EQ(v.unflagged, 0);
  // Quality, not only visibility (printed for the record; bounds are loose on purpose but
  // catch a camera that hugs the character or jitters).
  const auto& m = run.metrics;
  std::printf(
      "[quality] %-16s cuts %d  dev h %.2f m  d %.2f m  o %.1f deg  speed p99 %.2f m/s  "
      "jerk p99 %.0f m/s^3  solve p50 %.0f us p99 %.0f us\n",
      GetParam().c_str(), m.cuts, m.height_deviation_mean, m.distance_deviation_mean,
      m.orientation_deviation_mean, m.speed_p99, m.jerk_p99, m.solve_us_p50, m.solve_us_p99);
}

INSTANTIATE_TEST_SUITE_P(AllThesisScenes, OcclusionOctreeOnThesisScene,
                         ::testing::ValuesIn(thesis_scenes()), [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(ChaseCamera, TwoSmoothingStagesKeepEveryGuaranteeAndLowerTheJerk) {
  // A second low-pass stage on the solver's target rounds off the corners of its path; the
  // visibility guard still vets every step, so nothing else may change for the worse.
  for (const char* name : {"grand-tour", "crammed-doorway", "into-corner"}) {
    SCOPED_TRACE(name);
    const camera::Scene scene = camera::read_scene_file(scene_path(name));
    camera::ChaseCameraOptions one;
    one.solver = "occlusion-octree";
    camera::ChaseCameraOptions two = one;
    two.target_smoothing_stages = 2;
    const experiments::CameraRun a = experiments::run_camera(scene, scene.profile(), one);
    const experiments::CameraRun b = experiments::run_camera(scene, scene.profile(), two);
    const Violations v = independent_violations(scene, two, b);
    EXPECT_EQ(v.hidden + v.too_close + v.unflagged, 0);
    EXPECT_LT(b.metrics.jerk_p99, a.metrics.jerk_p99);
  }
}

TEST(ChaseCameraOptions, SmoothingStagesOutsideOneToFourAreRefused) {
  camera::ChaseCameraOptions o;
  EXPECT_EQ(o.validate(), "");
  for (int stages : {0, 5, -1}) {
    o.target_smoothing_stages = stages;
    EXPECT_NE(o.validate().find("target_smoothing_stages"), std::string::npos) << stages;
  }
  o.target_smoothing_stages = 4;
  EXPECT_EQ(o.validate(), "");
}

TEST(BourneOctree, AsPublishedLosesSightOfTheCharacterInTheEnclosedRoom) {
  // Bourne & Sattar's controller goes wherever its solver says (no visibility guard), keeps
  // the profile's distance inside rooms (area adaptation is Ali's), and its solver handles
  // occlusion only through the four-ray height tweak: in a small room it picks spots behind
  // the walls (thesis fig. 24), as the independent check sees.
  const camera::Scene scene = camera::read_scene_file(scene_path("rotate-in-room"));
  camera::CameraProfile published = scene.profile();
  published.enclosed = {};
  published.semi_enclosed = {};
  camera::ChaseCameraOptions options;
  options.solver = "bourne-octree";
  options.visibility_guard = false;
  const experiments::CameraRun run = experiments::run_camera(scene, published, options);
  EXPECT_LT(run.metrics.visible_percent, 90.0);
  // Ali's solver under the very same controller keeps it in view.
  options.solver = "occlusion-octree";
  const experiments::CameraRun ali = experiments::run_camera(scene, scene.profile(), options);
  EXPECT_GT(ali.metrics.visible_percent, run.metrics.visible_percent);
}

TEST(ChaseCamera, SameSceneSolverAndSeedGiveTheSameTraceByteForByte) {
  const camera::Scene scene = camera::read_scene_file(scene_path("crammed-doorway"));
  camera::ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  const auto dir = std::filesystem::temp_directory_path();
  const std::string a = (dir / "sightline_det_a.csv").string();
  const std::string b = (dir / "sightline_det_b.csv").string();
  auto strip_timing = [](std::vector<experiments::TraceRow> rows) {
    for (auto& r : rows) r.solve_us = 0;  // wall time is the one thing that may differ
    return rows;
  };
  experiments::write_trace_csv(
      a, strip_timing(experiments::run_camera(scene, scene.profile(), options).trace));
  experiments::write_trace_csv(
      b, strip_timing(experiments::run_camera(scene, scene.profile(), options).trace));
  std::ifstream fa(a), fb(b);
  const std::string ta((std::istreambuf_iterator<char>(fa)), {});
  const std::string tb((std::istreambuf_iterator<char>(fb)), {});
  EXPECT_FALSE(ta.empty());
  EXPECT_EQ(ta, tb);
}

}  // namespace
}  // namespace sightline
