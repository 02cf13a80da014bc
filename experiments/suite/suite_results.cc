#include "sightline/experiments/suite/suite_results.h"

#include <algorithm>
#include <cmath>

#include "sightline/experiments/runs/edit_metrics.h"
#include "sightline/experiments/runs/edit_run.h"
#include "sightline/experiments/runs/metrics.h"
#include "sightline/experiments/runs/shot_metrics.h"

namespace sightline::experiments {
namespace {

const std::vector<std::string>& toy_metric_names() {
  static const std::vector<std::string> names = {
      "cost", "hard_violations", "feasible", "time_s", "evaluations", "iterations", "stop",
      "independent_broken", "time_to_best_s", "evaluations_to_best",
      // The best feasible cost at 1%, 10% and 50% of the time limit (anytime curves in
      // runs/<id>.anytime.csv); empty without a time limit or before the first feasible one.
      "cost_at_1pct", "cost_at_10pct", "cost_at_50pct"};
  return names;
}

}  // namespace

std::string metric_text(const std::vector<std::string>& columns, const RunResult& r,
                        const std::string& name) {
  const auto c = static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) -
                                          columns.begin());
  return c < r.values.size() ? r.values[c] : std::string();
}

double metric_value(const std::vector<std::string>& columns, const RunResult& r,
                    const std::string& name) {
  const std::string text = metric_text(columns, r, name);
  if (text.empty()) return std::nan("");
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return std::nan("");
  }
}

std::vector<std::string> metric_columns(const Suite& suite) {
  std::vector<std::string> columns;
  if (!suite.scenes.empty()) columns = metric_names();
  // Scenes an editor films add the edit's columns (suites without them keep their columns).
  if (std::any_of(suite.scenes.begin(), suite.scenes.end(),
                  [](const SuiteScene& s) { return s.scene && is_edit_scene(*s.scene); })) {
    columns.insert(columns.end(), edit_metric_names().begin(), edit_metric_names().end());
  }
  // Scenes with a shot: block (tracking shots) add the shot's columns likewise.
  if (std::any_of(suite.scenes.begin(), suite.scenes.end(),
                  [](const SuiteScene& s) { return s.scene && s.scene->shot() != nullptr; })) {
    columns.insert(columns.end(), shot_metric_names().begin(), shot_metric_names().end());
  }
  if (!suite.problems.empty()) {
    columns.insert(columns.end(), toy_metric_names().begin(), toy_metric_names().end());
  }
  return columns;
}

std::vector<std::string> result_columns(const Suite& suite) {
  std::vector<std::string> columns = {"id", "kind", suite.scenes.empty() ? "problem" : "scene",
                                      "solver", "profile", "seed", "status"};
  for (const std::string& m : metric_columns(suite)) columns.push_back(m);
  columns.push_back("note");
  for (const char* p : {"host", "cpu_model", "build_commit", "command_line", "run_wall_s",
                        "run_cpu_s", "run_max_rss_mb"}) {
    columns.push_back(p);
  }
  return columns;
}

bool is_provenance_column(const std::string& column) {
  return column == "host" || column == "cpu_model" || column == "build_commit" ||
         column == "command_line";
}

bool is_timing_column(const std::string& column) {
  return column == "solve_us_p50" || column == "solve_us_p99" || column == "solve_us_max" ||
         column == "time_s" || column == "time_to_best_s" || column == "run_wall_s" || column == "run_cpu_s" ||
         column == "run_max_rss_mb";
}

}  // namespace sightline::experiments
