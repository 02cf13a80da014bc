// Ranking solvers across subjects: average ranks with ties and Friedman's test on hand-made
// results with answers worked out in the comments, the Wilcoxon comparison end to end on a
// small colouring suite (against the test computed here from results.csv), and the checks
// on the names a comparison gives.
#include "sightline/experiments/reports/suite_ranking.h"
#include "sightline/experiments/reports/suite_outputs.h"
#include "sightline/experiments/execution/suite_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "sightline/experiments/reports/statistics.h"
#include "sightline/experiments/reports/suite_statistics.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

std::string text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

void set_metric(const Suite& suite, RunResult& r, const std::string& name,
                const std::string& value) {
  const std::vector<std::string> columns = metric_columns(suite);
  r.values.resize(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) r.values[c] = value;
}

// Problems p1 p2 p3; solvers A B C; time limit 10 s.
Suite problem_suite(std::vector<std::uint64_t> seeds) {
  Suite suite;
  suite.name = "hand-made";
  for (const char* p : {"p1", "p2", "p3"}) {
    suite.problems.push_back({});
    suite.problems.back().label = p;
  }
  suite.toy_solvers.resize(3);
  suite.toy_solvers[0].label = "A";
  suite.toy_solvers[1].label = "B";
  suite.toy_solvers[2].label = "C";
  suite.toy_seeds = std::move(seeds);
  suite.toy_limits.time_limit_seconds = 10;
  return suite;
}

RunResult problem_run(const Suite& suite, const std::string& problem, const std::string& solver,
                      std::uint64_t seed, double cost, bool feasible) {
  RunResult r;
  r.kind = "toy";
  r.subject = problem;
  r.solver = solver;
  r.profile = "-";
  r.seed = seed;
  r.status = "ok";
  set_metric(suite, r, "cost", text(cost));
  set_metric(suite, r, "feasible", feasible ? "1" : "0");
  set_metric(suite, r, "time_s", "1");
  set_metric(suite, r, "stop", "completed");
  return r;
}

// Median costs per problem (A, B, C):
//   p1: 1 1 2          -> ranks 1.5 1.5 3
//   p2: 3 2 2          -> ranks 3 1.5 1.5
//   p3: 0 5 infeasible -> ranks 1 2 3 (an infeasible answer is worse than any feasible one)
// Average ranks A 5.5/3, B 5/3, C 7.5/3. A's p1 seeds cost 1, 100 and 0.5: median 1 (a mean
// of 33.8 would rank A last on p1).
// Friedman: n = 3, k = 3, R = 5.5 5 7.5; sum r^2 = 13.5 + 13.5 + 14 = 41; n k (k+1)^2 / 4 =
// 36, so the denominator is 5; n (k+1) / 2 = 6: 0.25 + 1 + 2.25 = 3.5; Q = 2 * 3.5 / 5 = 1.4,
// p = exp(-0.7) (chi-square with 2 degrees of freedom).
// Every run takes 1 s and completes, except C's infeasible p3 runs (unsolved: 20 s for PAR-2):
//   par2_s ranks p1 2 2 2, p2 2 2 2, p3 1.5 1.5 3 -> A 5.5/3, B 5.5/3, C 7/3;
//   sum r^2 = 12 + 12 + 13.5 = 37.5, denominator 1.5, spread 0.25 + 0.25 + 1 = 1.5,
//   Q = 2 * 1.5 / 1.5 = 2, p = exp(-1).
SuiteOutcome problem_outcome(const Suite& suite) {
  SuiteOutcome o;
  const std::vector<std::tuple<const char*, const char*, std::vector<double>, bool>> cells = {
      {"p1", "A", {1, 100, 0.5}, true}, {"p1", "B", {1, 1, 1}, true},
      {"p1", "C", {2, 2, 2}, true},     {"p2", "A", {3, 3, 3}, true},
      {"p2", "B", {2, 2, 2}, true},     {"p2", "C", {2, 2, 2}, true},
      {"p3", "A", {0, 0, 0}, true},     {"p3", "B", {5, 5, 5}, true},
      {"p3", "C", {0, 0, 0}, false}};
  for (const auto& [problem, solver, costs, feasible] : cells)
    for (std::size_t s = 0; s < costs.size(); ++s)
      o.results.push_back(problem_run(suite, problem, solver, s + 1, costs[s], feasible));
  o.total = o.results.size();
  return o;
}

TEST(SuiteRanking, AverageRanksShareTiesAndUseTheMedianOverSeeds) {
  const Suite suite = problem_suite({1, 2, 3});
  const std::string csv = statistics_csv(suite, problem_outcome(suite));
  EXPECT_TRUE(has_line(csv, "toy,*,A,-,cost,average_rank," + text(5.5 / 3))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,B,-,cost,average_rank," + text(5.0 / 3))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,C,-,cost,average_rank,2.5")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,A,-,par2_s,average_rank," + text(5.5 / 3))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,C,-,par2_s,average_rank," + text(7.0 / 3))) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,*,-,cost,friedman_subjects,3")) << csv;
}

TEST(SuiteRanking, SummaryShowsTheFriedmanStatisticAndPOfAKnownTable) {
  const Suite suite = problem_suite({1, 2, 3});
  const std::string md = markdown_summary(suite, problem_outcome(suite));
  EXPECT_NE(md.find("### Ranking of problem solvers"), std::string::npos) << md;
  EXPECT_NE(md.find("| solver | cost | par2_s |"), std::string::npos) << md;
  EXPECT_NE(md.find("| A | 1.83 | 1.83 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| B | 1.67 | 1.83 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| C | 2.50 | 2.33 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Friedman chi-square | 1.4 | 2 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Friedman p | " + text(std::exp(-0.7)) + " | " + text(std::exp(-1.0)) + " |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("median per subject and solver"), std::string::npos) << md;
  // No pair named: no Wilcoxon section.
  EXPECT_EQ(md.find("Wilcoxon"), std::string::npos) << md;
}

TEST(SuiteRanking, OneSubjectOrOneSolverHasNoRanking) {
  Suite suite = problem_suite({1});
  SuiteOutcome o;
  for (const char* solver : {"A", "B", "C"})
    o.results.push_back(problem_run(suite, "p1", solver, 1, 1, true));
  EXPECT_EQ(statistics_markdown(suite, o).find("### Ranking"), std::string::npos);
  EXPECT_EQ(statistics_csv(suite, o).find("average_rank"), std::string::npos);
}

// A subject where some solver has no finished run (an interrupted suite) is left out, not
// counted as that solver's loss: without p3's C runs the ranks are over p1 and p2 only.
TEST(SuiteRanking, SubjectsWithUnfinishedSolversAreLeftOut) {
  const Suite suite = problem_suite({1, 2, 3});
  SuiteOutcome o = problem_outcome(suite);
  std::erase_if(o.results, [](const RunResult& r) { return r.subject == "p3" && r.solver == "C"; });
  const std::string csv = statistics_csv(suite, o);
  EXPECT_TRUE(has_line(csv, "toy,*,*,-,cost,friedman_subjects,2")) << csv;
  EXPECT_TRUE(has_line(csv, "toy,*,A,-,cost,average_rank,2.25")) << csv;  // (1.5 + 3) / 2
  EXPECT_TRUE(has_line(csv, "toy,*,C,-,cost,average_rank,2.25")) << csv;  // (3 + 1.5) / 2
  EXPECT_NE(statistics_markdown(suite, o).find("no finished run there yet): 1 of 3 subjects."),
            std::string::npos);
}

// Camera runs: visible_pct is higher-better and a failed run ranks last.
//   s1: X 100, Y 90 -> X; s2: X 99, Y 98 -> X; s3: X 50, Y 95 -> Y; s4: X failed, Y 10 -> Y.
//   X = (1 + 1 + 2 + 2) / 4 = 1.5 (lower-better would give 1.75; a failed run counted best 1.25).
TEST(SuiteRanking, CameraRanksTakeHigherVisibilityAsBetterAndFailedRunsLast) {
  Suite suite;
  suite.name = "camera";
  for (const char* s : {"s1", "s2", "s3", "s4"}) {
    suite.scenes.push_back({});
    suite.scenes.back().label = s;
  }
  suite.camera_solvers.resize(2);
  suite.camera_solvers[0].label = "X";
  suite.camera_solvers[1].label = "Y";
  suite.profiles.push_back({"scene", std::nullopt, true, "scene", {}});
  suite.camera_seeds = {1};
  SuiteOutcome o;
  const std::vector<std::tuple<const char*, const char*, double>> cells = {
      {"s1", "X", 100}, {"s1", "Y", 90}, {"s2", "X", 99}, {"s2", "Y", 98},
      {"s3", "X", 50},  {"s3", "Y", 95}, {"s4", "X", -1}, {"s4", "Y", 10}};
  for (const auto& [scene, solver, visible] : cells) {
    RunResult r;
    r.kind = "camera";
    r.subject = scene;
    r.solver = solver;
    r.profile = "scene";
    r.status = visible < 0 ? "failed" : "ok";
    if (visible >= 0) {
      set_metric(suite, r, "visible_pct", text(visible));
      set_metric(suite, r, "cuts", "0");
      set_metric(suite, r, "jerk_p99", "1");
    }
    set_metric(suite, r, "frames", "10");
    o.results.push_back(r);
  }
  suite.comparisons.push_back({"X", "Y", {}});
  const std::string csv = statistics_csv(suite, o);
  EXPECT_TRUE(has_line(csv, "camera,*,X,-,visible_pct,average_rank,1.5")) << csv;
  EXPECT_TRUE(has_line(csv, "camera,*,Y,-,visible_pct,average_rank,1.5")) << csv;
  // cuts: X ties Y on s1..s3 and is last on s4: X = (1.5 * 3 + 2) / 4.
  EXPECT_TRUE(has_line(csv, "camera,*,X,-,cuts,average_rank,1.625")) << csv;
  // Wilcoxon on visible_pct: |differences| 10 (X), 1 (X), 45 (Y), infinite (Y) -> ranks
  // 2 1 3 4: W(X better) = 3, W(Y better) = 7; n = 4, exact p = 2 * P(W+ <= 3) = 2 * 5/16.
  EXPECT_TRUE(has_line(csv, "camera,*,X vs Y,-,visible_pct,wilcoxon_n,4")) << csv;
  EXPECT_TRUE(has_line(csv, "camera,*,X vs Y,-,visible_pct,wilcoxon_w_a_better,3")) << csv;
  EXPECT_TRUE(has_line(csv, "camera,*,X vs Y,-,visible_pct,wilcoxon_w_b_better,7")) << csv;
  EXPECT_TRUE(has_line(csv, "camera,*,X vs Y,-,visible_pct,wilcoxon_p,0.625")) << csv;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream t;
  t << in.rdbuf();
  return t.str();
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// Colouring with too few colours under an evaluation limit: the costs are deterministic and
// differ between sls and tabu on some graphs. The Wilcoxon rows of stats.csv and summary.md
// must equal the test computed here from results.csv (medians over the three seeds).
TEST(SuiteRanking, WilcoxonComparisonNamedInTheSuiteFileRunsEndToEnd) {
  ScratchDir dir("ranking-wilcoxon");
  const std::string graphs = std::string(SIGHTLINE_SOURCE_DIR) + "/examples/graphs/";
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: colour-compare
problems:
  instances:
    - {graph: )" + graphs + R"(myciel5.col, colours: [4, 5]}
    - {graph: )" + graphs + R"(queen5_5.col, colours: [4]}
    - {graph: )" + graphs + R"(queen6_6.col, colours: [5, 6]}
    - {graph: )" + graphs + R"(queen8_8.col, colours: [7, 8]}
  solvers: [sls, tabu]
  seeds: [1, 2, 3]
  limits: {max_evaluations: 3000}
statistics:
  compare: [sls, tabu]
)"));
  ASSERT_EQ(suite.comparisons.size(), 1u);
  RunnerOptions options;
  options.out_dir = dir.path("out");
  options.jobs = 2;
  options.progress = false;
  run_suite(suite, options);

  // results.csv -> cost per (problem, solver), then medians.
  std::istringstream csv(read_text(dir.path("out/results.csv")));
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = split_csv_line(line);
  auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  std::map<std::string, std::map<std::string, std::vector<double>>> costs;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = split_csv_line(line);
    ASSERT_EQ(f[column("feasible")], "1");
    costs[f[column("problem")]][f[column("solver")]].push_back(std::stod(f[column("cost")]));
  }
  ASSERT_EQ(costs.size(), 7u);
  std::vector<double> sls, tabu;
  for (auto& [problem, by_solver] : costs) {
    ASSERT_EQ(by_solver["sls"].size(), 3u);
    sls.push_back(median(by_solver["sls"]));
    tabu.push_back(median(by_solver["tabu"]));
  }
  // W(sls better) sums the ranks where sls's cost is lower: tabu - sls > 0.
  const WilcoxonResult expected = wilcoxon_signed_rank(tabu, sls);
  ASSERT_GE(expected.n, 3) << "the suite should show differences to test";

  const std::string stats = read_text(dir.path("out/stats.csv"));
  const std::string head = "toy,*,sls vs tabu,-,cost,";
  EXPECT_TRUE(has_line(stats, head + "wilcoxon_n," + std::to_string(expected.n))) << stats;
  EXPECT_TRUE(has_line(stats, head + "wilcoxon_w_a_better," + text(expected.w_plus))) << stats;
  EXPECT_TRUE(has_line(stats, head + "wilcoxon_w_b_better," + text(expected.w_minus))) << stats;
  EXPECT_TRUE(has_line(stats, head + "wilcoxon_p," + text(expected.p_value))) << stats;

  const std::string summary = read_text(dir.path("out/summary.md"));
  EXPECT_NE(summary.find("### Wilcoxon signed-rank test: `sls` vs `tabu`"), std::string::npos)
      << summary;
  const std::string row = "| cost | 7 | " + std::to_string(expected.n) + " | ";
  EXPECT_NE(summary.find(row), std::string::npos) << summary;
  const std::string ahead = expected.w_plus > expected.w_minus ? "`sls`" : "`tabu`";
  const std::size_t at = summary.find(row);
  ASSERT_NE(at, std::string::npos);
  const std::string cost_row = summary.substr(at, summary.find('\n', at) - at);
  EXPECT_NE(cost_row.find(text(expected.p_value) + " (exact)"), std::string::npos) << cost_row;
  EXPECT_NE(cost_row.find(ahead), std::string::npos) << cost_row;
}

const char* kTwoSolverSuite = R"(name: pair
problems:
  instances: [{nqueens: [4, 5]}]
  solvers: [sls, bnb]
)";

TEST(SuiteRanking, ACompareNamingAnUnknownSolverIsRefusedWithItsLine) {
  ScratchDir dir("ranking-bad");
  const std::string path = dir.write(
      "suite.yaml", std::string(kTwoSolverSuite) + "statistics:\n  compare: [sls, tabuu]\n");
  try {
    read_suite_file(path);
    FAIL() << "expected an InputError";
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().line, 6) << e.what();
    EXPECT_NE(std::string(e.what()).find("'tabuu' is not a solver"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sls, bnb"), std::string::npos) << e.what();
  }
}

TEST(SuiteRanking, MalformedComparisonsAreRefusedWithTheirLine) {
  ScratchDir dir("ranking-malformed");
  const std::vector<std::pair<std::string, int>> cases = {
      {"statistics:\n  compare: [sls, bnb, sls]\n", 6},                 // three names
      {"statistics:\n  compare: [sls, sls]\n", 6},                      // the same solver twice
      {"statistics:\n  compare:\n    - [sls, bnb]\n    - [bnb]\n", 8},  // a short pair, own line
      {"statistics:\n  comparison: [sls, bnb]\n", 6},                   // unknown key
      {"statistics:\n  compare: sls\n", 6}};                            // not a list
  for (const auto& [tail, line] : cases) {
    const std::string path = dir.write("suite.yaml", std::string(kTwoSolverSuite) + tail);
    try {
      read_suite_file(path);
      ADD_FAILURE() << "expected an InputError for\n" << tail;
    } catch (const csp::InputError& e) {
      EXPECT_EQ(e.where().line, line) << tail << e.what();
    }
  }
  // Several pairs are fine.
  const Suite ok = read_suite_file(dir.write(
      "suite.yaml",
      std::string(kTwoSolverSuite) + "statistics:\n  compare: [[sls, bnb], [bnb, sls]]\n"));
  EXPECT_EQ(ok.comparisons.size(), 2u);
}

TEST(SuiteRanking, TheCommandLineComparisonChecksItsNamesToo) {
  ScratchDir dir("ranking-option");
  Suite suite = read_suite_file(dir.write("suite.yaml", kTwoSolverSuite));
  EXPECT_THROW(add_comparison_option(suite, "sls"), csp::InputError);
  EXPECT_THROW(add_comparison_option(suite, "sls,"), csp::InputError);
  EXPECT_THROW(add_comparison_option(suite, "sls,bnb,tabu"), csp::InputError);
  try {
    add_comparison_option(suite, "sls,grid");
    ADD_FAILURE() << "expected an InputError";
  } catch (const csp::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--compare", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("'grid' is not a solver"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(suite.comparisons.empty());
  add_comparison_option(suite, "bnb,sls");
  ASSERT_EQ(suite.comparisons.size(), 1u);
  EXPECT_EQ(suite.comparisons[0].a, "bnb");
  EXPECT_EQ(suite.comparisons[0].b, "sls");
}

}  // namespace
}  // namespace sightline::experiments
