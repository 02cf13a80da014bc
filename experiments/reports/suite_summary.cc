// The Markdown summary of a suite (declared in suite_runner.h): what `sightline run` prints
// and writes to OUT/summary.md. Camera runs get a per-solver table (over every scene,
// profile and seed) and a per-run table; toy runs one table of cost, feasibility, time,
// evaluations and the independent check.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "sightline/experiments/reports/suite_outputs.h"
#include "sightline/experiments/reports/suite_statistics.h"

namespace sightline::experiments {
namespace {

std::string fixed(double v, int decimals) {
  if (std::isnan(v)) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string str() const {
    std::ostringstream out;
    out << '|';
    for (const auto& h : header) out << ' ' << h << " |";
    out << "\n|";
    for (std::size_t i = 0; i < header.size(); ++i) out << (i < 3 ? " --- |" : " ---: |");
    out << '\n';
    for (const auto& row : rows) {
      out << '|';
      for (const auto& cell : row) out << ' ' << cell << " |";
      out << '\n';
    }
    return out.str();
  }
};

// Edited films (scenes with a script and nobody to chase, experiments/runs/edit_run.h), by
// the rules of continuity editing (experiments/runs/edit_metrics.h): per editor, then per run.
std::string edited_films_markdown(const SuiteOutcome& outcome, const std::vector<std::string>& columns) {
  if (std::find(columns.begin(), columns.end(), "edit_line_crossings") == columns.end()) return "";
  auto value = [&](const RunResult& r, const std::string& name) { return metric_value(columns, r, name); };
  std::vector<std::string> order;
  std::map<std::string, std::vector<const RunResult*>> by_editor;
  for (const RunResult& r : outcome.results) {
    if (r.kind != "camera" || r.status != "ok" || std::isnan(value(r, "edit_line_crossings"))) continue;
    if (!by_editor.count(r.solver)) order.push_back(r.solver);
    by_editor[r.solver].push_back(&r);
  }
  if (order.empty()) return "";
  std::ostringstream out;
  out << "### Edited films\n\nJudged from each trace and its scene by the rules of continuity "
         "editing (experiments/runs/edit_metrics.h): cuts across the line of action, jump cuts, "
         "shots under the minimum length are totals; the speaker shown (and from the front, a "
         "fifth of the image or more: readable) is the share of speaking time, worst run.\n\n";
  Table t{{"editor", "runs", "line crossings", "jump cuts", "short shots", "cuts / min (mean)",
           "mean shot s (mean)", "speaker shown % (min)", "readable % (min)", "action shown % (min)"},
          {}};
  for (const std::string& editor : order) {
    const auto& rs = by_editor[editor];
    double crossings = 0, jumps = 0, shorts = 0, cpm = 0, shot = 0;
    double shown = 100, readable = 100, action = 100;
    for (const RunResult* r : rs) {
      crossings += value(*r, "edit_line_crossings");
      jumps += value(*r, "edit_jump_cuts");
      shorts += value(*r, "edit_short_shots");
      cpm += value(*r, "edit_cuts_per_min") / static_cast<double>(rs.size());
      shot += value(*r, "edit_mean_shot_s") / static_cast<double>(rs.size());
      shown = std::min(shown, value(*r, "edit_speaker_shown_pct"));
      readable = std::min(readable, value(*r, "edit_speaker_readable_pct"));
      action = std::min(action, value(*r, "edit_action_shown_pct"));
    }
    t.rows.push_back({editor, std::to_string(rs.size()), fixed(crossings, 0), fixed(jumps, 0),
                      fixed(shorts, 0), fixed(cpm, 1), fixed(shot, 2), fixed(shown, 1),
                      fixed(readable, 1), fixed(action, 1)});
  }
  out << t.str() << '\n';
  Table runs{{"scene", "editor", "seed", "line crossings", "jump cuts", "short shots", "cuts / min",
              "mean shot s", "speaker shown %", "readable %", "action shown %"},
             {}};
  for (const std::string& editor : order) {
    for (const RunResult* r : by_editor[editor]) {
      runs.rows.push_back({r->subject, editor, std::to_string(r->seed),
                           fixed(value(*r, "edit_line_crossings"), 0), fixed(value(*r, "edit_jump_cuts"), 0),
                           fixed(value(*r, "edit_short_shots"), 0), fixed(value(*r, "edit_cuts_per_min"), 1),
                           fixed(value(*r, "edit_mean_shot_s"), 2), fixed(value(*r, "edit_speaker_shown_pct"), 1),
                           fixed(value(*r, "edit_speaker_readable_pct"), 1),
                           fixed(value(*r, "edit_action_shown_pct"), 1)});
    }
  }
  out << runs.str() << '\n';
  return out.str();
}

}  // namespace

std::string markdown_summary(const Suite& suite, const SuiteOutcome& outcome) {
  const std::vector<std::string> columns = metric_columns(suite);
  auto value = [&](const RunResult& r, const std::string& name) {
    return metric_value(columns, r, name);
  };

  std::ostringstream out;
  out << "## Suite `" << suite.name << "`\n\n";
  if (!suite.description.empty()) out << suite.description << "\n\n";
  out << outcome.results.size() << " of " << outcome.total << " runs finished ("
      << outcome.reused << " from an earlier invocation, " << outcome.ran << " now";
  if (outcome.failed) out << ", " << outcome.failed << " FAILED";
  out << "); " << fixed(outcome.seconds, 1) << " s.\n\n";

  // Camera: per solver over all scenes.
  std::vector<std::string> solver_order;
  std::map<std::string, std::vector<const RunResult*>> by_solver;
  for (const RunResult& r : outcome.results) {
    if (r.kind != "camera" || r.status != "ok") continue;
    const std::string key = r.solver + (suite.profiles.size() > 1 ? " / " + r.profile : "");
    if (!by_solver.count(key)) solver_order.push_back(key);
    by_solver[key].push_back(&r);
  }
  if (!solver_order.empty()) {
    out << "### Camera solvers over all scenes\n\n"
           "Visibility is judged by the independent brute-force check. Means over runs, "
           "except: occlusion episodes, clearance frames, frames in solid matter (a level's "
           "brushes), cuts and pops (moves beyond the smooth-motion bound without a cut flag) "
           "are totals; cuts per minute are over the total walk time; longest occlusion, "
           "longest recovery and p99 solve time are the worst run's. Discretionary cuts are "
           "those for any reason but lost visibility (- when a trace does not say).\n\n";
    Table t{{"solver", "runs", "frames", "look-at visible %", "body visible (mean)",
             "body visible (min)", "occlusion episodes", "longest occlusion (frames)",
             "clearance frames", "in solid frames", "cuts", "cuts / min",
             "discretionary cuts / min", "pops", "recovery max s", "speed p99 m/s",
             "jerk p99 m/s^3", "cost mean",
             "solve p50 us", "solve p99 us (worst)"},
            {}};
    for (const std::string& key : solver_order) {
      const auto& rs = by_solver[key];
      auto mean = [&](const std::string& m) {
        double s = 0;
        for (const RunResult* r : rs) s += value(*r, m);
        return s / rs.size();
      };
      auto total = [&](const std::string& m) {
        double s = 0;
        for (const RunResult* r : rs) s += value(*r, m);
        return s;
      };
      auto worst = [&](const std::string& m, bool largest) {
        double w = value(*rs.front(), m);
        for (const RunResult* r : rs) w = largest ? std::max(w, value(*r, m)) : std::min(w, value(*r, m));
        return w;
      };
      // Per minute over all the runs' walk time, so long walks weigh by their length.
      const double minutes = total("duration_s") / 60;
      auto per_minute = [&](const std::string& count) {
        return minutes > 0 ? total(count) / minutes : 0.0;
      };
      t.rows.push_back({key, std::to_string(rs.size()), fixed(total("frames"), 0),
                        fixed(mean("visible_pct"), 1), fixed(mean("visible_fraction_mean"), 3),
                        fixed(worst("visible_fraction_min", false), 3),
                        fixed(total("occlusion_episodes"), 0),
                        fixed(worst("longest_occlusion_frames", true), 0),
                        fixed(total("clearance_violations"), 0),
                        fixed(total("solid_frames"), 0), fixed(total("cuts"), 0),
                        fixed(per_minute("cuts"), 2), fixed(per_minute("discretionary_cuts"), 2),
                        fixed(total("unflagged_jumps"), 0),
                        fixed(worst("recovery_s_max", true), 2),
                        fixed(mean("speed_p99"), 2), fixed(mean("jerk_p99"), 0),
                        fixed(mean("cost_mean"), 3), fixed(mean("solve_us_p50"), 0),
                        fixed(worst("solve_us_p99", true), 0)});
    }
    out << t.str() << '\n';

    out << "### Camera runs\n\n";
    Table runs{{"scene", "solver", "profile", "seed", "visible %", "body mean", "episodes",
                "longest", "clearance", "cuts", "shortest shot s", "speed p99", "jerk p99",
                "height dev m", "distance dev m", "orient dev deg", "cost mean", "p50 us",
                "p99 us"},
               {}};
    for (const RunResult& r : outcome.results) {
      if (r.kind != "camera") continue;
      if (r.status != "ok") {
        runs.rows.push_back({r.subject, r.solver, r.profile, std::to_string(r.seed),
                             r.status + ": " + r.note});
        runs.rows.back().resize(runs.header.size(), "");
        continue;
      }
      runs.rows.push_back(
          {r.subject, r.solver, r.profile, std::to_string(r.seed),
           fixed(value(r, "visible_pct"), 1), fixed(value(r, "visible_fraction_mean"), 3),
           fixed(value(r, "occlusion_episodes"), 0), fixed(value(r, "longest_occlusion_frames"), 0),
           fixed(value(r, "clearance_violations"), 0), fixed(value(r, "cuts"), 0),
           fixed(value(r, "shortest_shot_s"), 2), fixed(value(r, "speed_p99"), 2),
           fixed(value(r, "jerk_p99"), 0), fixed(value(r, "height_dev_mean"), 2),
           fixed(value(r, "distance_dev_mean"), 2),
           fixed(value(r, "orientation_dev_mean"), 1), fixed(value(r, "cost_mean"), 3),
           fixed(value(r, "solve_us_p50"), 0), fixed(value(r, "solve_us_p99"), 0)});
    }
    out << runs.str() << '\n';
  }
  out << edited_films_markdown(outcome, columns);

  bool any_toy = false;
  Table toy{{"problem", "solver", "seed", "status", "cost", "hard violations", "feasible",
             "time s", "evaluations", "independent check"},
            {}};
  for (const RunResult& r : outcome.results) {
    if (r.kind != "toy") continue;
    any_toy = true;
    if (r.status != "ok") {
      toy.rows.push_back({r.subject, r.solver, std::to_string(r.seed), r.status + ": " + r.note,
                          "", "", "", "", "", ""});
      continue;
    }
    const std::string broken = metric_text(columns, r, "independent_broken");
    toy.rows.push_back({r.subject, r.solver, std::to_string(r.seed), "ok",
                        fixed(value(r, "cost"), 3), fixed(value(r, "hard_violations"), 0),
                        value(r, "feasible") == 1 ? "yes" : "no", fixed(value(r, "time_s"), 3),
                        fixed(value(r, "evaluations"), 0),
                        !broken.empty()
                            ? broken + " " + (r.note.find("attacking") != std::string::npos
                                                            ? "attacking pairs"
                                                            : "conflicts")
                            : "-"});
  }
  if (any_toy) out << "### Problems\n\n" << toy.str() << '\n';
  out << statistics_markdown(suite, outcome);  // repetitions over seeds, PAR-2
  return out.str();
}

}  // namespace sightline::experiments
