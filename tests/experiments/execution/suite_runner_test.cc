// The suite runner: resumes without redoing finished runs, never takes a half-written result
// for a finished one, produces the same results.csv as an uninterrupted run, and writes a
// self-contained report.
#include "sightline/experiments/execution/suite_runner.h"

#include <algorithm>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sightline/experiments/reports/report.h"
#include "tests/experiments/comparable_results.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;
using testing::kTinySuite;
using testing::read_text;
using testing::without_timing;
namespace fs = std::filesystem;

RunnerOptions options_for(const std::string& out, std::size_t max_new_runs = 0) {
  RunnerOptions o;
  o.out_dir = out;
  o.jobs = 2;
  o.max_new_runs = max_new_runs;
  o.progress = false;
  o.isolation.program = SIGHTLINE_BINARY;  // not this test program
  return o;
}

TEST(SuiteRunner, ResumesWithoutRedoingFinishedRunsAndMatchesAFreshRun) {
  ScratchDir dir("runner-resume");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTinySuite));
  const std::size_t total = expand_runs(suite).size();
  ASSERT_EQ(total, 8u);

  // Interrupted after 3 runs...
  const SuiteOutcome first = run_suite(suite, options_for(dir.path("out"), 3));
  EXPECT_EQ(first.ran, 3u);
  EXPECT_EQ(first.reused, 0u);
  EXPECT_EQ(first.results.size(), 3u);
  // ... started again: the 3 are kept, the other 5 done, none twice.
  const SuiteOutcome second = run_suite(suite, options_for(dir.path("out")));
  EXPECT_EQ(second.reused, 3u);
  EXPECT_EQ(second.ran, 5u);
  EXPECT_EQ(second.results.size(), total);
  EXPECT_EQ(second.failed, 0u);
  // A third invocation has nothing left to do.
  const SuiteOutcome third = run_suite(suite, options_for(dir.path("out")));
  EXPECT_EQ(third.ran, 0u);
  EXPECT_EQ(third.reused, total);
  const std::string resumed = read_text(dir.path("out/results.csv"));

  const SuiteOutcome fresh = run_suite(suite, options_for(dir.path("fresh")));
  EXPECT_EQ(fresh.ran, total);
  const std::string uninterrupted = read_text(dir.path("fresh/results.csv"));
  EXPECT_EQ(without_timing(suite, resumed), without_timing(suite, uninterrupted));
  // One header and one row per run.
  EXPECT_EQ(std::count(resumed.begin(), resumed.end(), '\n'), static_cast<long>(total + 1));
}

TEST(SuiteRunner, AHalfWrittenOrStrayResultIsRedone) {
  ScratchDir dir("runner-partial");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTinySuite));
  const std::vector<SuiteRun> runs = expand_runs(suite);
  run_suite(suite, options_for(dir.path("out")));
  const fs::path run_dir = dir.path("out/runs");

  // Run 0: only a stray .tmp left, as if killed before the rename.
  const fs::path result0 = run_dir / (runs[0].id + ".result");
  fs::rename(result0, run_dir / (runs[0].id + ".result.tmp"));
  // Run 5: the file cut short (no end marker), as if written without the rename.
  const fs::path result5 = run_dir / (runs[5].id + ".result");
  std::string text = read_text(result5.string());
  std::ofstream(result5, std::ios::trunc) << text.substr(0, text.size() / 2);

  const SuiteOutcome again = run_suite(suite, options_for(dir.path("out")));
  EXPECT_EQ(again.ran, 2u);
  EXPECT_EQ(again.reused, runs.size() - 2);
  RunResult r;
  EXPECT_TRUE(read_run_file(result0.string(), r));
  EXPECT_TRUE(read_run_file(result5.string(), r));
}

TEST(SuiteRunner, EditingAProfileFileRedoesExactlyTheRunsWithThatProfile) {
  ScratchDir dir("runner-profile-edit");
  dir.write("profiles/near.yaml", "name: near\nbase: close-follow\ndistance: {desired: 2.5}\n");
  dir.write("profiles/far.yaml", "name: far\ndistance: {desired: 5}\n");
  const std::string suite_path = dir.write("suite.yaml", R"(name: profile-edit
camera:
  scenes: [scenes/wall.yaml]
  solvers: [occlusion-octree]
  profiles: [profiles/near.yaml, profiles/far.yaml]
  seeds: [1, 2]
)");
  const std::vector<SuiteRun> before = expand_runs(read_suite_file(suite_path));
  ASSERT_EQ(before.size(), 4u);
  const SuiteOutcome first = run_suite(read_suite_file(suite_path), options_for(dir.path("out")));
  EXPECT_EQ(first.ran, 4u);
  EXPECT_EQ(first.failed, 0u);

  // The same profile written differently (keys reordered, a comment): nothing is redone.
  dir.write("profiles/far.yaml", "# farther back\ndistance: {desired: 5.0}\nname: far\n");
  const SuiteOutcome same = run_suite(read_suite_file(suite_path), options_for(dir.path("out")));
  EXPECT_EQ(same.ran, 0u);
  EXPECT_EQ(same.reused, 4u);

  // One number of far.yaml edited: its two seeds run again with the new profile, near's are
  // kept; the file name, and so the profile's source, did not change.
  dir.write("profiles/far.yaml", "name: far\ndistance: {desired: 5.5}\n");
  const Suite edited = read_suite_file(suite_path);
  const std::vector<SuiteRun> after = expand_runs(edited);
  ASSERT_EQ(after.size(), 4u);
  const SuiteOutcome second = run_suite(edited, options_for(dir.path("out")));
  EXPECT_EQ(second.ran, 2u);
  EXPECT_EQ(second.reused, 2u);
  EXPECT_EQ(second.failed, 0u);
  ASSERT_EQ(second.results.size(), 4u);
  for (std::size_t i = 0; i < after.size(); ++i) {
    const bool far = edited.profiles[after[i].profile].label == "far";
    EXPECT_EQ(after[i].id != before[i].id, far) << after[i].id;
    // Each result names the run's current definition: none is the stale one.
    RunResult r;
    ASSERT_TRUE(read_run_file(dir.path("out/runs/" + after[i].id + ".result"), r));
    EXPECT_EQ(r.definition, after[i].definition);
  }
  const std::string csv = read_text(dir.path("out/results.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5) << csv;
}

TEST(SuiteRunner, ToyRunsReportCostFeasibilityAndTheIndependentCheck) {
  ScratchDir dir("runner-toy");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: toy
problems:
  instances: [{nqueens: [3, 8]}]
  solvers: [bnb]
)"));
  const SuiteOutcome outcome = run_suite(suite, options_for(dir.path("out")));
  ASSERT_EQ(outcome.results.size(), 2u);
  const std::vector<std::string> columns = metric_columns(suite);
  auto value = [&](const RunResult& r, const std::string& name) {
    return r.values[std::find(columns.begin(), columns.end(), name) - columns.begin()];
  };
  // 3-queens has no solution: its best assignment breaks a hard constraint, and the
  // independent count of attacking pairs agrees that queens attack.
  EXPECT_EQ(value(outcome.results[0], "feasible"), "0");
  EXPECT_NE(value(outcome.results[0], "hard_violations"), "0");
  EXPECT_NE(value(outcome.results[0], "independent_broken"), "0");
  // 8-queens has solutions.
  EXPECT_EQ(value(outcome.results[1], "hard_violations"), "0");
  EXPECT_EQ(value(outcome.results[1], "feasible"), "1");
  EXPECT_EQ(value(outcome.results[1], "independent_broken"), "0");
  EXPECT_EQ(result_columns(suite)[2], "problem");
}

TEST(SuiteRunner, ToyRunsRecordWhenTheBestWasFound) {
  ScratchDir dir("runner-best");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: best
problems:
  instances: [{nqueens: [20]}]
  solvers: [sls, bnb]
)"));
  const SuiteOutcome outcome = run_suite(suite, options_for(dir.path("out")));
  ASSERT_EQ(outcome.results.size(), 2u);
  const std::vector<std::string> columns = metric_columns(suite);
  auto value = [&](const RunResult& r, const std::string& name) {
    return r.values[std::find(columns.begin(), columns.end(), name) - columns.begin()];
  };
  // Both note when they found their best (bnb: its last incumbent).
  const RunResult& sls = outcome.results[0].solver == "sls" ? outcome.results[0] : outcome.results[1];
  const RunResult& bnb = outcome.results[0].solver == "sls" ? outcome.results[1] : outcome.results[0];
  ASSERT_FALSE(value(sls, "time_to_best_s").empty());
  EXPECT_LE(std::stod(value(sls, "time_to_best_s")), std::stod(value(sls, "time_s")) + 1e-9);
  EXPECT_LE(std::stoull(value(sls, "evaluations_to_best")), std::stoull(value(sls, "evaluations")));
  ASSERT_FALSE(value(bnb, "time_to_best_s").empty());
  EXPECT_LE(std::stod(value(bnb, "time_to_best_s")), std::stod(value(bnb, "time_s")) + 1e-9);
  EXPECT_LE(std::stoull(value(bnb, "evaluations_to_best")), std::stoull(value(bnb, "evaluations")));
  // Without a time limit there are no checkpoints of it, and the cells stay empty.
  EXPECT_TRUE(value(sls, "cost_at_10pct").empty());
  // The anytime trajectory beside the result: a header and one row per improvement.
  std::ifstream anytime(dir.path("out") + "/runs/" + sls.id + ".anytime.csv");
  std::string header, row;
  ASSERT_TRUE(std::getline(anytime, header));
  EXPECT_EQ(header, "seconds,evaluations,cost,hard");
  EXPECT_TRUE(std::getline(anytime, row));
  // The assignment beside it, a queen per row.
  std::ifstream solution(dir.path("out") + "/runs/" + sls.id + ".solution.csv");
  ASSERT_TRUE(std::getline(solution, header));
  EXPECT_EQ(header, "variable,value");
  int rows = 0;
  while (std::getline(solution, row)) ++rows;
  EXPECT_EQ(rows, 20);
}

// A problem file's labelled values go into runs/<id>.solution.csv as their labels, the way
// `solve --format json` writes them; unlabelled ones as numbers.
TEST(SuiteRunner, TheSolutionFileWritesLabelledValuesAsTheirLabels) {
  ScratchDir dir("runner-labels");
  dir.write("slots.yaml", R"(name: slots
variables:
  - {names: [s0, s1], labels: [Mon_am, Mon_pm, "Tue, am"]}
  - {name: n, int: [2, 4]}
constraints:
  - {kind: equals, scope: [s0], value: 1}
  - {kind: equals, scope: [s1], value: 2}
  - {kind: equals, scope: [n], value: 3}
)");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: labels
problems:
  instances: [{problem: slots.yaml}]
  solvers: [bnb]
)"));
  const SuiteOutcome outcome = run_suite(suite, options_for(dir.path("out")));
  ASSERT_EQ(outcome.results.size(), 1u);
  EXPECT_EQ(read_text(dir.path("out") + "/runs/" + outcome.results[0].id + ".solution.csv"),
            "variable,value\ns0,Mon_pm\ns1,\"Tue, am\"\nn,3\n");
}

// A toy suite repeated over seeds with two solvers: stats.csv beside results.csv holds each
// (problem, solver)'s repetitions and each solver's PAR-2, and the summary shows both.
TEST(SuiteRunner, WritesStatisticsOfRepetitionsOverSeeds) {
  ScratchDir dir("runner-stats");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: repeated
problems:
  instances: [{nqueens: [6]}]
  solvers: [sls, bnb]
  seeds: [1, 2, 3]
)"));
  const SuiteOutcome outcome = run_suite(suite, options_for(dir.path("out")));
  ASSERT_EQ(outcome.results.size(), 6u);
  const std::string label = outcome.results.front().subject;
  const std::string csv = read_text(dir.path("out") + "/stats.csv");
  EXPECT_EQ(csv.rfind("kind,subject,solver,profile,metric,statistic,value\n", 0), 0u) << csv;
  for (const std::string solver : {"sls", "bnb"}) {
    EXPECT_NE(csv.find("toy," + label + "," + solver + ",-,cost,n,3\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("toy,*," + solver + ",-,time_s,par2_s,"), std::string::npos) << csv;
  }
  // bnb proves 6-queens feasible every time: cost 0 with a zero-width interval.
  EXPECT_NE(csv.find("toy," + label + ",bnb,-,cost,median,0\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("toy," + label + ",bnb,-,cost,mean_ci_high,0\n"), std::string::npos) << csv;
  const std::string summary = read_text(dir.path("out") + "/summary.md");
  EXPECT_NE(summary.find("### Repetitions over seeds"), std::string::npos) << summary;
  EXPECT_NE(summary.find("### PAR-2"), std::string::npos) << summary;
}

TEST(SuiteReport, IsSelfContainedWithPicturesOfEveryScene) {
  ScratchDir dir("runner-report");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTinySuite));
  const SuiteOutcome outcome = run_suite(suite, options_for(dir.path("out")));
  // Without the 3D replay: no script at all, no external reference.
  ReportOptions still;
  still.replay = false;
  write_report(suite, outcome, dir.path("out"), still);
  const std::string stills = read_text(dir.path("out/report.html"));
  EXPECT_EQ(stills.find("http:"), std::string::npos);
  EXPECT_EQ(stills.find("https:"), std::string::npos);
  EXPECT_EQ(stills.find("<link"), std::string::npos);
  EXPECT_EQ(stills.find("<script"), std::string::npos);
  // With it (the default): scripts inline only (three.js's own text names URLs, such as
  // XML namespaces, which are not references), one replay section per scene with its runs.
  write_report(suite, outcome, dir.path("out"));
  const std::string html = read_text(dir.path("out/report.html"));
  EXPECT_EQ(html.find("<link"), std::string::npos);
  for (std::size_t at = html.find(" src="); at != std::string::npos; at = html.find(" src=", at + 1)) {
    EXPECT_EQ(html.compare(at, 11, " src='data:"), 0) << html.substr(at, 40);  // pictures only
  }
  EXPECT_FALSE(fs::exists(dir.path("out/report-assets")));
  for (const char* scene : {"room", "wall"}) {
    const std::size_t at = html.find(std::string("<section class='replay' data-scene='") + scene + "'");
    ASSERT_NE(at, std::string::npos) << scene;
    const std::size_t runs = html.find("data-runs='", at) + 11;
    const std::string ids = html.substr(runs, html.find('\'', runs) - runs);
    EXPECT_EQ(std::count(ids.begin(), ids.end(), ' '), 1) << ids;  // two runs
  }
  EXPECT_NE(html.find("data:image/png;base64,iVBORw0KGgo"), std::string::npos);  // PNG magic
  // Each scene: a top and a side view per run (2 runs), three plots.
  for (const char* scene : {"room", "wall"}) {
    EXPECT_NE(html.find(std::string("Scene <code>") + scene), std::string::npos) << scene;
  }
  std::size_t top_views = 0, pos = 0;
  while ((pos = html.find("top view (", pos)) != std::string::npos) ++top_views, ++pos;
  EXPECT_EQ(top_views, 4u);
  EXPECT_NE(html.find("visible fraction of the body"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir.path("out/report.html.tmp")));

  // Without three.js the report is still written, saying why the replay is left out.
  ReportOptions no_three;
  no_three.three_dir = dir.path("no-three");
  const std::string without = report_html(suite, outcome, dir.path("out"), no_three);
  EXPECT_NE(without.find("3D replay left out"), std::string::npos);
  EXPECT_NE(without.find("libjs-three"), std::string::npos);
  EXPECT_EQ(without.find("<section class='replay'"), std::string::npos);
  EXPECT_NE(without.find("top view ("), std::string::npos);
}

TEST(SuiteReport, ReplayAssetsBesideGoToReportAssets) {
  ScratchDir dir("runner-report-beside");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTinySuite));
  const SuiteOutcome outcome = run_suite(suite, options_for(dir.path("out")));
  ReportOptions beside;
  beside.replay_assets = ReportOptions::ReplayAssets::kBeside;
  write_report(suite, outcome, dir.path("out"), beside);
  const std::string html = read_text(dir.path("out/report.html"));
  EXPECT_NE(html.find("src='report-assets/three.js'"), std::string::npos);
  EXPECT_EQ(html.find("class='replay-data'"), std::string::npos);
  for (const char* scene : {"room", "wall"}) {
    const std::string file = std::string("report-assets/replay-") + scene + ".js";
    EXPECT_NE(html.find("data-src='" + file + "'"), std::string::npos) << scene;
    EXPECT_TRUE(fs::exists(dir.path("out/" + file))) << file;
  }
  EXPECT_TRUE(fs::exists(dir.path("out/report-assets/three.js")));
}

}  // namespace
}  // namespace sightline::experiments
