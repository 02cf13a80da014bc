// RunMetrics: what a camera run achieved, computed from its trace and the scene's boxes.
//
// Visibility and clearance are judged by the independent brute-force checks
// (independent_check.h), never by the controller's flag. Speeds and jerk come from finite
// differences of the camera path; frames next to a cut are left out of them (a cut is a
// deliberate jump, not motion). Deviations compare the chosen position with the profile's
// desired values recorded in the trace for that frame.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "experiments/independent_check.h"
#include "experiments/independent_triangles.h"
#include "experiments/trace.h"

namespace sightline::experiments {

struct MetricsInput {
  std::vector<SolidBox> boxes;
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
  double visible_percent = 0;        // frames whose look-at point is visible, in %
  double visible_fraction_mean = 0;  // of the body, 0..1
  double visible_fraction_min = 0;
  int occlusion_episodes = 0;        // maximal runs of frames with the look-at hidden
  int longest_occlusion_frames = 0;
  int clearance_violations = 0;      // frames with the camera inside or within its radius
  int solid_frames = 0;              // frames with the camera inside a level's solid volume
  double min_clearance = 0;          // metres (0 when inside)
  int cuts = 0;
  double shortest_shot_seconds = 0;  // between cuts (the start counts; the open last shot not)
  int unflagged_jumps = 0;           // moves above max_smooth_step without a cut flag
  double speed_p99 = 0;              // m/s, camera
  double speed_max = 0;
  double jerk_p99 = 0;               // m/s^3, camera
  double height_deviation_mean = 0;  // |desired - actual|, metres
  double distance_deviation_mean = 0;
  double orientation_deviation_mean = 0;  // degrees
  double cost_mean = 0, cost_max = 0;
  double solve_us_p50 = 0, solve_us_p99 = 0, solve_us_max = 0;
};

// Independent visibility and clearance against everything in `input` (boxes and triangles).
bool segment_blocked(const MetricsInput& input, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
double distance_to_geometry(const MetricsInput& input, const Eigen::Vector3d& p);
double visible_body_fraction(const MetricsInput& input, const Eigen::Vector3d& eye,
                             const Eigen::Vector3d& feet);

RunMetrics compute_metrics(const std::vector<TraceRow>& trace, const MetricsInput& input);

// Percentile (0..100) by linear interpolation between order statistics; 0 for no values.
double percentile(std::vector<double> values, double p);

// The column names and values of RunMetrics, in a fixed order, for results.csv.
std::vector<std::string> metric_names();
std::vector<double> metric_values(const RunMetrics& m);

}  // namespace sightline::experiments
