// `sightline edit SCENE.yaml [--solver NAME] [--trace OUT.csv] [--format text|json]`: films
// a scene as an edited sequence of shots (FORMATS.md "Script and named shots"; the editor is
// domains/camera/editing): prints the shots with their start times and the costs that
// decided each cut, the model's size, the times, and the film judged by the rules of
// continuity editing (experiments/runs/edit_metrics.h); writes the trace with its `shot`
// column. Exits 0 on success, 2 on bad input.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "sightline/csp/json_text.h"
#include "sightline/domains/camera/editing/editor.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/edit_metrics.h"
#include "sightline/experiments/runs/edit_run.h"
#include "sightline/solvers/registry.h"

namespace sightline::apps {
namespace {

struct EditCommandOptions {
  std::string scene;
  std::string solver = camera::kDefaultEditSolver;
  std::string trace;
  std::string format = "text";
  double slot = 0.25;
  double min_shot = 2.0;
  double time_limit = 0;
  std::uint64_t seed = 1;
};

std::string fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

void run_edit(const EditCommandOptions& o) {
  const auto began = std::chrono::steady_clock::now();
  if (!(o.slot > 0) || !std::isfinite(o.slot)) throw std::invalid_argument("--slot: expected seconds > 0");
  if (!(o.min_shot >= 0) || !std::isfinite(o.min_shot)) {
    throw std::invalid_argument("--min-shot: expected seconds >= 0");
  }
  if (!(o.time_limit >= 0) || !std::isfinite(o.time_limit)) {
    throw std::invalid_argument("--time-limit: expected seconds >= 0");
  }
  if (o.solver != camera::kGreedyEditor) solvers::SolverRegistry::global().create(o.solver);  // known?
  const camera::Scene scene = camera::read_scene_file(o.scene);
  camera::EditorOptions options;
  options.solver = o.solver;
  options.seed = o.seed;
  options.time_limit_seconds = o.time_limit;
  options.footage.slot_seconds = o.slot;
  options.footage.seed = o.seed;
  options.weights.min_shot_seconds = o.min_shot;
  const camera::Edit edit = camera::edit_scene(scene, options);
  const std::vector<experiments::TraceRow> rows = experiments::edit_trace(scene, edit);
  if (!o.trace.empty()) experiments::write_trace_csv(o.trace, rows);
  const experiments::EditMetrics m = experiments::edit_metrics(scene, rows, o.min_shot);
  const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  const auto& names = edit.footage.candidates;
  const std::size_t slots = edit.costs.slots, shots = edit.costs.shots;
  if (o.format == "json") {
    using csp::json_number;
    using csp::json_string;
    std::cout << "{\"scene\": " << json_string(scene.name()) << ", \"solver\": " << json_string(o.solver)
              << ", \"frames\": " << rows.size() << ", \"slots\": " << slots
              << ", \"candidate_shots\": " << shots << ", \"constraints\": " << edit.model_constraints
              << ", \"cost\": " << json_number(edit.score.soft)
              << ", \"footage_seconds\": " << json_number(edit.footage.seconds)
              << ", \"solve_seconds\": " << json_number(edit.solve_seconds)
              << ", \"command_seconds\": " << json_number(whole) << ",\n \"shots\": [";
    for (std::size_t i = 0; i < edit.shots.size(); ++i) {
      const camera::FilmShot& s = edit.shots[i];
      std::cout << (i ? ",\n  " : "\n  ") << "{\"name\": " << json_string(names[s.shot].name)
                << ", \"start\": " << json_number(s.start) << ", \"end\": " << json_number(s.end)
                << ", \"why\": " << json_string(s.why) << "}";
    }
    std::cout << "],\n \"metrics\": {\"cuts\": " << m.cuts << ", \"cuts_per_minute\": "
              << json_number(m.cuts_per_minute) << ", \"mean_shot_seconds\": "
              << json_number(m.mean_shot_seconds) << ", \"short_shots\": " << m.short_shots
              << ", \"line_crossings\": " << m.line_crossings << ", \"jump_cuts\": " << m.jump_cuts
              << ", \"speaker_shown_percent\": " << json_number(m.speaker_shown_percent)
              << ", \"speaker_readable_percent\": " << json_number(m.speaker_readable_percent)
              << ", \"action_shown_percent\": " << json_number(m.action_shown_percent) << "}}\n";
    return;
  }
  std::cout << "Edit of " << scene.name() << " by " << o.solver << ": " << edit.shots.size()
            << " shots, " << m.cuts << " cuts over " << fixed(m.seconds, 2) << " s (" << rows.size()
            << " frames).\n";
  for (const camera::FilmShot& s : edit.shots) {
    std::cout << "  " << fixed(s.start, 2) << " s  " << names[s.shot].name << "  -- " << s.why << "\n";
  }
  std::cout << "Model: " << slots << " slots x " << shots << " candidate shots, "
            << edit.model_constraints << " constraints; cost " << fixed(edit.score.soft, 3) << ".\n"
            << "Judged: " << m.line_crossings << " line crossings, " << m.jump_cuts << " jump cuts, "
            << m.short_shots << " shots under " << fixed(o.min_shot, 2) << " s, "
            << fixed(m.cuts_per_minute, 1) << " cuts/min, mean shot " << fixed(m.mean_shot_seconds, 2)
            << " s; speaker shown " << fixed(m.speaker_shown_percent, 1) << "% of speaking time, from the front "
            << "and readable " << fixed(m.speaker_readable_percent, 1) << "%";
  if (m.action_seconds > 0) std::cout << "; action shown " << fixed(m.action_shown_percent, 1) << "%";
  std::cout << ".\nTimes: footage " << fixed(edit.footage.seconds, 3) << " s ("
            << edit.footage.evaluations << " shot evaluations), solve " << fixed(edit.solve_seconds, 3)
            << " s, whole command " << fixed(whole, 3) << " s.\n";
  if (!o.trace.empty()) std::cout << "Trace written to " << o.trace << "\n";
}

}  // namespace

void add_edit_command(CLI::App& app) {
  auto options = std::make_shared<EditCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "edit", "Film a scene with a script as an edited sequence of shots (cuts chosen as a weighted CSP)");
  cmd->add_option("scene", options->scene, "scene file with actors and a script: (FORMATS.md)")->required();
  cmd->add_option("--solver", options->solver,
                  "a discrete solver for the editing model (default: chain, exact dynamic "
                  "programming; bnb, tabu, lns, sls ...), or greedy (the baseline)");
  cmd->add_option("--trace", options->trace, "write the edited film's trace (CSV, with a shot column)");
  cmd->add_option("--format", options->format, "text (the default) or json")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("--slot", options->slot, "seconds per slot of the editing model (default 0.25)");
  cmd->add_option("--min-shot", options->min_shot, "the minimum shot length in seconds (default 2)");
  cmd->add_option("--time-limit", options->time_limit, "seconds for the solver (default: its own course)");
  cmd->add_option("--seed", options->seed, "random seed for stochastic solvers");
  cmd->callback([options] { run_edit(*options); });
}

}  // namespace sightline::apps
