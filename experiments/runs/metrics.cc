#include "sightline/experiments/runs/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline::experiments {

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * (values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(rank));
  const auto hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (rank - lo) * (values[hi] - values[lo]);
}

namespace {

// The geometry of one frame: the input's static boxes and triangles plus the movers' boxes at
// that frame's time, computed once per frame.
struct FrameGeometry {
  const MetricsInput& input;
  std::vector<SolidBox> movers;

  FrameGeometry(const MetricsInput& in, double t) : input(in) {
    moving_boxes_at(in.movers, t, movers);
  }
  bool blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return segment_blocked(input.boxes, a, b) || segment_blocked(movers, a, b) ||
           (input.triangles && input.triangles->segment_blocked(a, b));
  }
  double distance(const Eigen::Vector3d& p) const {
    double d = std::min(distance_to_geometry(input.boxes, p), distance_to_geometry(movers, p));
    if (input.triangles) d = input.triangles->distance(p, d);
    return d;
  }
  double body_fraction(const Eigen::Vector3d& eye, const Eigen::Vector3d& feet) const {
    const std::vector<Eigen::Vector3d> points = body_check_points(feet, input.character_size);
    int visible = 0;
    for (const Eigen::Vector3d& p : points) visible += !blocked(eye, p);
    return static_cast<double>(visible) / static_cast<double>(points.size());
  }
};

constexpr const char* kForcedCutReason = "visibility-lost";

}  // namespace

bool segment_blocked(const MetricsInput& input, const Eigen::Vector3d& a,
                     const Eigen::Vector3d& b, double t) {
  return FrameGeometry(input, t).blocked(a, b);
}

double distance_to_geometry(const MetricsInput& input, const Eigen::Vector3d& p, double t) {
  return FrameGeometry(input, t).distance(p);
}

double visible_body_fraction(const MetricsInput& input, const Eigen::Vector3d& eye,
                             const Eigen::Vector3d& feet, double t) {
  return FrameGeometry(input, t).body_fraction(eye, feet);
}

RunMetrics compute_metrics(const std::vector<TraceRow>& trace, const MetricsInput& input) {
  RunMetrics m;
  m.frames = static_cast<int>(trace.size());
  if (trace.empty()) return m;
  constexpr double kPi = 3.14159265358979323846;

  int visible_frames = 0, current_occlusion = 0;
  double fraction_sum = 0;
  int body_half_frames = 0;
  double last_cut = -std::numeric_limits<double>::infinity();
  std::vector<double> beyond_rules;  // when the cuts beyond the thesis' rules came
  m.visible_fraction_min = 1;
  m.min_clearance = std::numeric_limits<double>::infinity();
  double height_sum = 0, distance_sum = 0, orientation_sum = 0, cost_sum = 0;
  std::vector<double> solve_us;
  solve_us.reserve(trace.size());
  // Recovery: from the first hidden frame of an episode to the next visible frame.
  double lost_at = 0, recovery_sum = 0;
  int recoveries = 0;
  auto recovered = [&](double seconds) {
    m.recovery_seconds_max = std::max(m.recovery_seconds_max, seconds);
    recovery_sum += seconds;
    ++recoveries;
  };
  m.cut_reasons_known = true;
  for (const TraceRow& r : trace) {
    const FrameGeometry world(input, r.t);
    const bool hidden = world.blocked(r.camera, r.target);
    if (hidden) {
      if (current_occlusion++ == 0) {
        ++m.occlusion_episodes;
        lost_at = r.t;
      }
      m.longest_occlusion_frames = std::max(m.longest_occlusion_frames, current_occlusion);
    } else {
      if (current_occlusion > 0) recovered(r.t - lost_at);
      ++visible_frames;
      current_occlusion = 0;
    }
    const double fraction = world.body_fraction(r.camera, r.character);
    fraction_sum += fraction;
    if (fraction >= 0.5) ++body_half_frames;
    m.visible_fraction_min = std::min(m.visible_fraction_min, fraction);
    const double clearance = world.distance(r.camera);
    if (input.solid_at && input.solid_at(r.camera)) ++m.solid_frames;
    m.min_clearance = std::min(m.min_clearance, clearance);
    // A small tolerance: positions are written with 4 decimals.
    if (clearance < input.clearance_radius - 1e-3) ++m.clearance_violations;

    // Deviations from the profile, with the thesis' definitions (tables 5-6).
    const double height = r.camera.y() - r.character.y();
    const Eigen::Vector2d to_character(r.character.x() - r.camera.x(),
                                       r.character.z() - r.camera.z());
    const double distance = to_character.norm();
    height_sum += std::abs(r.desired_height - height);
    distance_sum += std::abs(r.desired_distance - distance);
    if (distance > 1e-9) {
      const double yaw = r.character_yaw * kPi / 180;
      const Eigen::Vector2d facing(std::sin(yaw), std::cos(yaw));
      const double cosine = std::clamp(facing.dot(to_character) / distance, -1.0, 1.0);
      orientation_sum += std::abs(r.desired_orientation - std::acos(cosine) * 180 / kPi);
    }
    cost_sum += r.cost;
    m.cost_max = std::max(m.cost_max, r.cost);
    solve_us.push_back(r.solve_us);
    if (r.cut_reason.empty()) m.cut_reasons_known = false;
    if (r.cut) {
      if (r.t - last_cut < 1.0 - 1e-9) ++m.cuts_within_1s;
      last_cut = r.t;
      // The thesis' rules' cuts (leaving an enclosed area, backing up) are the profile's own.
      if (r.cut_reason != "left-enclosed-area" && r.cut_reason != "backed-up-to-obstacle") {
        beyond_rules.push_back(r.t);
      }
      ++m.cuts;
      if (r.cut_reason == kForcedCutReason) ++m.forced_cuts;
      else ++m.discretionary_cuts;
    }
  }
  if (current_occlusion > 0) {
    // Still hidden at the end: count until one frame after the last (a lower bound).
    const double frame = trace.size() > 1 ? trace.back().t - trace[trace.size() - 2].t : 0;
    recovered(trace.back().t + frame - lost_at);
  }
  m.recovery_seconds_mean = recoveries > 0 ? recovery_sum / recoveries : 0;
  if (!m.cut_reasons_known) m.forced_cuts = m.discretionary_cuts = 0;
  m.duration_seconds = trace.back().t - trace.front().t;
  const double minutes = m.duration_seconds / 60;
  if (minutes > 0) {
    m.cuts_per_minute = m.cuts / minutes;
    m.discretionary_cuts_per_minute = m.discretionary_cuts / minutes;
  }
  const double n = static_cast<double>(trace.size());
  m.visible_percent = 100.0 * visible_frames / n;
  m.visible_fraction_mean = fraction_sum / n;
  m.body_half_visible_percent = 100.0 * body_half_frames / n;
  for (std::size_t i = 0, j = 0; i < beyond_rules.size(); ++i) {
    while (beyond_rules[i] - beyond_rules[j] >= 60.0) ++j;
    m.cuts_beyond_rules_per_60s_max = std::max(m.cuts_beyond_rules_per_60s_max, static_cast<int>(i - j + 1));
  }
  m.height_deviation_mean = height_sum / n;
  m.distance_deviation_mean = distance_sum / n;
  m.orientation_deviation_mean = orientation_sum / n;
  m.cost_mean = cost_sum / n;
  m.solve_us_p50 = percentile(solve_us, 50);
  m.solve_us_p99 = percentile(solve_us, 99);
  m.solve_us_max = *std::max_element(solve_us.begin(), solve_us.end());
  if (!std::isfinite(m.min_clearance)) m.min_clearance = 0;

  // Shots: from the start or a cut to the next cut. The last shot is cut short by the end of
  // the run, not by the camera, so it only counts when there is no cut at all.
  double shot_start = trace.front().t;
  m.shortest_shot_seconds = trace.back().t - trace.front().t;
  for (std::size_t i = 1; i < trace.size(); ++i) {
    if (trace[i].cut) {
      m.shortest_shot_seconds = std::min(m.shortest_shot_seconds, trace[i].t - shot_start);
      shot_start = trace[i].t;
    }
  }

  // Motion: velocities between consecutive frames, accelerations and jerks from them,
  // skipping every difference that spans a cut.
  std::vector<double> speeds, jerks;
  std::vector<Eigen::Vector3d> velocity(trace.size(), Eigen::Vector3d::Zero());
  std::vector<bool> velocity_ok(trace.size(), false);
  for (std::size_t i = 1; i < trace.size(); ++i) {
    const double dt = trace[i].t - trace[i - 1].t;
    const double step = (trace[i].camera - trace[i - 1].camera).norm();
    if (!trace[i].cut && step > input.max_smooth_step) ++m.unflagged_jumps;
    if (trace[i].cut || dt <= 0) continue;
    velocity[i] = (trace[i].camera - trace[i - 1].camera) / dt;
    velocity_ok[i] = true;
    speeds.push_back(velocity[i].norm());
  }
  // Divided differences, so that a frame shorter than the others (the walk's last, cut at
  // its end time) is measured as it is: the velocity between frames i-1 and i is
  // f[t(i-1), t(i)], the acceleration 2 f[t(i-2), t(i-1), t(i)] and the jerk
  // 6 f[t(i-3) .. t(i)], exact for a cubic whatever the spacing (with equal frames, the
  // plain differences divided by the frame time).
  for (std::size_t i = 3; i < trace.size(); ++i) {
    if (!(velocity_ok[i] && velocity_ok[i - 1] && velocity_ok[i - 2])) continue;
    const double span2 = trace[i].t - trace[i - 2].t, span2_before = trace[i - 1].t - trace[i - 3].t;
    const double span3 = trace[i].t - trace[i - 3].t;
    if (!(span2 > 0 && span2_before > 0 && span3 > 0)) continue;
    const Eigen::Vector3d a1 = 2 * (velocity[i] - velocity[i - 1]) / span2;
    const Eigen::Vector3d a0 = 2 * (velocity[i - 1] - velocity[i - 2]) / span2_before;
    jerks.push_back((3 * (a1 - a0) / span3).norm());
  }
  m.speed_p99 = percentile(speeds, 99);
  m.speed_max = speeds.empty() ? 0 : *std::max_element(speeds.begin(), speeds.end());
  m.jerk_p99 = percentile(jerks, 99);
  return m;
}

std::vector<std::string> metric_names() {
  return {"frames",           "visible_pct",        "visible_fraction_mean",
          "visible_fraction_min", "occlusion_episodes", "longest_occlusion_frames",
          "clearance_violations", "min_clearance",    "cuts",
          "shortest_shot_s",  "unflagged_jumps",    "speed_p99",
          "speed_max",        "jerk_p99",           "height_dev_mean",
          "distance_dev_mean", "orientation_dev_mean", "cost_mean",
          "cost_max",         "solve_us_p50",       "solve_us_p99",
          "solve_us_max",     "solid_frames",       "cuts_per_minute",
          "forced_cuts",      "discretionary_cuts", "discretionary_cuts_per_minute",
          "recovery_s_max",   "recovery_s_mean",    "duration_s",
          "body_half_visible_pct", "cuts_within_1s", "cuts_beyond_rules_60s_max"};
}

std::vector<double> metric_values(const RunMetrics& m) {
  const double kUnknown = std::numeric_limits<double>::quiet_NaN();
  return {static_cast<double>(m.frames), m.visible_percent, m.visible_fraction_mean,
          m.visible_fraction_min, static_cast<double>(m.occlusion_episodes),
          static_cast<double>(m.longest_occlusion_frames),
          static_cast<double>(m.clearance_violations), m.min_clearance,
          static_cast<double>(m.cuts), m.shortest_shot_seconds,
          static_cast<double>(m.unflagged_jumps), m.speed_p99, m.speed_max, m.jerk_p99,
          m.height_deviation_mean, m.distance_deviation_mean, m.orientation_deviation_mean,
          m.cost_mean, m.cost_max, m.solve_us_p50, m.solve_us_p99, m.solve_us_max,
          static_cast<double>(m.solid_frames), m.cuts_per_minute,
          // Unknown without a cut_reason column: NaN, which results.csv writes as "nan".
          m.cut_reasons_known ? static_cast<double>(m.forced_cuts) : kUnknown,
          m.cut_reasons_known ? static_cast<double>(m.discretionary_cuts) : kUnknown,
          m.cut_reasons_known ? m.discretionary_cuts_per_minute : kUnknown,
          m.recovery_seconds_max, m.recovery_seconds_mean, m.duration_seconds,
          m.body_half_visible_percent, static_cast<double>(m.cuts_within_1s),
          static_cast<double>(m.cuts_beyond_rules_per_60s_max)};
}

}  // namespace sightline::experiments
