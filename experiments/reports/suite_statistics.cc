#include "sightline/experiments/reports/suite_statistics.h"

#include "sightline/experiments/runs/output_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>
#include <vector>

#include "sightline/experiments/reports/statistics.h"
#include "sightline/experiments/reports/suite_ranking.h"
#include "sightline/experiments/reports/time_profiles.h"

namespace sightline::experiments {
namespace {

struct MetricSummary {
  std::string metric;
  std::size_t n = 0;
  double median = 0, mean = 0;
  ConfidenceInterval mean_ci, median_ci;
};

struct Group {
  std::string kind, subject, solver, profile;
  std::vector<MetricSummary> metrics;
};

struct Par2Row {
  std::string solver;
  std::size_t runs = 0, solved = 0;
  double par2 = 0, time_limit = 0;
};

struct Statistics {
  std::vector<Group> groups;
  std::vector<Par2Row> par2;
};

Statistics compute(const Suite& suite, const SuiteOutcome& outcome) {
  const std::vector<std::string> columns = metric_columns(suite);
  auto value = [&](const RunResult& r, const std::string& name) {
    return metric_value(columns, r, name);
  };
  Statistics s;

  // Repetitions over seeds: groups in the order they first appear.
  using Key = std::tuple<std::string, std::string, std::string, std::string>;
  std::vector<Key> order;
  std::map<Key, std::vector<const RunResult*>> runs;
  for (const RunResult& r : outcome.results) {
    if (r.status != "ok") continue;
    const bool repeated =
        r.kind == "camera" ? suite.camera_seeds.size() > 1 : suite.toy_seeds.size() > 1;
    if (!repeated) continue;
    const Key key{r.kind, r.subject, r.solver, r.profile};
    if (!runs.count(key)) order.push_back(key);
    runs[key].push_back(&r);
  }
  for (const Key& key : order) {
    Group g{std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key), {}};
    const std::vector<std::string> headline =
        g.kind == "camera"
            ? std::vector<std::string>{"visible_pct", "cost_mean", "cuts", "solve_us_p99"}
            : std::vector<std::string>{"cost", "time_s"};
    for (const std::string& metric : headline) {
      std::vector<double> values;
      for (const RunResult* r : runs[key]) {
        const double v = value(*r, metric);
        if (!std::isnan(v)) values.push_back(v);
      }
      if (values.empty()) continue;
      g.metrics.push_back({metric, values.size(), median(values), mean(values),
                           bootstrap_mean_ci(values), bootstrap_median_ci(values)});
    }
    s.groups.push_back(std::move(g));
  }

  // PAR-2 per toy solver, when there are several to compare (time_profiles.h says what
  // counts as solved and which time limit applies).
  std::vector<std::string> solvers;
  std::map<std::string, std::vector<TimedRun>> timed;
  for (const RunResult& r : outcome.results) {
    if (r.kind != "toy") continue;
    if (!timed.count(r.solver)) solvers.push_back(r.solver);
    timed[r.solver].push_back(problem_timed_run(suite, outcome, columns, r));
  }
  if (solvers.size() > 1) {
    const double limit = problem_time_limit(suite, outcome);
    for (const std::string& solver : solvers) {
      const auto& rs = timed[solver];
      const std::size_t solved = cactus_curve(rs, limit).size();
      s.par2.push_back({solver, rs.size(), solved, par2_score(rs, limit), limit});
    }
  }
  return s;
}

}  // namespace

std::string statistics_markdown(const Suite& suite, const SuiteOutcome& outcome) {
  const Statistics s = compute(suite, outcome);
  std::ostringstream out;
  if (!s.groups.empty()) {
    out << "### Repetitions over seeds\n\n"
           "Per scene or problem and solver: median and mean over seeds, each with a "
           "percentile-bootstrap 95% confidence interval (2000 resamples, fixed seed).\n\n"
           "| scene or problem | solver | profile | metric | n | median [95% CI] | mean [95% CI] "
           "|\n"
           "| --- | --- | --- | --- | ---: | ---: | ---: |\n";
    for (const Group& g : s.groups)
      for (const MetricSummary& m : g.metrics)
        out << "| " << g.subject << " | " << g.solver << " | " << g.profile << " | " << m.metric
            << " | " << m.n << " | " << statistic_text(m.median) << " ["
            << statistic_text(m.median_ci.low) << ", " << statistic_text(m.median_ci.high) << "] | "
            << statistic_text(m.mean) << " [" << statistic_text(m.mean_ci.low) << ", "
            << statistic_text(m.mean_ci.high) << "] |\n";
    out << '\n';
  }
  if (!s.par2.empty()) {
    out << "### PAR-2\n\n"
        << "Mean time over each solver's problem runs: " << solved_rule_text(suite)
        << "; an unsolved run (or one not solved in time) counts twice the time limit of "
        << statistic_text(s.par2.front().time_limit)
        << " s (the suite's toy time limit, else the slowest run's time).\n\n"
           "| solver | runs | solved | PAR-2 s |\n| --- | ---: | ---: | ---: |\n";
    for (const Par2Row& p : s.par2)
      out << "| " << p.solver << " | " << p.runs << " | " << p.solved << " | "
          << statistic_text(p.par2) << " |\n";
    out << '\n';
  }
  out << ranking_markdown(suite, outcome);  // average ranks, Friedman, Wilcoxon on demand
  return out.str();
}

std::string statistics_csv(const Suite& suite, const SuiteOutcome& outcome) {
  const Statistics s = compute(suite, outcome);
  std::ostringstream out;
  out << "kind,subject,solver,profile,metric,statistic,value\n";
  for (const Group& g : s.groups) {
    const std::string prefix = g.kind + ',' + csv_field(g.subject) + ',' + csv_field(g.solver) +
                               ',' + csv_field(g.profile) + ',';
    for (const MetricSummary& m : g.metrics) {
      const std::pair<const char*, double> rows[] = {{"n", static_cast<double>(m.n)},
                                                     {"median", m.median},
                                                     {"mean", m.mean},
                                                     {"mean_ci_low", m.mean_ci.low},
                                                     {"mean_ci_high", m.mean_ci.high},
                                                     {"median_ci_low", m.median_ci.low},
                                                     {"median_ci_high", m.median_ci.high}};
      for (const auto& [statistic, v] : rows)
        out << prefix << m.metric << ',' << statistic << ',' << statistic_text(v) << '\n';
    }
  }
  for (const Par2Row& p : s.par2) {
    const std::string prefix = "toy,*," + csv_field(p.solver) + ",-,time_s,";
    out << prefix << "runs," << p.runs << '\n'
        << prefix << "solved," << p.solved << '\n'
        << prefix << "par2_s," << statistic_text(p.par2) << '\n'
        << prefix << "time_limit_s," << statistic_text(p.time_limit) << '\n';
  }
  out << ranking_csv_rows(suite, outcome);
  return out.str();
}

std::vector<std::pair<std::string, std::string>> statistics_files(const Suite& suite,
                                                                  const SuiteOutcome& outcome) {
  std::vector<std::pair<std::string, std::string>> files = {
      {"stats.csv", statistics_csv(suite, outcome)}};
  const TimeProfiles profiles = problem_time_profiles(suite, outcome);
  if (!profiles.solvers.empty()) {
    files.emplace_back("cactus.csv", cactus_csv(profiles));
    files.emplace_back("profiles.csv", profiles_csv(profiles));
  }
  return files;
}

}  // namespace sightline::experiments
