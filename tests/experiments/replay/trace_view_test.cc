// TraceView's pieces (trace_view.h) on a scene built here: the match between a trace and its
// scene at the edge of its tolerances, the hidden frames against segments worked out by hand,
// and run ids from file names.
#include "sightline/experiments/replay/trace_view.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sightline/csp/input_error.h"
#include "sightline/experiments/runs/camera_run.h"

namespace sightline::experiments {
namespace {

// The character walks from x = 0 to x = 1 in one second at 4 frames per second, past a wall
// at z 1 .. 1.2.
camera::Scene walk_scene() {
  std::vector<camera::SolidBox> solids{{"wall", camera::Aabb{{-2, 0, 1}, {2, 3, 1.2}}, {}}};
  camera::Trajectory path({{0, {0, 0, 0}, 0}, {1, {1, 0, 0}, 90}});
  return camera::Scene("walk", solids, {}, camera::CharacterShape{}, path, 4);
}

// The trace a perfect follower writes: the scene's frames, the camera 3 m behind on -z.
std::vector<TraceRow> walk_trace(const camera::Scene& scene) {
  std::vector<TraceRow> rows;
  for (std::size_t i = 0; i < scene.frame_count(); ++i) {
    TraceRow r;
    r.frame = static_cast<int>(i);
    r.t = scene.frame_time(i);
    r.character = scene.character_at(r.t).position;
    r.target = r.character + Eigen::Vector3d(0, 1.5, 0);
    r.camera = r.character + Eigen::Vector3d(0, 2, -3);
    r.line = static_cast<int>(i) + 2;
    rows.push_back(r);
  }
  return rows;
}

std::string mismatch(const camera::Scene& scene, const std::vector<TraceRow>& trace) {
  try {
    check_trace_matches_scene(scene, trace, "t.csv");
  } catch (const csp::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TraceMatch, AcceptsTheScenesOwnFramesAndDriftWithinTheTolerances) {
  const camera::Scene scene = walk_scene();
  std::vector<TraceRow> trace = walk_trace(scene);
  EXPECT_EQ(mismatch(scene, trace), "");
  trace[2].character.z() += 0.009;  // under 1 cm
  trace[4].t += 0.0009;             // under 1 ms after the last keyframe
  trace[4].character = scene.character_at(1).position;
  EXPECT_EQ(mismatch(scene, trace), "");
}

TEST(TraceMatch, RejectsDriftJustBeyondTheTolerancesNamingTheLine) {
  const camera::Scene scene = walk_scene();
  std::vector<TraceRow> trace = walk_trace(scene);
  trace[2].character.z() += 0.011;
  std::string e = mismatch(scene, trace);
  EXPECT_NE(e.find("t.csv:4: frame 2 (row 3)"), std::string::npos) << e;
  EXPECT_NE(e.find("0.011 m from where scene 'walk' puts it"), std::string::npos) << e;
  trace = walk_trace(scene);
  trace[0].t = -0.0011;
  e = mismatch(scene, trace);
  EXPECT_NE(e.find("t.csv:2: frame 0 (row 1) is at t = -0.0011 s, 0.0011 s outside"),
            std::string::npos)
      << e;
  trace = walk_trace(scene);
  trace.push_back(trace.back());
  trace.back().t = 1.0005;  // inside the span's slack, but one frame too many
  trace.back().line = 7;
  e = mismatch(scene, trace);
  EXPECT_NE(e.find("t.csv:7: the trace has 6 frames, scene 'walk' has 5"), std::string::npos)
      << e;
  EXPECT_NE(e.find("1 frames more, from row 6"), std::string::npos) << e;
  EXPECT_NE(mismatch(scene, {}).find("the trace has no frames"), std::string::npos);
}

TEST(HiddenFrames, AreTheFramesWhoseSightLineCrossesABox) {
  const camera::Scene scene = walk_scene();
  std::vector<TraceRow> trace = walk_trace(scene);
  // Frame 1 films from beyond the wall; frame 3 from beyond it but off to the side (the line
  // crosses the wall's depth at x 2.75 .. 3.15, past its end at x = 2); frame 4 from above the
  // wall's top (the line leaves the wall's depth at y 3.32 > 3).
  trace[1].camera = {0.25, 2, 3};
  trace[3].camera = {6.75, 2, 3};
  trace[4].camera = {1, 3.5, 1.1};
  const MetricsInput world = metrics_input(scene, scene.profile(), 0);
  EXPECT_EQ(hidden_frames(world, trace), (std::vector<char>{0, 1, 0, 0, 0}));
  trace[4].camera = {1, 2.9, 1.1};  // inside the wall
  EXPECT_EQ(hidden_frames(world, trace), (std::vector<char>{0, 1, 0, 0, 1}));
}

TEST(RunIds, ComeFromFileNamesMadeFragmentSafeAndUnique) {
  EXPECT_EQ(run_ids_from_paths({"out/runs/room__sls__scene__s1__ab12.trace.csv", "b/walk.csv",
                                "c/walk.csv", "walk-2.csv", "d/my run (2).csv", "e/.csv"}),
            (std::vector<std::string>{"room__sls__scene__s1__ab12", "walk", "walk-2", "walk-2-2",
                                      "my_run__2_", ".csv"}));
}

}  // namespace
}  // namespace sightline::experiments
