// RunMetrics: what a camera run achieved, computed from its trace and the scene's geometry.
//
// Visibility and clearance are judged by the independent brute-force checks
// (independent_check.h), never by the controller's flag, against the static boxes, a level's
// triangles and the movers' boxes at each frame's time (interpolated here, not by the camera
// domain). Speeds and jerk come from finite
// differences of the camera path; frames next to a cut are left out of them (a cut is a
// deliberate jump, not motion). Deviations compare the chosen position with the profile's
// desired values recorded in the trace for that frame.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sightline/experiments/runs/independent_check.h"
#include "sightline/experiments/runs/independent_triangles.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

struct MetricsInput {
  std::vector<SolidBox> boxes;
  // The scene's movers as plain keyframes; each frame sees their boxes at its time.
  std::vector<MovingBox> movers;
  // A level's triangles for the independent check (null without a level), and its solid
  // volume (empty without one): a camera inside solid matter or outside the world counts
  // in `solid_frames`.
  std::shared_ptr<const IndependentTriangles> triangles;
  std::function<bool(const Eigen::Vector3d&)> solid_at;
  Eigen::Vector3d character_size{0.6, 1.8, 0.6};
  double clearance_radius = 0.2;  // metres; the camera sphere
  // A frame-to-frame move longer than this without a cut flag is an unflagged jump.
  double max_smooth_step = 0.25;  // metres per frame
};

struct RunMetrics {
  int frames = 0;
  double duration_seconds = 0;       // from the first frame to the last
  double visible_percent = 0;        // frames whose look-at point is visible, in %
  double visible_fraction_mean = 0;  // of the body, 0..1
  double visible_fraction_min = 0;
  double body_half_visible_percent = 0;  // frames with at least half the body visible, %
  int occlusion_episodes = 0;        // maximal runs of frames with the look-at hidden
  int longest_occlusion_frames = 0;
  int clearance_violations = 0;      // frames with the camera inside or within its radius
  int solid_frames = 0;              // frames with the camera inside a level's solid volume
  double min_clearance = 0;          // metres (0 when inside)
  int cuts = 0;
  double cuts_per_minute = 0;        // cuts / minutes from the first frame to the last (0 for one frame)
  // Cuts by reason, when the trace has a cut_reason column (cut_reasons_known): forced ones
  // (visibility-lost: no smooth move keeps the character visible) and discretionary ones
  // (every other reason: leaving an enclosed area, backing up to an obstacle, stuck, a
  // baseline's too-fast move).
  bool cut_reasons_known = false;
  int forced_cuts = 0;
  int discretionary_cuts = 0;
  double discretionary_cuts_per_minute = 0;
  double shortest_shot_seconds = 0;  // between cuts (the start counts; the open last shot not)
  int cuts_within_1s = 0;            // cuts less than 1 s after the one before
  // The most cuts in any 60 s beyond those the thesis' rules call for (leaving an enclosed
  // area, backing up to an obstacle): issue 24's bound is 2.
  int cuts_beyond_rules_per_60s_max = 0;
  // Moves above max_smooth_step without a cut flag: the "pops" of issue 13 (one figure, one
  // name in results.csv).
  int unflagged_jumps = 0;
  // Time to see the look-at point again after losing it (independent check): from the first
  // hidden frame of an occlusion episode to the next visible frame. An episode still open at
  // the last frame counts until one frame after it (a lower bound). 0 when never lost.
  double recovery_seconds_max = 0;
  double recovery_seconds_mean = 0;
  double speed_p99 = 0;              // m/s, camera
  double speed_max = 0;
  double jerk_p99 = 0;               // m/s^3, camera
  double height_deviation_mean = 0;  // |desired - actual|, metres
  double distance_deviation_mean = 0;
  double orientation_deviation_mean = 0;  // degrees
  double cost_mean = 0, cost_max = 0;
  double solve_us_p50 = 0, solve_us_p99 = 0, solve_us_max = 0;
};

// Independent visibility and clearance against everything in `input` at time t (seconds):
// the boxes, the triangles and the movers' boxes at t.
bool segment_blocked(const MetricsInput& input, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     double t);
double distance_to_geometry(const MetricsInput& input, const Eigen::Vector3d& p, double t);
double visible_body_fraction(const MetricsInput& input, const Eigen::Vector3d& eye,
                             const Eigen::Vector3d& feet, double t);

RunMetrics compute_metrics(const std::vector<TraceRow>& trace, const MetricsInput& input);

// Percentile (0..100) by linear interpolation between order statistics; 0 for no values.
double percentile(std::vector<double> values, double p);

// The column names and values of RunMetrics, in a fixed order, for results.csv.
std::vector<std::string> metric_names();
std::vector<double> metric_values(const RunMetrics& m);

}  // namespace sightline::experiments
