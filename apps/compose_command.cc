// `sightline compose SCENE.yaml [--solver NAME] [--time T] [--budget-ms MS] [--pose OUT.json]`
// (FORMATS.md "The compose command"): solves the scene's shot: at one instant, prints the
// satisfaction and each property's score, writes the pose file; exits 0 when the pose is
// feasible, 1 when the solver found none (saying which rule it breaks), 2 on bad input.
// With `--evaluate POSE.json` it solves nothing: it judges the pose of that pose file (any
// tool's) on the shot at that instant, with the same output and exit status.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/solve_options.h"
#include "sightline/domains/camera/composition/compose.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/composition/pose_file.h"
#include "sightline/domains/camera/composition/pose_reading.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/solvers/registry.h"

namespace sightline::apps {
namespace {

struct ComposeOptions {
  std::string scene;
  std::string solver = camera::kRecommendedCompositionSolver;
  std::vector<std::string> settings;
  double time = std::numeric_limits<double>::quiet_NaN();
  double budget_ms = 20;
  std::uint64_t seed = 1;
  std::string pose;
  std::string evaluate;  // a pose file to judge instead of solving
  std::string format = "text";
};

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return v > 0 ? "inf" : (std::isnan(v) ? "undefined" : "-inf");
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

void run_compose(const ComposeOptions& o) {
  const auto began = std::chrono::steady_clock::now();
  const camera::Scene scene = camera::read_scene_file(o.scene);
  const camera::Shot& shot = camera::shot_to_compose(scene, o.scene);
  if (!(o.budget_ms > 0) || !std::isfinite(o.budget_ms)) {
    throw std::invalid_argument("--budget-ms: expected a time in milliseconds > 0");
  }
  const double t = camera::compose_time(
      scene, std::isnan(o.time) ? std::nullopt : std::optional<double>(o.time), "--time");
  const camera::CompositionProblem composition(scene, shot, t);
  camera::CameraPose pose;
  camera::ShotEvaluation e;
  solvers::SolverResult result;
  std::string note;  // what the text output says about the pose's origin
  if (!o.evaluate.empty()) {
    pose = camera::read_pose_file(o.evaluate);
    // FORMATS.md: the aspect is always the shot's.
    if (std::abs(pose.aspect - shot.aspect) > 1e-6 * shot.aspect) {
      note = " (the pose file's aspect " + fixed(pose.aspect, 4) + " replaced by the shot's " +
             fixed(shot.aspect, 4) + ")";
    }
    pose.aspect = shot.aspect;
    e = composition.evaluate(pose);
  } else {
    camera::register_composition_solvers(solvers::SolverRegistry::global());
    solvers::OptionValues values;
    for (const std::string& s : o.settings) values.insert(solvers::split_option(s));
    std::unique_ptr<solvers::Solver> solver =
        solvers::SolverRegistry::global().create(o.solver, values);
    solvers::SolveContext context;
    context.seed = o.seed;
    context.limits.time_limit_seconds = o.budget_ms / 1000;
    const camera::Composed composed = camera::compose(composition, *solver, context);
    result = composed.result;
    pose = composed.pose;
    e = composed.evaluation;
  }
  const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();

  const std::string source = o.evaluate.empty() ? o.solver : "evaluated";
  camera::PoseFileExtras extras{t, source, result.wall_seconds};
  if (o.format == "json") {
    std::cout << camera::pose_json(pose, composition, e, extras);
  } else {
  std::cout << "Shot of " << scene.name() << " at t = " << fixed(t, 3) << " s, "
            << (o.evaluate.empty() ? o.solver + " (" + fixed(o.budget_ms, 1) + " ms budget)"
                                   : "the pose of " + o.evaluate + note)
            << ": satisfaction " << fixed(e.satisfaction, 4)
            << ", " << (e.feasible ? "feasible" : "infeasible: " + e.why_infeasible) << ".\n";
  std::cout << "  camera " << fixed(pose.position.x(), 3) << " " << fixed(pose.position.y(), 3)
            << " " << fixed(pose.position.z(), 3) << ", looking at "
            << fixed(pose.look_at.x(), 3) << " " << fixed(pose.look_at.y(), 3) << " "
            << fixed(pose.look_at.z(), 3) << ", fov " << fixed(pose.fov, 2) << " deg, roll "
            << fixed(pose.roll, 2) << " deg\n";
  for (std::size_t i = 0; i < shot.properties.size(); ++i) {
    const camera::ShotProperty& p = shot.properties[i];
    std::cout << "  line " << p.where.line << "  " << p.describe() << ": measured "
              << fixed(e.measures[i], 4) << ", score " << fixed(e.scores[i], 4)
              << (p.hard ? " (hard)" : "") << "\n";
  }
  if (o.evaluate.empty()) {
    std::cout << "  solve " << fixed(result.wall_seconds * 1000, 2) << " ms, "
              << result.evaluations << " evaluations; ";
  } else {
    std::cout << "  ";
  }
  std::cout << "whole command " << fixed(whole * 1000, 1) << " ms\n";
  }
  if (!o.pose.empty()) {
    std::ofstream out(o.pose);
    out << camera::pose_json(pose, composition, e, extras);
    if (!out) throw std::runtime_error("cannot write the pose file " + o.pose);
    if (o.format != "json") std::cout << "Pose written to " << o.pose << "\n";
  }
  if (!e.feasible) {
    throw RunFailed((o.evaluate.empty() ? "no feasible pose found: " : "the pose is infeasible: ") +
                    e.why_infeasible);
  }
}

}  // namespace

void add_compose_command(CLI::App& app) {
  auto options = std::make_shared<ComposeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compose", "Solve a scene's shot: at one instant and write the camera's pose (JSON)");
  cmd->add_option("scene", options->scene, "scene file with a shot: block (FORMATS.md)")->required();
  CLI::Option* solver = cmd->add_option("--solver", options->solver,
                  "registered solver or pipeline (default: shot-search, the recommended "
                  "composition solver)");
  CLI::Option* set = cmd->add_option("--set", options->settings, "solver option key=value (repeatable)");
  cmd->add_option("--time", options->time,
                  "the shot's time in seconds (default: the earliest keyframe of any person)");
  CLI::Option* budget =
      cmd->add_option("--budget-ms", options->budget_ms, "time budget of the solve (default 20 ms)");
  CLI::Option* seed = cmd->add_option("--seed", options->seed, "random seed for stochastic solvers");
  cmd->add_option("--pose", options->pose, "write the pose file (JSON) here");
  cmd->add_option("--evaluate", options->evaluate,
                  "judge the pose of this pose file (JSON, FORMATS.md; any tool's) on the shot "
                  "instead of solving: same output and exit status")
      ->excludes(solver)
      ->excludes(set)
      ->excludes(budget)
      ->excludes(seed);
  cmd->add_option("--format", options->format,
                  "text (the default) or json (the pose file's object on standard output)")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->callback([options] { run_compose(*options); });
}

}  // namespace sightline::apps
