// Metrics on hand-made traces whose answers are known, and the independent checks against
// hand-worked geometry.
#include "sightline/experiments/runs/metrics.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace sightline::experiments {
namespace {

TraceRow row(int frame, Eigen::Vector3d camera, bool cut = false) {
  TraceRow r;
  r.frame = frame;
  r.t = frame / 10.0;
  r.character = {0, 0, 0};
  r.character_yaw = 0;  // facing +z
  r.camera = camera;
  r.target = {0, 1.5, 0};
  r.cut = cut;
  r.cost = frame;
  r.solve_us = 100 + frame;
  r.desired_height = 2;
  r.desired_distance = 4;
  r.desired_orientation = 0;
  return r;
}

TEST(IndependentCheck, SegmentThroughABoxIsBlockedAndBesideItIsNot) {
  const std::vector<SolidBox> wall{{{-1, 0, 1}, {1, 3, 1.2}}};
  EXPECT_TRUE(segment_blocked(wall, {0, 1, 0}, {0, 1, 2}));
  EXPECT_FALSE(segment_blocked(wall, {2, 1, 0}, {2, 1, 2}));
  EXPECT_FALSE(segment_blocked(wall, {0, 1, 0}, {0, 1, 0.9}));  // stops short
  EXPECT_TRUE(segment_blocked(wall, {0, 1, 1.1}, {0, 1, 5}));   // starts inside
  EXPECT_TRUE(segment_blocked(wall, {1, 1, 0}, {1, 1, 2}));     // grazes the face x = 1
  EXPECT_FALSE(segment_blocked(wall, {0, 3.5, 0}, {0, 3.5, 2}));  // passes over it
}

TEST(IndependentCheck, DistanceToGeometryIsEuclideanToTheNearestBox) {
  const std::vector<SolidBox> boxes{{{0, 0, 0}, {1, 1, 1}}, {{5, 0, 0}, {6, 1, 1}}};
  EXPECT_DOUBLE_EQ(distance_to_geometry(boxes, {2, 0.5, 0.5}), 1.0);
  EXPECT_DOUBLE_EQ(distance_to_geometry(boxes, {0.5, 0.5, 0.5}), 0.0);
  EXPECT_NEAR(distance_to_geometry(boxes, {2, 2, 0.5}), std::sqrt(2.0), 1e-12);
}

TEST(IndependentCheck, BodyBehindAHalfHeightWallIsPartlyVisible) {
  // A wall up to y = 0.9 between eye and character, eye at the same height as the wall top:
  // body points below the wall top are hidden.
  const std::vector<SolidBox> wall{{{-2, 0, 1}, {2, 0.9, 1.2}}};
  const double f = visible_body_fraction(wall, {0, 0.9, -3}, {0, 0, 3}, {0.6, 1.8, 0.6});
  EXPECT_GT(f, 0.2);
  EXPECT_LT(f, 0.8);
  EXPECT_DOUBLE_EQ(visible_body_fraction({}, {0, 2, -3}, {0, 0, 3}, {0.6, 1.8, 0.6}), 1.0);
}

TEST(RunMetrics, CountsOcclusionEpisodesCutsAndShots) {
  MetricsInput input;
  input.boxes = {{{-1, 0, -2.2}, {1, 3, -2.0}}};  // a wall between z = -2.2 and -2
  std::vector<TraceRow> trace;
  // Frames 0-2 behind the character at z = -1 (visible), 3-4 behind the wall (hidden),
  // frame 5 cuts back in front of the wall, 6-7 visible, 8 hidden again.
  for (int f = 0; f < 3; ++f) trace.push_back(row(f, {0, 2, -1}));
  trace.push_back(row(3, {0, 2, -3}, true));
  trace.push_back(row(4, {0, 2, -3}));
  trace.push_back(row(5, {0, 2, -1}, true));
  trace.push_back(row(6, {0, 2, -1}));
  trace.push_back(row(7, {0, 2, -1}));
  trace.push_back(row(8, {0, 2, -3.5}, true));
  const RunMetrics m = compute_metrics(trace, input);
  EXPECT_EQ(m.frames, 9);
  EXPECT_EQ(m.occlusion_episodes, 2);
  EXPECT_EQ(m.longest_occlusion_frames, 2);
  EXPECT_NEAR(m.visible_percent, 100.0 * 6 / 9, 1e-9);
  EXPECT_EQ(m.cuts, 3);
  EXPECT_NEAR(m.shortest_shot_seconds, 0.0 + 0.2, 1e-9);  // frames 3 -> 5
  EXPECT_EQ(m.unflagged_jumps, 0);
  EXPECT_DOUBLE_EQ(m.cost_max, 8);
  EXPECT_DOUBLE_EQ(m.cost_mean, 4);
  EXPECT_DOUBLE_EQ(m.solve_us_max, 108);
  EXPECT_DOUBLE_EQ(m.solve_us_p50, 104);
}

TEST(RunMetrics, FlagsUnflaggedJumpsAndMeasuresSpeed) {
  MetricsInput input;
  std::vector<TraceRow> trace;
  for (int f = 0; f < 5; ++f) trace.push_back(row(f, {0.1 * f, 2, -4}));  // 1 m/s along x
  trace.push_back(row(5, {3, 2, -4}));  // a 2.6 m jump, not flagged
  const RunMetrics m = compute_metrics(trace, input);
  EXPECT_EQ(m.unflagged_jumps, 1);
  EXPECT_NEAR(m.speed_max, 26.0, 1e-9);
}

// A camera moving as x = t^3 (jerk 6 m/s^3 throughout) at 60 frames a second, its last
// frame 3 ms after the one before (a walk's end between frames): every jerk measured is 6.
// (Divided by the last frame's own time step alone, the last sample came out at -680 along x.)
TEST(RunMetrics, JerkIsExactForACubicEvenAcrossAShortLastFrame) {
  MetricsInput input;
  std::vector<TraceRow> trace;
  auto at = [&](int frame, double t) {
    TraceRow r = row(frame, {t * t * t, 2, -4});
    r.t = t;
    return r;
  };
  for (int f = 0; f < 12; ++f) trace.push_back(at(f, f / 60.0));
  trace.push_back(at(12, 11 / 60.0 + 0.003));
  const RunMetrics m = compute_metrics(trace, input);
  EXPECT_NEAR(m.jerk_p99, 6.0, 1e-6);
}

TEST(RunMetrics, DeviationsFollowTheThesisDefinitions) {
  MetricsInput input;
  // Character at the origin facing +z; camera 3 m behind and 2.5 m up: height deviation 0.5,
  // distance deviation 1, orientation: camera->character points +z, angle 0.
  std::vector<TraceRow> trace{row(0, {0, 2.5, -3})};
  RunMetrics m = compute_metrics(trace, input);
  EXPECT_NEAR(m.height_deviation_mean, 0.5, 1e-12);
  EXPECT_NEAR(m.distance_deviation_mean, 1.0, 1e-12);
  EXPECT_NEAR(m.orientation_deviation_mean, 0.0, 1e-9);
  // Camera to the character's right side (+x): direction camera->character is -x, 90 deg.
  trace = {row(0, {4, 2, 0})};
  m = compute_metrics(trace, input);
  EXPECT_NEAR(m.orientation_deviation_mean, 90.0, 1e-9);
}

TEST(RunMetrics, ClearanceViolationsCountFramesTooCloseToGeometry) {
  MetricsInput input;
  input.boxes = {{{1, 0, -5}, {2, 3, 5}}};
  std::vector<TraceRow> trace{row(0, {0.5, 2, -3}), row(1, {0.9, 2, -3}), row(2, {1.5, 2, -3})};
  const RunMetrics m = compute_metrics(trace, input);
  EXPECT_EQ(m.clearance_violations, 2);
  EXPECT_DOUBLE_EQ(m.min_clearance, 0.0);
}

TEST(Trace, RoundTripsThroughCsvWithThePublicColumnsFirst) {
  const auto path = (std::filesystem::temp_directory_path() / "sightline_trace_test.csv").string();
  std::vector<TraceRow> trace{row(0, {0, 2, -1}), row(1, {0.5, 2.25, -1.5}, true)};
  write_trace_csv(path, trace);
  const auto back = read_trace_csv(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_TRUE(back[1].cut);
  EXPECT_DOUBLE_EQ(back[1].camera.y(), 2.25);
  EXPECT_DOUBLE_EQ(back[1].desired_distance, 4);
  EXPECT_EQ(trace_header().rfind(
                "frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,target_x,target_y,"
                "target_z,cut,cost,solve_us",
                0),
            0u);
  std::filesystem::remove(path);
}

TEST(Percentile, InterpolatesBetweenOrderStatistics) {
  EXPECT_DOUBLE_EQ(percentile({1, 2, 3, 4, 5}, 50), 3);
  EXPECT_DOUBLE_EQ(percentile({1, 2, 3, 4, 5}, 100), 5);
  EXPECT_DOUBLE_EQ(percentile({10, 20}, 25), 12.5);
  EXPECT_DOUBLE_EQ(percentile({}, 99), 0);
}

}  // namespace
}  // namespace sightline::experiments
