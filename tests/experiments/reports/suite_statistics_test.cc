// The suite's statistics sections and stats.csv on a hand-made outcome with known answers.
#include "sightline/experiments/reports/suite_statistics.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "sightline/experiments/reports/statistics.h"

namespace sightline::experiments {
namespace {

// One problem "p", toy solvers A and B, seeds 1 2 3, toy time limit 10 s.
Suite toy_suite(double time_limit, std::vector<std::uint64_t> seeds) {
  Suite suite;
  suite.name = "hand-made";
  suite.problems.push_back({});
  suite.problems.back().label = "p";
  suite.toy_solvers.resize(2);
  suite.toy_solvers[0].label = "A";
  suite.toy_solvers[1].label = "B";
  suite.toy_seeds = std::move(seeds);
  suite.toy_limits.time_limit_seconds = time_limit;
  return suite;
}

RunResult toy_run(const Suite& suite, const std::string& solver, std::uint64_t seed, double cost,
                  double seconds, const std::string& stop) {
  RunResult r;
  r.kind = "toy";
  r.subject = "p";
  r.solver = solver;
  r.profile = "-";
  r.seed = seed;
  r.status = "ok";
  const std::vector<std::string> columns = metric_columns(suite);
  r.values.assign(columns.size(), "");
  auto set = [&](const std::string& name, const std::string& text) {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == name) r.values[c] = text;
  };
  set("cost", std::to_string(cost));
  set("feasible", "1");
  set("time_s", std::to_string(seconds));
  set("stop", stop);
  return r;
}

// A: costs 4 1 7 (median 4, mean 4), times 1 2 3, all completed -> PAR-2 (1+2+3)/3 = 2.
// B: costs 2 2 2 (every resample 2: CI [2, 2]); 4 s completed, 5 s stopped by the time limit
// (unsolved), 12 s completed but over the 10 s limit -> PAR-2 (4 + 20 + 20)/3 = 14.6667,
// 1 solved.
SuiteOutcome toy_outcome(const Suite& suite) {
  SuiteOutcome outcome;
  outcome.results = {
      toy_run(suite, "A", 1, 4, 1, "completed"),  toy_run(suite, "A", 2, 1, 2, "proven optimal"),
      toy_run(suite, "A", 3, 7, 3, "completed"),  toy_run(suite, "B", 1, 2, 4, "completed"),
      toy_run(suite, "B", 2, 2, 5, "time limit"), toy_run(suite, "B", 3, 2, 12, "completed")};
  outcome.total = outcome.results.size();
  return outcome;
}

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

TEST(SuiteStatistics, CsvHasMediansMeansIntervalsAndPar2OfAHandMadeOutcome) {
  const Suite suite = toy_suite(10.0, {1, 2, 3});
  const std::string csv = statistics_csv(suite, toy_outcome(suite));
  EXPECT_TRUE(has_line(csv, "kind,subject,solver,profile,metric,statistic,value")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,n,3")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,median,4")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,mean,4")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,time_s,median,2")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,B,-,cost,mean_ci_low,2")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,B,-,cost,median_ci_high,2")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,A,-,time_s,par2_s,2")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,A,-,time_s,solved,3")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,B,-,time_s,par2_s,14.6667")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,B,-,time_s,solved,1")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,B,-,time_s,time_limit_s,10")) << csv;
}

TEST(SuiteStatistics, MarkdownShowsRepetitionsAndPar2Sections) {
  const Suite suite = toy_suite(10.0, {1, 2, 3});
  const std::string md = statistics_markdown(suite, toy_outcome(suite));
  EXPECT_NE(md.find("### Repetitions over seeds"), std::string::npos) << md;
  EXPECT_NE(md.find("| p | A | - | cost | 3 | 4 ["), std::string::npos) << md;
  EXPECT_NE(md.find("### PAR-2"), std::string::npos) << md;
  EXPECT_NE(md.find("| B | 3 | 1 | 14.6667 |"), std::string::npos) << md;
}

// The PAR-2 line says which rule made a run solved: the solver's own stop, or the reference
// values, named by where they come from (never "given, or none" for values from a file).
TEST(SuiteStatistics, ThePar2LineStatesTheSolvedRuleTheSuiteUses) {
  Suite suite = toy_suite(10.0, {1, 2, 3});
  std::string md = statistics_markdown(suite, toy_outcome(suite));
  EXPECT_NE(md.find("when it is feasible and its solver stopped on its own"), std::string::npos) << md;
  suite.references["p"] = 4;  // as a references file gives it
  md = statistics_markdown(suite, toy_outcome(suite));
  EXPECT_NE(md.find("its problem's reference value (the suite's references:), at its time to best"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("given, or none"), std::string::npos) << md;
  EXPECT_EQ(md.find("stopped on its own"), std::string::npos) << md;
}

// Without a suite time limit the slowest run (12 s) is the limit: B = (4 + 24 + 12)/3 = 13.3333,
// now with 2 solved.
TEST(SuiteStatistics, WithoutATimeLimitTheSlowestRunSetsIt) {
  const Suite suite = toy_suite(0.0, {1, 2, 3});
  const std::string csv = statistics_csv(suite, toy_outcome(suite));
  EXPECT_TRUE(has_line(csv, "toy,*,B,-,time_s,par2_s,13.3333")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,B,-,time_s,solved,2")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,B,-,time_s,time_limit_s,12")) << csv;
}

TEST(SuiteStatistics, OneSeedHasNoRepetitionSection) {
  const Suite suite = toy_suite(10.0, {1});
  const std::string md = statistics_markdown(suite, toy_outcome(suite));
  EXPECT_EQ(md.find("### Repetitions over seeds"), std::string::npos) << md;
  EXPECT_NE(md.find("### PAR-2"), std::string::npos) << md;
  const std::string csv = statistics_csv(suite, toy_outcome(suite));
  EXPECT_EQ(csv.find(",cost,median,"), std::string::npos) << csv;
}

// The CSV's intervals are statistics.h's bootstrap of the right statistic: with an outlier
// (costs 1 2 3 4 5 100) the two intervals differ, so a swap would show.
TEST(SuiteStatistics, IntervalsAreTheBootstrapOfTheNamedStatistic) {
  const Suite suite = toy_suite(10.0, {1, 2, 3, 4, 5, 6});
  SuiteOutcome outcome;
  const std::vector<double> costs = {1, 2, 3, 4, 5, 100};
  for (std::size_t i = 0; i < costs.size(); ++i)
    outcome.results.push_back(toy_run(suite, "A", i + 1, costs[i], 1, "completed"));
  const std::string csv = statistics_csv(suite, outcome);
  auto text = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return std::string(buffer);
  };
  const ConfidenceInterval mean_ci = bootstrap_mean_ci(costs);
  const ConfidenceInterval median_ci = bootstrap_median_ci(costs);
  ASSERT_TRUE(mean_ci.low != median_ci.low || mean_ci.high != median_ci.high);
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,mean_ci_high," + text(mean_ci.high))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,mean_ci_low," + text(mean_ci.low))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,median_ci_high," + text(median_ci.high))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,median_ci_low," + text(median_ci.low))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,median,3.5")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,p,A,-,cost,mean,19.1667")) << csv;  // 115 / 6
  // One solver: no PAR-2 comparison.
  EXPECT_EQ(csv.find("par2_s"), std::string::npos) << csv;
}

}  // namespace
}  // namespace sightline::experiments
