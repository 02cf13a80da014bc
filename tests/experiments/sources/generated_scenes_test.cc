// The chase camera on worlds nobody tuned it for: random pillar forests and city blocks.
// Judged by the run metrics, which use the independent brute-force checks.
#include <gtest/gtest.h>

#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/sources/scene_generator.h"

namespace sightline::experiments {
namespace {

struct Case {
  const char* kind;
  std::uint64_t seed;
};

class OcclusionOctreeOnGeneratedScene : public ::testing::TestWithParam<Case> {};

TEST_P(OcclusionOctreeOnGeneratedScene, KeepsTheCharacterInViewWithoutTouchingGeometry) {
  GeneratedSceneOptions options;
  options.seed = GetParam().seed;
  options.boxes = 300;
  options.walk_seconds = 25;
  const camera::Scene scene = std::string(GetParam().kind) == "city"
                                  ? generate_city(options)
                                  : generate_pillar_forest(options);
  camera::ChaseCameraOptions controller;
  controller.solver = "occlusion-octree";
  const CameraRun run = run_camera(scene, scene.profile(), controller);
  const RunMetrics& m = run.metrics;
  EXPECT_EQ(m.visible_percent, 100.0) << scene.name() << ": " << m.occlusion_episodes
                                      << " occlusion episodes";
  EXPECT_EQ(m.clearance_violations, 0) << scene.name();
  EXPECT_EQ(m.unflagged_jumps, 0) << scene.name();
  std::printf("[generated] %-28s frames %d cuts %d dev d %.2f m h %.2f m o %.1f deg, speed p99 "
              "%.2f, jerk p99 %.0f, solve p99 %.0f us\n",
              scene.name().c_str(), m.frames, m.cuts, m.distance_deviation_mean,
              m.height_deviation_mean, m.orientation_deviation_mean, m.speed_p99, m.jerk_p99,
              m.solve_us_p99);
}

INSTANTIATE_TEST_SUITE_P(ForestsAndCities, OcclusionOctreeOnGeneratedScene,
                         ::testing::Values(Case{"forest", 1}, Case{"forest", 2}, Case{"forest", 3},
                                           Case{"city", 1}, Case{"city", 2}, Case{"city", 3}),
                         [](const auto& info) {
                           return std::string(info.param.kind) + "_" +
                                  std::to_string(info.param.seed);
                         });

TEST(SceneGenerator, SameSeedGivesTheSameScene) {
  GeneratedSceneOptions options;
  options.seed = 7;
  const camera::Scene a = generate_city(options), b = generate_city(options);
  ASSERT_EQ(a.solids().size(), b.solids().size());
  for (std::size_t i = 0; i < a.solids().size(); ++i) {
    EXPECT_EQ(a.solids()[i].box.min, b.solids()[i].box.min);
    EXPECT_EQ(a.solids()[i].box.max, b.solids()[i].box.max);
  }
  EXPECT_EQ(a.frame_count(), b.frame_count());
}

TEST(SceneGenerator, MakesAsManyBoxesAsAskedAndKeepsThePathClear) {
  GeneratedSceneOptions options;
  options.boxes = 500;
  const camera::Scene forest = generate_pillar_forest(options);
  EXPECT_EQ(forest.solids().size(), 500u);
  for (std::size_t f = 0; f < forest.frame_count(); f += 10) {
    const auto c = forest.character_at(forest.frame_time(f));
    EXPECT_FALSE(forest.solid_overlapping(forest.character().body_at(c.position)).has_value())
        << "frame " << f;
  }
}

}  // namespace
}  // namespace sightline::experiments
