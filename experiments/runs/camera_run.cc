#include "sightline/experiments/runs/camera_run.h"

#include <iomanip>
#include <sstream>

#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/experiments/runs/edit_run.h"

namespace sightline::experiments {
namespace {

// The trace's word for a cut reason (trace.h): short, no commas.
const char* cut_reason_word(camera::CutReason reason) {
  switch (reason) {
    case camera::CutReason::kNone: return "none";
    case camera::CutReason::kLeftEnclosedArea: return "left-enclosed-area";
    case camera::CutReason::kBackedUpToObstacle: return "backed-up-to-obstacle";
    case camera::CutReason::kVisibilityLost: return "visibility-lost";
    case camera::CutReason::kStuck: return "stuck";
    case camera::CutReason::kTooFast: return "too-fast";
  }
  return "unknown";
}

}  // namespace

MetricsInput metrics_input(const camera::Scene& scene, const camera::CameraProfile& profile,
                           double max_step) {
  MetricsInput input;
  input.boxes.reserve(scene.solids().size());
  for (const auto& solid : scene.solids()) input.boxes.push_back({solid.box.min, solid.box.max});
  // Movers as plain keyframes: the metrics interpolate them with their own code.
  input.movers.reserve(scene.movers().size());
  for (const camera::Mover& m : scene.movers()) {
    MovingBox& copy = input.movers.emplace_back();
    copy.size = m.size();
    for (const camera::MoverKeyframe& k : m.path()) {
      copy.times.push_back(k.t);
      copy.positions.push_back(k.position);
    }
  }
  if (const camera::Level* level = scene.level()) {
    input.triangles = std::make_shared<const IndependentTriangles>(level->mesh);
    if (level->solid) {
      std::shared_ptr<const camera::SolidVolume> solid = level->solid;
      input.solid_at = [solid](const Eigen::Vector3d& p) { return solid->solid_at(p); };
    }
  }
  input.character_size = scene.character().size;
  input.clearance_radius = profile.clearance_radius;
  // Camera positions are written with 6 decimals: allow for that rounding.
  input.max_smooth_step = max_step + 2e-6;
  return input;
}

std::string recommended_solver(const camera::Scene& scene) {
  if (scene.shot()) return camera::kRecommendedCompositionSolver;
  if (is_edit_scene(scene)) return camera::kDefaultEditSolver;
  return camera::kRecommendedCameraSolver;
}

CameraRun run_camera(const camera::Scene& scene, const camera::CameraProfile& profile,
                     const camera::ChaseCameraOptions& options) {
  CameraRun run;
  run.solver = options.solver;
  run.profile = profile.name;
  if (is_edit_scene(scene)) {
    camera::EditorOptions editor;
    editor.solver = options.solver.empty() ? camera::kDefaultEditSolver : options.solver;
    editor.seed = options.seed;
    editor.footage.seed = options.seed;
    run.solver = editor.solver;
    const camera::Edit edit = camera::edit_scene(scene, editor);
    run.trace = edit_trace(scene, edit);
    run.edit = edit_metrics(scene, run.trace, editor.weights.min_shot_seconds);
    run.metrics = compute_metrics(run.trace, metrics_input(scene, profile, options.max_speed / scene.frame_rate()));
    return run;
  }
  const std::unique_ptr<camera::CameraController> controller =
      camera::make_controller(options.solver, scene, profile, options);
  const std::size_t frames = scene.frame_count();
  run.trace.reserve(frames);
  double previous_t = scene.frame_time(0) - 1.0 / scene.frame_rate();
  for (std::size_t i = 0; i < frames; ++i) {
    const double t = scene.frame_time(i);
    const camera::CharacterState character = scene.character_at(t);
    const double dt = t - previous_t > 0 ? t - previous_t : 1.0 / scene.frame_rate();
    previous_t = t;
    const camera::CameraFrame& f = controller->update(character, dt);
    TraceRow row;
    row.frame = static_cast<int>(i);
    row.t = t;
    row.character = character.position;
    row.character_yaw = character.yaw;
    row.camera = f.position;
    row.target = f.target;
    row.cut = f.cut;
    row.cut_reason = cut_reason_word(f.cut_reason);
    row.cost = f.score.soft;
    row.solve_us = f.solve_seconds * 1e6;
    row.controller_visible = f.look_at_visible;
    row.desired_height = f.effective.desired_height;
    row.desired_distance = f.effective.desired_distance;
    row.desired_orientation = f.effective.desired_orientation;
    row.fov = f.fov;
    row.roll = f.roll;
    run.trace.push_back(row);
  }
  if (scene.shot()) run.shot = shot_metrics(scene, run.trace);
  run.metrics = compute_metrics(
      run.trace, metrics_input(scene, profile, controller->max_step(1.0 / scene.frame_rate())));
  return run;
}

std::string summary_paragraph(const camera::Scene& scene, const CameraRun& run) {
  const RunMetrics& m = run.metrics;
  if (run.edit) {
    const EditMetrics& e = *run.edit;
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(1);
    out << "Scene '" << scene.name() << "', edited by '" << run.solver << "': " << m.frames
        << " frames, " << e.shots << " shots, " << e.cuts << " cuts (" << e.cuts_per_minute
        << " a minute, mean shot " << std::setprecision(2) << e.mean_shot_seconds
        << " s); independent check: " << e.line_crossings << " line crossings, " << e.jump_cuts
        << " jump cuts, " << e.short_shots << " short shots; the speaker shown "
        << std::setprecision(1) << e.speaker_shown_percent << "% of speaking time, from the front and "
        << "readable " << e.speaker_readable_percent << "%.";
    return out.str();
  }
  if (run.shot) {
    const ShotMetrics& s = *run.shot;
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(1);
    out << "Scene '" << scene.name() << "', a tracking shot with solver '" << run.solver
        << "': " << m.frames << " frames; shown (framed and seen as the shot asks, "
        << "independent check):";
    for (std::size_t i = 0; i < s.people.size(); ++i) {
      out << (i ? "," : "") << " " << s.people[i].name << " " << s.people[i].shown_percent << "%";
    }
    out << "; satisfaction mean " << std::setprecision(3) << s.satisfaction_mean << ", 10th percentile "
        << s.satisfaction_p10 << std::setprecision(1) << "; the shot's rules kept in "
        << s.feasible_percent << "% of frames; " << m.cuts << " cut" << (m.cuts == 1 ? "" : "s")
        << " and " << m.unflagged_jumps << " unflagged jumps; solve time median " << m.solve_us_p50
        << " us, p99 " << m.solve_us_p99 << " us; camera speed p99 " << m.speed_p99
        << " m/s, jerk p99 " << m.jerk_p99 << " m/s^3.";
    return out.str();
  }
  const int visible = static_cast<int>(m.visible_percent * m.frames / 100.0 + 0.5);
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(1);
  out << "Scene '" << scene.name() << "' with solver '" << run.solver << "' and profile '"
      << run.profile << "': " << m.frames << " frames; the look-at point was visible in "
      << visible << " of them (" << m.visible_percent << "%, independent check";
  if (m.occlusion_episodes > 0) {
    out << "; lost " << m.occlusion_episodes << " time" << (m.occlusion_episodes == 1 ? "" : "s")
        << ", back in sight after " << std::setprecision(2) << m.recovery_seconds_mean
        << " s on average, " << m.recovery_seconds_max << " s at worst" << std::setprecision(1);
  }
  if (!scene.movers().empty()) {
    out << ", movers included";
  }
  out << "), the mean "
      << "visible fraction of the body " << m.visible_fraction_mean * 100 << "%; " << m.cuts
      << " cut" << (m.cuts == 1 ? "" : "s") << " (" << m.cuts_per_minute << " per minute"
      << (m.cut_reasons_known && m.cuts > 0
              ? ", " + std::to_string(m.discretionary_cuts) + " discretionary"
              : std::string())
      << ") and " << m.unflagged_jumps << " unflagged jumps (pops); " << m.clearance_violations
      << " frames inside the clearance radius" << (m.solid_frames > 0 ? ", " + std::to_string(m.solid_frames) + " inside solid matter" : std::string()) << "; cost mean " << m.cost_mean << ", max "
      << m.cost_max << "; solve time median " << m.solve_us_p50 << " us, p99 "
      << m.solve_us_p99 << " us; mean deviation from the profile: height "
      << m.height_deviation_mean << " m, distance " << m.distance_deviation_mean
      << " m, orientation " << m.orientation_deviation_mean << " deg; camera speed p99 "
      << m.speed_p99 << " m/s, jerk p99 " << m.jerk_p99 << " m/s^3.";
  return out.str();
}

}  // namespace sightline::experiments
