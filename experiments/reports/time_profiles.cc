#include "sightline/experiments/reports/time_profiles.h"

#include "sightline/experiments/runs/output_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace sightline::experiments {
namespace {

// Labels in the order they first appear among `runs`.
template <typename Field>
std::vector<std::string> first_seen(const std::vector<const RunResult*>& runs, Field field) {
  std::vector<std::string> labels;
  for (const RunResult* r : runs)
    if (std::find(labels.begin(), labels.end(), field(*r)) == labels.end())
      labels.push_back(field(*r));
  return labels;
}

std::size_t index_of(const std::vector<std::string>& labels, const std::string& label) {
  return static_cast<std::size_t>(std::find(labels.begin(), labels.end(), label) - labels.begin());
}

}  // namespace

double problem_time_limit(const Suite& suite, const SuiteOutcome& outcome) {
  if (suite.toy_limits.time_limit_seconds > 0) return suite.toy_limits.time_limit_seconds;
  const std::vector<std::string> columns = metric_columns(suite);
  double slowest = 0;
  for (const RunResult& r : outcome.results) {
    if (r.kind != "toy") continue;
    const double seconds = metric_value(columns, r, "time_s");
    if (!std::isnan(seconds)) slowest = std::max(slowest, seconds);
  }
  return std::max(slowest, 1e-6);  // all-zero times: any positive limit
}

std::optional<double> problem_reference(const Suite& suite, const SuiteOutcome& outcome,
                                        const std::string& problem_label) {
  if (const auto it = suite.references.find(problem_label); it != suite.references.end()) {
    return it->second;
  }
  if (suite.reference_from.empty()) return std::nullopt;
  const std::vector<std::string> columns = metric_columns(suite);
  for (const RunResult& r : outcome.results) {
    if (r.kind == "toy" && r.solver == suite.reference_from && r.subject == problem_label &&
        r.status == "ok" && metric_text(columns, r, "stop") == "proven optimal" &&
        metric_value(columns, r, "feasible") == 1.0) {
      return metric_value(columns, r, "cost");
    }
  }
  return std::nullopt;
}

TimedRun problem_timed_run(const Suite& suite, const SuiteOutcome& outcome,
                           const std::vector<std::string>& columns, const RunResult& run) {
  const double seconds = metric_value(columns, run, "time_s");
  if (const std::optional<double> reference = problem_reference(suite, outcome, run.subject)) {
    const double cost = metric_value(columns, run, "cost");
    const double to_best = metric_value(columns, run, "time_to_best_s");
    const bool solved = run.status == "ok" && metric_value(columns, run, "feasible") == 1.0 &&
                        cost <= *reference + suite.reference_tolerance;
    const double at = !std::isnan(to_best) ? to_best : (std::isnan(seconds) ? 0.0 : seconds);
    return {solved, at};
  }
  const std::string stop = metric_text(columns, run, "stop");
  const bool solved =
      run.status == "ok" && metric_value(columns, run, "feasible") == 1.0 &&
      (stop == "completed" || stop == "proven optimal" || stop == "target reached") &&
      !std::isnan(seconds);
  return {solved, std::isnan(seconds) ? 0.0 : seconds};
}

std::string solved_rule_text(const Suite& suite) {
  const std::string stop_rule =
      "when it is feasible and its solver stopped on its own (completed, proven optimal or "
      "target reached)";
  const bool given = !suite.references.empty(), from = !suite.reference_from.empty();
  if (!given && !from) return "a run is solved " + stop_rule;
  std::string source = given ? "the suite's references:" : "";
  if (from) source += (given ? ", else " : "") + std::string("the optimum ") + suite.reference_from + " proves";
  std::string text = "a run is solved when it is feasible and its cost is within " +
                     statistic_text(suite.reference_tolerance) +
                     " of its problem's reference value (" + source + "), at its time to best";
  bool every_problem_given = true;
  for (const SuiteProblem& p : suite.problems) every_problem_given = every_problem_given && suite.references.count(p.label);
  if (from || !every_problem_given) text += "; on a problem without a reference, " + stop_rule;
  return text;
}

TimeProfiles problem_time_profiles(const Suite& suite, const SuiteOutcome& outcome) {
  TimeProfiles p;
  const std::vector<std::string> columns = metric_columns(suite);
  std::vector<const RunResult*> runs;
  for (const RunResult& r : outcome.results)
    if (r.kind == "toy") runs.push_back(&r);
  if (runs.empty()) return p;
  p.solvers = first_seen(runs, [](const RunResult& r) { return r.solver; });
  p.instances = first_seen(runs, [](const RunResult& r) { return r.subject; });
  p.time_limit = problem_time_limit(suite, outcome);

  const double infinite = std::numeric_limits<double>::infinity();
  p.runs.resize(p.solvers.size());
  // Per (instance, solver): the seconds of each run, infinite when it is not solved in time.
  std::vector<std::vector<std::vector<double>>> seconds(
      p.instances.size(), std::vector<std::vector<double>>(p.solvers.size()));
  for (const RunResult* r : runs) {
    const std::size_t s = index_of(p.solvers, r->solver);
    const TimedRun timed = problem_timed_run(suite, outcome, columns, *r);
    p.runs[s].push_back(timed);
    const bool in_time = timed.solved && timed.seconds <= p.time_limit;
    seconds[index_of(p.instances, r->subject)][s].push_back(in_time ? timed.seconds : infinite);
  }
  for (const auto& solver_runs : p.runs)
    p.cactus.push_back(cactus_curve(solver_runs, p.time_limit));

  // The median run per (instance, solver) decides; then statistics.h's ratios.
  std::vector<std::vector<TimedRun>> table;
  for (const auto& row : seconds) {
    std::vector<TimedRun>& out = table.emplace_back();
    for (const auto& times : row) {
      const double m = times.empty() ? infinite : median(times);
      out.push_back({std::isfinite(m), std::isfinite(m) ? m : 0.0});
    }
  }
  p.ratios = performance_ratios(table);
  p.taus.push_back(1.0);
  for (const auto& row : p.ratios)
    for (double r : row)
      if (std::isfinite(r)) p.taus.push_back(r);
  std::sort(p.taus.begin(), p.taus.end());
  p.taus.erase(std::unique(p.taus.begin(), p.taus.end()), p.taus.end());
  return p;
}

std::string cactus_csv(const TimeProfiles& profiles) {
  std::ostringstream out;
  out << "solver,runs_solved,seconds\n";
  for (std::size_t s = 0; s < profiles.solvers.size(); ++s)
    for (const CactusPoint& point : profiles.cactus[s])
      out << csv_field(profiles.solvers[s]) << ',' << point.runs_solved << ','
          << statistic_text(point.seconds) << '\n';
  return out.str();
}

std::string profiles_csv(const TimeProfiles& profiles) {
  std::ostringstream out;
  out << "solver,tau,fraction\n";
  if (profiles.ratios.empty()) return out.str();
  std::vector<std::vector<double>> fractions;  // [tau][solver]
  for (double tau : profiles.taus)
    fractions.push_back(performance_profile_at(profiles.ratios, tau));
  for (std::size_t s = 0; s < profiles.solvers.size(); ++s)
    for (std::size_t t = 0; t < profiles.taus.size(); ++t)
      out << csv_field(profiles.solvers[s]) << ',' << statistic_text(profiles.taus[t]) << ','
          << statistic_text(fractions[t][s]) << '\n';
  return out.str();
}

}  // namespace sightline::experiments
