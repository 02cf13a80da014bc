// occlusion-octree's alternatives (its best points in other regions, handed to the next stage
// of a pipeline) on camera frames met by the chase camera in two thesis scenes: none unless
// asked, asking never makes its best worse, and each alternative is feasible, cheapest first
// and in another region than the best and than the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/solvers/registry.h"

namespace sightline::camera {
namespace {

struct Frame {
  CharacterState character;
  Eigen::Vector3d last_camera;
  double dt;
};

// Every `stride`-th frame of the occlusion-octree chase camera's run through `scene`.
std::vector<Frame> sample_frames(const Scene& scene, std::size_t stride) {
  std::vector<Frame> frames;
  ChaseCamera chase(scene, scene.profile(), {});
  double previous = scene.frame_time(0) - 1.0 / scene.frame_rate();
  for (std::size_t i = 0; i < scene.frame_count(); ++i) {
    const double t = scene.frame_time(i);
    const CharacterState c = scene.character_at(t);
    const double dt = std::max(t - previous, 1e-3);
    previous = t;
    if (i % stride == stride / 2) frames.push_back({c, chase.frame().position, dt});
    chase.update(c, dt);
  }
  return frames;
}

Scene thesis_scene(const std::string& name) {
  return read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/" + name +
                         ".yaml");
}

class OcclusionOctreeAlternatives : public ::testing::TestWithParam<std::string> {};

TEST_P(OcclusionOctreeAlternatives, AreNoneUnlessAskedAndAskingNeverWorsensTheBest) {
  const Scene scene = thesis_scene(GetParam());
  auto& registry = solver_registry();
  auto plain = registry.create("occlusion-octree");
  auto asked = registry.create("occlusion-octree");
  int handed_over = 0, compared = 0;
  const std::vector<Frame> frames = sample_frames(scene, 10);
  for (const Frame& f : frames) {
    CameraProblem problem(scene);
    problem.set_frame(f.character, f.last_camera, f.dt);
    const double start[3] = {f.last_camera.x(), f.last_camera.y(), f.last_camera.z()};
    solvers::SolveContext context;
    const solvers::SolverResult without = plain->solve(problem.problem(), start, context);
    EXPECT_TRUE(without.alternatives.empty());
    context.alternatives_wanted = 3;
    const solvers::SolverResult with = asked->solve(problem.problem(), start, context);
    EXPECT_LE(with.alternatives.size(), 3u);
    handed_over += !with.alternatives.empty();
    // Without an orientation sweep, the octree's costs are the problem's soft costs, and
    // the best when asked is the cheapest of a superset of the candidates.
    if (without.message.empty() && with.message.empty() && without.feasible()) {
      ++compared;
      EXPECT_TRUE(with.feasible());
      EXPECT_FALSE(without.score.better_than(with.score))
          << without.brief_report("plain") << "\n" << with.brief_report("asked");
    }
  }
  const int n = static_cast<int>(frames.size());
  EXPECT_GT(compared, n / 2);
  EXPECT_GT(handed_over, n / 4) << "of " << n;  // the next test's checks are not vacuous
}

TEST_P(OcclusionOctreeAlternatives, AreFeasibleCheapestFirstAndInOtherRegions) {
  const Scene scene = thesis_scene(GetParam());
  auto octree = solver_registry().create("occlusion-octree");
  for (const Frame& f : sample_frames(scene, 10)) {
    CameraProblem problem(scene);
    problem.set_frame(f.character, f.last_camera, f.dt);
    const csp::Problem& p = problem.problem();
    const double start[3] = {f.last_camera.x(), f.last_camera.y(), f.last_camera.z()};
    solvers::SolveContext context;
    context.alternatives_wanted = 4;
    const solvers::SolverResult r = octree->solve(p, start, context);
    if (!r.message.empty()) continue;  // swept orientation: costs are not the problem's
    // A quarter of the first cube's half-size, itself half the smallest domain width.
    double width = 1e9;
    for (csp::VariableId v = 0; v < 3; ++v) {
      width = std::min(width, p.variable(v).domain.upper() - p.variable(v).domain.lower());
    }
    const double separation = 0.25 * 0.5 * width;
    const Eigen::Vector3d best(r.best[0], r.best[1], r.best[2]);
    double previous = r.cost();
    for (std::size_t i = 0; i < r.alternatives.size(); ++i) {
      const csp::Assignment& a = r.alternatives[i];
      ASSERT_EQ(a.size(), 3u);
      const Eigen::Vector3d q(a[0], a[1], a[2]);
      for (csp::VariableId v = 0; v < 3; ++v) EXPECT_TRUE(p.variable(v).domain.contains(a[v]));
      const csp::Score score = p.score(a);
      EXPECT_TRUE(score.feasible()) << "alternative " << i;
      EXPECT_GE(score.soft, previous - 1e-9) << "alternative " << i << " is out of order";
      previous = score.soft;
      EXPECT_GE((q - best).norm(), separation - 1e-9) << "alternative " << i;
      for (std::size_t j = 0; j < i; ++j) {
        const csp::Assignment& b = r.alternatives[j];
        EXPECT_GE((q - Eigen::Vector3d(b[0], b[1], b[2])).norm(), separation - 1e-9);
      }
    }
  }
}

TEST_P(OcclusionOctreeAlternatives, ThePipelineThatRefinesFromThemIsNeverWorseThanTheOctree) {
  const Scene scene = thesis_scene(GetParam());
  auto octree = solver_registry().create("occlusion-octree");
  auto pipeline = solver_registry().create("occlusion-octree>ceres-refine");
  ASSERT_EQ(pipeline->alternatives_wanted(), 0u);  // the octree's; ceres-refine asks it for 2
  int better = 0;
  for (const Frame& f : sample_frames(scene, 50)) {
    CameraProblem problem(scene);
    problem.set_frame(f.character, f.last_camera, f.dt);
    const double start[3] = {f.last_camera.x(), f.last_camera.y(), f.last_camera.z()};
    const solvers::SolverResult alone = octree->solve(problem.problem(), start);
    const solvers::SolverResult refined = pipeline->solve(problem.problem(), start);
    if (!alone.message.empty()) continue;  // swept orientation: its costs are not the problem's
    EXPECT_FALSE(alone.score.better_than(refined.score)) << refined.brief_report("pipeline");
    if (alone.feasible()) {
      EXPECT_TRUE(refined.feasible());
    }
    better += refined.score.better_than(alone.score);
  }
  EXPECT_GT(better, 0);
}

INSTANTIATE_TEST_SUITE_P(TwoThesisScenes, OcclusionOctreeAlternatives,
                         ::testing::Values("into-corner", "open-field"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace sightline::camera
