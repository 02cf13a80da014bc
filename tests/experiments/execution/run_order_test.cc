// RunOrder: the MPI dispatcher's longest-expected-first order (experiments/execution/run_order.h):
// bigger problems, slower solvers and longer scenes first; equal guesses in suite order;
// a toy run never expected to outlast the suite's time limit.
#include "sightline/experiments/execution/run_order.h"

#include <gtest/gtest.h>

#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;

TEST(RunOrder, HandsOutBiggerProblemsFirstAndKeepsSuiteOrderForEqualGuesses) {
  ScratchDir dir("order-toy");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: toy
problems:
  instances: [{nqueens: [6, 50, 20]}]
  solvers: [bnb]
  seeds: [1, 2]
)"));
  const std::vector<SuiteRun> runs = expand_runs(suite);
  ASSERT_EQ(runs.size(), 6u);  // 6 s1, 6 s2, 50 s1, 50 s2, 20 s1, 20 s2
  EXPECT_EQ(longest_first(suite, runs, {0, 1, 2, 3, 4, 5}),
            (std::vector<std::size_t>{2, 3, 4, 5, 0, 1}));
  // Only the pending runs are ordered.
  EXPECT_EQ(longest_first(suite, runs, {0, 5, 3}), (std::vector<std::size_t>{3, 5, 0}));
  EXPECT_TRUE(longest_first(suite, runs, {}).empty());
}

TEST(RunOrder, ExpectsSlowerSolversAndLongerScenesToTakeLonger) {
  ScratchDir dir("order-camera");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: camera
camera:
  scenes: [scenes/room.yaml, scenes/wall.yaml]
  solvers: [spring-arm, occlusion-octree>ceres-refine, occlusion-octree]
)"));
  const std::vector<SuiteRun> runs = expand_runs(suite);
  // room: spring-arm, pipeline, octree (0..2); wall: the same (3..5).
  ASSERT_EQ(runs.size(), 6u);
  const std::size_t room_frames = suite.scenes[0].scene->frame_count();
  const std::size_t wall_frames = suite.scenes[1].scene->frame_count();
  ASSERT_GT(wall_frames, room_frames);  // 1.6 s against 1.5 s at 30 frames a second
  // Proportional to the frames for the same solver.
  for (std::size_t s = 0; s < 3; ++s) {
    EXPECT_NEAR(expected_run_seconds(suite, runs[3 + s]) / expected_run_seconds(suite, runs[s]),
                static_cast<double>(wall_frames) / static_cast<double>(room_frames), 1e-12);
  }
  // A pipeline runs the octree and then Ceres each frame: slower than the octree alone.
  EXPECT_EQ(longest_first(suite, runs, {0, 1, 2, 3, 4, 5}),
            (std::vector<std::size_t>{4, 1, 5, 2, 3, 0}));
}

TEST(RunOrder, NeverExpectsAToyRunToOutlastTheTimeLimit) {
  ScratchDir dir("order-limit");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: limited
problems:
  instances: [{nqueens: [10, 300]}]
  solvers: [sls]
  limits: {time_seconds: 0.05}
)"));
  const std::vector<SuiteRun> runs = expand_runs(suite);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_LT(expected_run_seconds(suite, runs[0]), 0.05);
  EXPECT_GT(expected_run_seconds(suite, runs[0]), 0.0);
  EXPECT_DOUBLE_EQ(expected_run_seconds(suite, runs[1]), 0.05);
}

}  // namespace
}  // namespace sightline::experiments
