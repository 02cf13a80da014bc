// `sightline run` end to end with isolated runs: the real program starts its own run-one
// children, records a crash, a hang and a memory blow-up with their statuses while the rest
// of the suite finishes, gives the same results as --in-process, and refuses output folders
// it may not use and limits that make no sense, with clear messages and non-zero exits.
// The misbehaving runs use the program's documented test hook SIGHTLINE_TEST_FAULT.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "run_sightline.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::test {
namespace {

using experiments::testing::read_text;
using experiments::testing::ScratchDir;

// results.csv as rows of column -> value (no quoted commas in these suites).
std::vector<std::map<std::string, std::string>> read_rows(const std::string& path) {
  std::istringstream in(read_text(path));
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    if (header.empty()) {
      header = fields;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) row[header[i]] = fields[i];
    rows.push_back(row);
  }
  return rows;
}

const char* kSuite = R"(name: cli-faults
problems:
  instances: [{nqueens: [6, 8, 10]}]
  solvers: [sls, bnb]
limits: {wall_seconds: 4, memory_mb: 512}
)";

TEST(RunCommand, RecordsACrashAHangAndAMemoryBlowUpWhileTheRestFinish) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "under AddressSanitizer a child cannot start under RLIMIT_AS (its shadow "
                  "memory needs terabytes of address space) and reports a segfault as an abort";
#endif
  ScratchDir dir("cli-faults");
  const std::string suite = dir.write("suite.yaml", kSuite);
  ::setenv("SIGHTLINE_TEST_FAULT", "crash:6-queens__sls,hang:8-queens__bnb,memory:10-queens__sls",
           1);
  const Outcome run = test::run("run '" + suite + "' --out '" + dir.path("out") + "' --no-report");
  ::unsetenv("SIGHTLINE_TEST_FAULT");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(contains(run.output, "3 run(s) ended in timeout, memout, crash or wrong"))
      << run.output;
  std::map<std::string, std::string> status;
  for (const auto& row : read_rows(dir.path("out/results.csv"))) {
    status[row.at("problem") + " " + row.at("solver")] = row.at("status");
  }
  ASSERT_EQ(status.size(), 6u);
  EXPECT_EQ(status["6-queens sls"], "crash");
  EXPECT_EQ(status["8-queens bnb"], "timeout");
  EXPECT_EQ(status["10-queens sls"], "memout");
  EXPECT_EQ(status["6-queens bnb"], "ok");
  EXPECT_EQ(status["8-queens sls"], "ok");
  EXPECT_EQ(status["10-queens bnb"], "ok");
}

// Columns that describe the machine or the invocation, not the run.
bool varies(const std::string& column) {
  static const std::set<std::string> names = {"solve_us_p50", "solve_us_p99", "solve_us_max",
                                              "time_s",       "time_to_best_s", "host",       "cpu_model",
                                              "build_commit", "command_line", "run_wall_s",
                                              "run_cpu_s",    "run_max_rss_mb"};
  return names.count(column) > 0;
}

TEST(RunCommand, IsolatedAndInProcessRunsGiveTheSameResults) {
  ScratchDir dir("cli-same");
  const std::string suite = dir.write("suite.yaml", R"(name: same
camera:
  scenes: [scenes/*.yaml]
  solvers: [occlusion-octree, spring-arm]
problems:
  instances: [{nqueens: [6, 8]}]
  solvers: [sls, bnb]
)");
  const Outcome isolated =
      test::run("run '" + suite + "' --out '" + dir.path("iso") + "' --no-report");
  ASSERT_EQ(isolated.status, 0) << isolated.output;
  const Outcome here =
      test::run("run '" + suite + "' --out '" + dir.path("here") + "' --no-report --in-process");
  ASSERT_EQ(here.status, 0) << here.output;
  auto a = read_rows(dir.path("iso/results.csv"));
  auto b = read_rows(dir.path("here/results.csv"));
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].at("status"), "ok") << a[i].at("id");
    EXPECT_FALSE(a[i].at("build_commit").empty());
    for (const auto& [column, value] : a[i]) {
      if (!varies(column)) {
        EXPECT_EQ(value, b[i][column]) << a[i].at("id") << " " << column;
      }
    }
  }
}

TEST(RunCommand, RefusesAFolderHoldingAnotherSuitesResults) {
  ScratchDir dir("cli-manifest");
  const std::string first = dir.write("first.yaml",
                                      "name: first\nproblems:\n"
                                      "  instances: [{nqueens: [5]}]\n  solvers: [bnb]\n");
  const std::string second = dir.write("second.yaml",
                                       "name: second\nproblems:\n"
                                       "  instances: [{nqueens: [6]}]\n  solvers: [bnb]\n");
  const std::string out = dir.path("out");
  ASSERT_EQ(test::run("run '" + first + "' --out '" + out + "' --no-report").status, 0);
  const Outcome refused = test::run("run '" + second + "' --out '" + out + "' --no-report");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "output folder '" + out + "'")) << refused.output;
  EXPECT_TRUE(contains(refused.output, "suite 'first'")) << refused.output;
  EXPECT_TRUE(contains(refused.output, "suite 'second'")) << refused.output;
  EXPECT_FALSE(contains(read_text(out + "/results.csv"), "6-queens"));
}

TEST(RunCommand, RefusesAnOutputFolderItCannotCreate) {
  ScratchDir dir("cli-unwritable");
  const std::string suite = dir.write("suite.yaml",
                                      "name: s\nproblems:\n"
                                      "  instances: [{nqueens: [5]}]\n  solvers: [bnb]\n");
  dir.write("a-file", "not a folder");
  // Under a regular file no folder can be made, even by root.
  const std::string out = dir.path("a-file/out");
  const Outcome refused = test::run("run '" + suite + "' --out '" + out + "'");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "cannot use '" + out + "' as the output folder"))
      << refused.output;
}

TEST(RunCommand, NamesTheLineOfLimitsThatMakeNoSense) {
  ScratchDir dir("cli-limits");
  const std::string head = "name: s\nproblems:\n  instances: [{nqueens: [5]}]\n  solvers: [bnb]\n";
  for (const std::string limits : {"limits: {wall_seconds: -1}", "limits: {cpu_seconds: .nan}",
                                   "limits: {memory_mb: 1}", "limits: {wall_seconds: ten}"}) {
    const std::string suite = dir.write("suite.yaml", head + limits + "\n");
    const Outcome refused = test::run("run '" + suite + "' --out '" + dir.path("out") + "'");
    EXPECT_EQ(refused.status, 2) << limits << ": " << refused.output;
    EXPECT_TRUE(contains(refused.output, "suite.yaml:5:")) << limits << ": " << refused.output;
  }
  // Limits with --in-process: only a child process can be held to them.
  const std::string suite = dir.write("suite.yaml", head + "limits: {wall_seconds: 5}\n");
  const Outcome refused =
      test::run("run '" + suite + "' --out '" + dir.path("out2") + "' --in-process");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "only isolated runs")) << refused.output;
}

}  // namespace
}  // namespace sightline::test
