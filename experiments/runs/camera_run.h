// CameraRun: one scene followed by one chase camera, frame by frame, as a trace plus metrics.
//
// The simulation of FORMATS.md: frames every 1 / frame_rate seconds from the first to the
// last keyframe, both ends included; each frame the character's state comes from the
// trajectory and the controller updates once. The trace is what `sightline follow` writes;
// the metrics judge visibility and clearance with the independent brute-force checks.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/experiments/runs/controllers.h"
#include "sightline/experiments/runs/edit_metrics.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/metrics.h"
#include "sightline/experiments/runs/shot_metrics.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

struct CameraRun {
  std::vector<TraceRow> trace;
  RunMetrics metrics;
  // For a scene with a shot: block (a tracking shot): how it kept its people.
  std::optional<ShotMetrics> shot;
  // For a scene an editor films (is_edit_scene): the film judged by continuity editing.
  std::optional<EditMetrics> edit;
  std::string solver;
  std::string profile;
};

// Runs `scene` with `profile` and the controller named by `options.solver` (a solver or
// pipeline driving a ChaseCamera, or a baseline such as "spring-arm"). Throws what
// make_controller throws for bad names or options. A scene an editor films (edit_run.h) is
// edited instead, `options.solver` solving the editing model (empty: chain; "greedy": the
// greedy editor).
CameraRun run_camera(const camera::Scene& scene, const camera::CameraProfile& profile,
                     const camera::ChaseCameraOptions& options);

// The solver a run of `scene` uses when none is named (FORMATS.md "The follow command"):
// the recommended composition solver for a scene with a shot: block, the editor's default
// for a scene an editor films (edit_run.h), else the recommended camera solver.
std::string recommended_solver(const camera::Scene& scene);

// The metrics' view of a scene: its boxes, its movers' keyframes, the character's size, the camera's radius and
// the controller's smooth-motion bound for one frame (CameraController::max_step).
MetricsInput metrics_input(const camera::Scene& scene, const camera::CameraProfile& profile,
                           double max_step);

// The one-paragraph summary of a run that `sightline follow` prints.
std::string summary_paragraph(const camera::Scene& scene, const CameraRun& run);

}  // namespace sightline::experiments
