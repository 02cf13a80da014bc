// Metrics with movers and issue 13's metrics, on hand-made traces with known answers: the
// metrics' own interpolation of movers against the camera domain's Mover, a mover crossing the
// sight line against a separating-axis segment/box test written here, recovery times, cuts
// per minute and by reason, and the trace's cut_reason column.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/mover.h"
#include "sightline/experiments/runs/metrics.h"

namespace sightline::experiments {
namespace {

using Eigen::Vector3d;

constexpr double kFps = 60;

TraceRow frame_row(int frame, const Vector3d& camera, const Vector3d& target) {
  TraceRow r;
  r.frame = frame;
  r.t = frame / kFps;
  r.character = {target.x(), 0, target.z()};
  r.camera = camera;
  r.target = target;
  return r;
}

MovingBox moving(const Vector3d& size, std::vector<double> times, std::vector<Vector3d> at) {
  MovingBox m;
  m.size = size;
  m.times = std::move(times);
  m.positions = std::move(at);
  return m;
}

// Segment a-b against a closed box by the separating axis theorem: the 3 box axes and the
// cross products of the segment's direction with them. A method of its own, not the
// clipping of independent_check.cc.
bool sat_segment_meets_box(const Vector3d& a, const Vector3d& b, const Vector3d& lo,
                           const Vector3d& hi) {
  const Vector3d c = (lo + hi) / 2, e = (hi - lo) / 2;
  const Vector3d m = (a + b) / 2 - c, h = (b - a) / 2;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(m[i]) > e[i] + std::abs(h[i])) return false;
  }
  const Vector3d ah = h.cwiseAbs();
  if (std::abs(m.y() * h.z() - m.z() * h.y()) > e.y() * ah.z() + e.z() * ah.y()) return false;
  if (std::abs(m.z() * h.x() - m.x() * h.z()) > e.x() * ah.z() + e.z() * ah.x()) return false;
  if (std::abs(m.x() * h.y() - m.y() * h.x()) > e.x() * ah.y() + e.y() * ah.x()) return false;
  return true;
}

TEST(MovingBox, MatchesTheCameraDomainsMoverAtRandomTimes) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coord(-20, 20), extent(0.1, 5), gap(0.01, 3);
  std::uniform_int_distribution<int> keys(1, 6);
  for (int round = 0; round < 200; ++round) {
    const Vector3d size(extent(rng), extent(rng), extent(rng));
    std::vector<camera::MoverKeyframe> path;
    MovingBox plain;
    plain.size = size;
    double t = coord(rng);
    for (int k = keys(rng); k > 0; --k) {
      const Vector3d p(coord(rng), coord(rng), coord(rng));
      path.push_back({t, p});
      plain.times.push_back(t);
      plain.positions.push_back(p);
      t += gap(rng);
    }
    const camera::Mover mover("m", size, path);
    std::uniform_real_distribution<double> when(plain.times.front() - 2, plain.times.back() + 2);
    std::vector<double> times{plain.times.front() - 1, plain.times.back() + 1};
    for (double k : plain.times) times.push_back(k);  // exactly at the keyframes too
    for (int i = 0; i < 30; ++i) times.push_back(when(rng));
    for (double q : times) {
      const SolidBox mine = moving_box_at(plain, q);
      const camera::Aabb theirs = mover.box_at(q);
      ASSERT_LT((mine.min - theirs.min).norm(), 1e-9) << "round " << round << " t " << q;
      ASSERT_LT((mine.max - theirs.max).norm(), 1e-9) << "round " << round << " t " << q;
    }
  }
}

TEST(MovingBox, FollowsTheFormatsExample) {
  // FORMATS.md's passer-by: 0.6 x 1.8 x 0.6, from [-6, 0, 1] at t = 2 to [6, 0, 1] at t = 6.
  const MovingBox m = moving({0.6, 1.8, 0.6}, {2, 6}, {{-6, 0, 1}, {6, 0, 1}});
  const SolidBox mid = moving_box_at(m, 4);
  EXPECT_NEAR((mid.min - Vector3d(-0.3, 0, 0.7)).norm(), 0, 1e-12);
  EXPECT_NEAR((mid.max - Vector3d(0.3, 1.8, 1.3)).norm(), 0, 1e-12);
  EXPECT_NEAR(moving_box_at(m, 0).min.x(), -6.3, 1e-12);   // before: where it starts
  EXPECT_NEAR(moving_box_at(m, 99).max.x(), 6.3, 1e-12);   // after: where it ends
  EXPECT_NEAR(moving_box_at(m, 3).min.x(), -3.3, 1e-12);
}

// A passer-by 0.6 m wide walks along x at 2.5 m/s (x = -5 at t = 0 to 5 at t = 4) across the
// sight line from a camera at z = -4 to the look-at point at the origin. The sight line runs
// along x = 0, so it is hidden while |x| <= 0.3: t in [1.88, 2.12], frames 113..127 at 60 fps.
TEST(RunMetricsWithMovers, AMoverCrossingTheSightLineHidesExactlyThoseFrames) {
  MetricsInput input;
  input.movers = {moving({0.6, 1.8, 0.6}, {0, 4}, {{-5, 0, -2}, {5, 0, -2}})};
  const Vector3d camera(0, 1.5, -4), target(0, 1.5, 0);
  std::vector<TraceRow> trace;
  int expected_hidden = 0, first = -1, last = -1;
  for (int f = 0; f <= 240; ++f) {
    trace.push_back(frame_row(f, camera, target));
    // Brute force: the box from the walk's own numbers, and the separating-axis test.
    const double x = -5 + 2.5 * (f / kFps);
    if (sat_segment_meets_box(camera, target, {x - 0.3, 0, -2.3}, {x + 0.3, 1.8, -1.7})) {
      ++expected_hidden;
      if (first < 0) first = f;
      last = f;
    }
    EXPECT_EQ(segment_blocked(input, camera, target, f / kFps), f >= 113 && f <= 127) << f;
  }
  EXPECT_EQ(expected_hidden, 15);
  EXPECT_EQ(first, 113);
  EXPECT_EQ(last, 127);
  const RunMetrics m = compute_metrics(trace, input);
  EXPECT_EQ(m.occlusion_episodes, 1);
  EXPECT_EQ(m.longest_occlusion_frames, 15);
  EXPECT_NEAR(m.visible_percent, 100.0 * (241 - 15) / 241, 1e-9);
  EXPECT_NEAR(m.recovery_seconds_max, 15 / kFps, 1e-9);
  EXPECT_LT(m.visible_fraction_mean, 1.0);  // the mover hides part of the body too
  // Without the mover nothing is hidden: the movers are what the metrics saw.
  const RunMetrics without = compute_metrics(trace, MetricsInput{});
  EXPECT_EQ(without.occlusion_episodes, 0);
  EXPECT_DOUBLE_EQ(without.visible_fraction_mean, 1.0);
}

// Random movers, static boxes and cameras: every frame's hidden flag agrees with the
// separating-axis test on boxes placed by this test's own interpolation.
TEST(RunMetricsWithMovers, HiddenFramesAgreeWithABruteForceCheckOnRandomScenes) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> coord(-6, 6), extent(0.3, 3), speed(-4, 4);
  for (int round = 0; round < 20; ++round) {
    MetricsInput input;
    input.boxes.push_back({{coord(rng), 0, coord(rng)}, {0, 0, 0}});
    input.boxes[0].max = input.boxes[0].min + Vector3d(extent(rng), extent(rng), extent(rng));
    struct Walk { Vector3d start, velocity, size; };
    std::vector<Walk> walks;
    for (int i = 0; i < 4; ++i) {
      const Walk w{{coord(rng), 0, coord(rng)}, {speed(rng), 0, speed(rng)},
                   {extent(rng), extent(rng), extent(rng)}};
      walks.push_back(w);
      // Straight from t = 0.5 to t = 2.5, standing still before and after.
      input.movers.push_back(moving(w.size, {0.5, 2.5}, {w.start, w.start + 2 * w.velocity}));
    }
    const Vector3d camera(coord(rng), 2, coord(rng) - 8), target(coord(rng), 1.5, coord(rng));
    std::vector<TraceRow> trace;
    int expected_hidden = 0;
    for (int f = 0; f <= 180; ++f) {
      trace.push_back(frame_row(f, camera, target));
      const double t = f / kFps;
      bool hidden = sat_segment_meets_box(camera, target, input.boxes[0].min, input.boxes[0].max);
      for (const Walk& w : walks) {
        const double moving_for = std::clamp(t - 0.5, 0.0, 2.0);
        const Vector3d base = w.start + moving_for * w.velocity;
        const Vector3d half(w.size.x() / 2, 0, w.size.z() / 2);
        hidden = hidden || sat_segment_meets_box(camera, target, base - half,
                                                 base + half + Vector3d(0, w.size.y(), 0));
      }
      expected_hidden += hidden;
      ASSERT_EQ(segment_blocked(input, camera, target, t), hidden) << "round " << round << " frame " << f;
    }
    const RunMetrics m = compute_metrics(trace, input);
    EXPECT_NEAR(m.visible_percent, 100.0 * (181 - expected_hidden) / 181, 1e-9);
  }
}

TEST(RunMetricsWithMovers, TheBodyBehindAPassingBusCountsAsHidden) {
  // A bus 3 m tall and 4 m long hides the whole body from a camera 1.7 m up while it stands
  // between them, frames 30..89 of 120; then it has driven off.
  MetricsInput input;
  input.movers = {moving({4, 3, 1}, {0.5, 1.5, 1.5 + 1e-3}, {{0, 0, -2}, {0, 0, -2}, {40, 0, -2}})};
  std::vector<TraceRow> trace;
  for (int f = 0; f < 120; ++f) {
    TraceRow r = frame_row(f, {0, 1.7, -4}, {0, 1.5, 0});
    trace.push_back(r);
  }
  // Frames before t = 0.5 see the bus too (a mover stands at its first keyframe before it):
  // hidden are frames 0..90 (t <= 1.5 + 1e-3 puts frame 90 at x = 0 still).
  const RunMetrics m = compute_metrics(trace, input);
  EXPECT_EQ(m.longest_occlusion_frames, 91);
  EXPECT_NEAR(m.visible_fraction_mean, (120.0 - 91) / 120, 1e-12);
  EXPECT_DOUBLE_EQ(m.visible_fraction_min, 0.0);
}

TEST(RunMetricsWithMovers, ACameraTooCloseToAMoverViolatesClearance) {
  MetricsInput input;
  input.clearance_radius = 0.2;
  // A door slab 1 m wide sliding along x through the camera's spot and back: from x = -3 at
  // t = 0 to 0.6 at t = 1 and back to -3 at t = 2.
  input.movers = {moving({1, 2, 1}, {0, 1, 2}, {{-3, 0, 0}, {0.6, 0, 0}, {-3, 0, 0}})};
  std::vector<TraceRow> trace;
  for (int f = 0; f <= 120; ++f) trace.push_back(frame_row(f, {0, 1, 0}, {0, 1, 5}));
  // Distance from the camera (x = 0, inside the slab's y and z spans) to the slab along x.
  int expected = 0;
  for (int f = 0; f <= 120; ++f) {
    const double t = f / kFps;
    const double x = t <= 1 ? -3 + 3.6 * t : 0.6 - 3.6 * (t - 1);
    const double face = x + 0.5, back = x - 0.5;
    const double d = face < 0 ? -face : back > 0 ? back : 0.0;
    expected += d < 0.2 - 1e-3;
  }
  const RunMetrics m = compute_metrics(trace, input);
  EXPECT_GT(expected, 0);
  EXPECT_EQ(m.clearance_violations, expected);
  EXPECT_DOUBLE_EQ(m.min_clearance, 0.0);
}

// The look-at point behind a wall for frames [from, from + count).
std::vector<TraceRow> hidden_for(const std::vector<std::pair<int, int>>& spans, int frames) {
  std::vector<TraceRow> trace;
  for (int f = 0; f < frames; ++f) {
    bool hidden = false;
    for (auto [from, count] : spans) hidden = hidden || (f >= from && f < from + count);
    trace.push_back(frame_row(f, hidden ? Vector3d(0, 1.5, -4) : Vector3d(3, 1.5, -4),
                              {0, 1.5, 0}));
  }
  return trace;
}

MetricsInput wall_in_front_of_x0() {
  MetricsInput input;
  input.boxes = {{{-0.5, 0, -2.2}, {0.5, 3, -2}}};
  return input;
}

TEST(RunMetrics, RecoveryOfThirtyHiddenFramesAtSixtyFpsIsHalfASecond) {
  const RunMetrics m = compute_metrics(hidden_for({{100, 30}}, 300), wall_in_front_of_x0());
  EXPECT_EQ(m.occlusion_episodes, 1);
  EXPECT_EQ(m.longest_occlusion_frames, 30);
  EXPECT_NEAR(m.recovery_seconds_max, 0.5, 1e-9);
  EXPECT_NEAR(m.recovery_seconds_mean, 0.5, 1e-9);
}

TEST(RunMetrics, RecoveryTakesTheWorstAndTheMeanOfEpisodes) {
  const RunMetrics m =
      compute_metrics(hidden_for({{10, 30}, {100, 60}, {200, 6}}, 300), wall_in_front_of_x0());
  EXPECT_EQ(m.occlusion_episodes, 3);
  EXPECT_NEAR(m.recovery_seconds_max, 1.0, 1e-9);
  EXPECT_NEAR(m.recovery_seconds_mean, (0.5 + 1.0 + 0.1) / 3, 1e-9);
}

TEST(RunMetrics, RecoveryIsZeroWhenSightIsNeverLostAndCountsAnOpenEpisodeToTheEnd) {
  const RunMetrics never = compute_metrics(hidden_for({}, 100), wall_in_front_of_x0());
  EXPECT_EQ(never.recovery_seconds_max, 0);
  EXPECT_EQ(never.recovery_seconds_mean, 0);
  // Hidden over the last 12 frames: counted until one frame after the last, 12 / 60 s.
  const RunMetrics open = compute_metrics(hidden_for({{88, 12}}, 100), wall_in_front_of_x0());
  EXPECT_NEAR(open.recovery_seconds_max, 0.2, 1e-9);
}

TEST(RunMetrics, CutsPerMinuteAndCutsByReason) {
  // 2 minutes at 10 frames per second: 1201 frames, t = 0 .. 120.
  std::vector<TraceRow> trace;
  for (int f = 0; f <= 1200; ++f) {
    TraceRow r = frame_row(f, {0, 2, -4}, {0, 1.5, 0});
    r.t = f / 10.0;
    r.cut_reason = "none";
    trace.push_back(r);
  }
  const char* reasons[] = {"visibility-lost", "left-enclosed-area", "stuck",
                           "visibility-lost", "backed-up-to-obstacle"};
  for (int i = 0; i < 5; ++i) {
    trace[100 + 200 * i].cut = true;
    trace[100 + 200 * i].cut_reason = reasons[i];
  }
  RunMetrics m = compute_metrics(trace, MetricsInput{});
  EXPECT_EQ(m.cuts, 5);
  EXPECT_NEAR(m.cuts_per_minute, 2.5, 1e-12);
  EXPECT_TRUE(m.cut_reasons_known);
  EXPECT_EQ(m.forced_cuts, 2);
  EXPECT_EQ(m.discretionary_cuts, 3);
  EXPECT_NEAR(m.discretionary_cuts_per_minute, 1.5, 1e-12);

  // The same trace without reasons (an older file): the split is unknown, NaN in results.
  for (TraceRow& r : trace) r.cut_reason.clear();
  m = compute_metrics(trace, MetricsInput{});
  EXPECT_FALSE(m.cut_reasons_known);
  EXPECT_NEAR(m.cuts_per_minute, 2.5, 1e-12);
  const std::vector<std::string> names = metric_names();
  const std::vector<double> values = metric_values(m);
  ASSERT_EQ(names.size(), values.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    const bool split = names[i] == "forced_cuts" || names[i] == "discretionary_cuts" ||
                       names[i] == "discretionary_cuts_per_minute";
    EXPECT_EQ(std::isnan(values[i]), split) << names[i];
    if (names[i] == "cuts_per_minute") {
      EXPECT_NEAR(values[i], 2.5, 1e-12);
    }
  }
}

TEST(RunMetrics, OneFrameHasNoCutRate) {
  const RunMetrics m = compute_metrics({frame_row(0, {0, 2, -4}, {0, 1.5, 0})}, MetricsInput{});
  EXPECT_EQ(m.cuts_per_minute, 0);
  EXPECT_EQ(m.discretionary_cuts_per_minute, 0);
}

TEST(Trace, CutReasonsRoundTripAndOlderTracesReadWithout) {
  const auto dir = std::filesystem::temp_directory_path() / "sightline_trace_reason_test";
  std::filesystem::create_directories(dir);
  std::vector<TraceRow> trace{frame_row(0, {0, 2, -4}, {0, 1.5, 0}),
                              frame_row(1, {1, 2, -4}, {0, 1.5, 0})};
  trace[1].cut = true;
  trace[1].cut_reason = "visibility-lost";
  write_trace_csv((dir / "a.csv").string(), trace);
  const auto back = read_trace_csv((dir / "a.csv").string());
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].cut_reason, "none");  // written as "none" when empty
  EXPECT_EQ(back[1].cut_reason, "visibility-lost");
  EXPECT_NE(trace_header().find(",cut_reason"), std::string::npos);

  // A trace with only the public columns: no reasons.
  std::ofstream(dir / "old.csv")
      << "frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,target_x,target_y,target_z,"
         "cut,cost,solve_us\n0,0,0,0,0,0,0,2,-4,0,1.5,0,1,0.5,100\n";
  const auto old = read_trace_csv((dir / "old.csv").string());
  ASSERT_EQ(old.size(), 1u);
  EXPECT_TRUE(old[0].cut);
  EXPECT_EQ(old[0].cut_reason, "");

  // A row whose reason cell is empty names its line.
  std::ofstream(dir / "bad.csv") << trace_header() << "\n"
                                 << "0,0,0,0,0,0,0,2,-4,0,1.5,0,0,0,100,1,2,4,0,none\n"
                                 << "1,0.1,0,0,0,0,0,2,-4,0,1.5,0,1,0,100,1,2,4,0,\n";
  try {
    read_trace_csv((dir / "bad.csv").string());
    FAIL();
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().line, 3);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sightline::experiments
