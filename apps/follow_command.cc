// `sightline follow SCENE.yaml --solver NAME [--profile NAME|FILE] [--seed S] [--trace OUT.csv]
//  [--smoothing-stages K]`
// (FORMATS.md): runs one scene with one solver through the chase camera, prints a
// one-paragraph summary and writes the trace.
#include <iostream>
#include <sstream>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "sightline/csp/json_text.h"
#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/solvers/registry.h"

namespace sightline::apps {
namespace {

struct FollowOptions {
  std::string scene;
  // FORMATS.md "The follow command": without --solver, the recommended camera solver (the
  // recommended composition solver for a scene with a shot: block).
  std::string solver;
  std::vector<std::string> settings;
  std::string profile;
  std::uint64_t seed = 1;
  std::string trace;
  bool no_guard = false;
  int smoothing_stages = 1;
  std::string format = "text";
};

// The run as one JSON object: scene, solver, profile, frames, every metric of results.csv
// by name, the people a shot keeps and its satisfaction (tracking shots), the trace path.
std::string run_json(const camera::Scene& scene, const experiments::CameraRun& run,
                     const std::string& trace) {
  std::ostringstream out;
  out << "{\"scene\": " << csp::json_string(scene.name()) << ", \"solver\": " << csp::json_string(run.solver)
      << ", \"profile\": " << csp::json_string(run.profile) << ", \"frames\": " << run.trace.size()
      << ", \"metrics\": {";
  const std::vector<std::string> names = experiments::metric_names();
  const std::vector<double> values = experiments::metric_values(run.metrics);
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) {
    out << (i ? ", " : "") << csp::json_string(names[i]) << ": " << csp::json_number(values[i]);
  }
  out << "}";
  if (run.shot) {
    out << ", \"shot\": {\"satisfaction_mean\": " << csp::json_number(run.shot->satisfaction_mean)
        << ", \"satisfaction_p10\": " << csp::json_number(run.shot->satisfaction_p10)
        << ", \"feasible_percent\": " << csp::json_number(run.shot->feasible_percent) << ", \"shown_percent\": {";
    for (std::size_t i = 0; i < run.shot->people.size(); ++i) {
      out << (i ? ", " : "") << csp::json_string(run.shot->people[i].name) << ": "
          << csp::json_number(run.shot->people[i].shown_percent);
    }
    out << "}}";
  }
  out << ", \"trace\": " << (trace.empty() ? "null" : csp::json_string(trace)) << "}";
  return out.str();
}

void run_follow(const FollowOptions& o) {
  camera::Scene scene = camera::read_scene_file(o.scene);
  camera::CameraProfile profile = scene.profile();
  if (!o.profile.empty()) {
    profile = camera::is_preset(o.profile) ? camera::preset_profile(o.profile)
                                           : camera::read_profile_file(o.profile);
  }
  camera::ChaseCameraOptions options;
  options.solver = !o.solver.empty() ? o.solver : experiments::recommended_solver(scene);
  options.seed = o.seed;
  options.visibility_guard = !o.no_guard;
  options.target_smoothing_stages = o.smoothing_stages;
  for (const std::string& s : o.settings) options.solver_options.insert(solvers::split_option(s));
  const experiments::CameraRun run = experiments::run_camera(scene, profile, options);
  if (!o.trace.empty()) experiments::write_trace_csv(o.trace, run.trace);
  if (o.format == "json") {
    std::cout << run_json(scene, run, o.trace) << "\n";
    return;
  }
  std::cout << experiments::summary_paragraph(scene, run) << "\n";
  if (!o.trace.empty()) std::cout << "Trace written to " << o.trace << "\n";
}

}  // namespace

void add_follow_command(CLI::App& app) {
  auto options = std::make_shared<FollowOptions>();
  CLI::App* cmd = app.add_subcommand(
      "follow", "Run one scene with one solver through the chase camera and write its trace");
  cmd->add_option("scene", options->scene, "scene file (YAML, see docs/CAMERA.md)")->required();
  cmd->add_option("--solver", options->solver,
                  "registered solver or pipeline, e.g. occlusion-octree, bourne-octree, sls, "
                  "occlusion-octree>ceres-refine (default: occlusion-octree, the recommended "
                  "camera solver; shot-search for a scene with a shot: block; chain, the "
                  "editor's, for a scene with only a script)");
  cmd->add_option("--set", options->settings, "solver option key=value (repeatable)");
  cmd->add_option("--profile", options->profile,
                  "camera profile: a preset name (default = anticipating, thesis = thesis-default, close-follow, high-follow, anticipating-path) or "
                  "a profile file; default: the scene's");
  cmd->add_option("--seed", options->seed, "random seed for stochastic solvers");
  cmd->add_option("--trace", options->trace, "write the per-frame trace (CSV) here");
  cmd->add_flag("--no-visibility-guard", options->no_guard,
                "move wherever the solver says, as Bourne & Sattar's controller did");
  cmd->add_option("--smoothing-stages", options->smoothing_stages,
                  "low-pass stages on the solver's target, 1-4 (2: a third of the jerk, more lag)")
      ->check(CLI::Range(1, camera::ChaseCameraOptions::kMaxSmoothingStages));
  cmd->add_option("--format", options->format,
                  "text (the default: a paragraph) or json (one object: the metrics by name)")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->callback([options] { run_follow(*options); });
}

}  // namespace sightline::apps
