// `mpirun -np 3 sightline run` end to end (experiments/execution/mpi_engine.h, docs/CLUSTER.md): the
// same results.csv as the thread pool apart from timing columns; a job whose rank died,
// submitted again, loses and redoes no finished run; a suite started by the thread pool is
// finished under MPI; an unwritable folder or a run that cannot be recorded stops every
// rank with a clear message and a non-zero exit, without hanging.
//
// Runs as CI does, as root on 2 cores: --oversubscribe and the Open MPI variables for root
// and containers. Skipped only when mpirun is not installed.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/execution/suite_runner.h"
#include "tests/experiments/comparable_results.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;
using testing::kTinySuite;
using testing::read_text;
using testing::without_timing;
namespace fs = std::filesystem;

struct Outcome {
  int status = -1;  // exit status; -1 when killed by a signal
  std::string output;
};

Outcome shell(const std::string& command) {
  Outcome r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe))
    r.output.append(buffer, n);
  const int raw = pclose(pipe);
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  return r;
}

bool mpirun_installed() { return std::system("command -v mpirun >/dev/null 2>&1") == 0; }

// `sightline run SUITE --out OUT --no-report` under mpirun with `ranks` processes. `timeout`
// turns a hang into exit status 124 instead of a stuck test.
Outcome mpi_run(int ranks, const std::string& suite, const std::string& out,
                const std::string& environment = "", const std::string& flags = "") {
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  ::setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
  return shell("env " + environment + " timeout -k 5 60 mpirun --oversubscribe -np " +
               std::to_string(ranks) + " '" SIGHTLINE_BINARY "' run '" + suite + "' --out '" + out +
               "' --no-report " + flags);
}

#define SKIP_WITHOUT_MPI()                                                         \
  do {                                                                             \
    if (!mpirun_installed()) GTEST_SKIP() << "mpirun is not installed";            \
    if (!SIGHTLINE_BUILT_WITH_MPI) GTEST_SKIP() << "this build has no MPI engine"; \
  } while (false)

// What identifies one writing of a result file: its inode (a rename puts a new one in
// place), its modification time in nanoseconds and its text.
struct Written {
  ino_t inode = 0;
  long long mtime_ns = 0;
  std::string text;
  bool operator==(const Written&) const = default;
};

// The finished runs' result files in OUT/runs, by run id.
std::map<std::string, Written> finished_runs(const std::string& out) {
  std::map<std::string, Written> files;
  for (const auto& entry : fs::directory_iterator(fs::path(out) / "runs")) {
    const std::string name = entry.path().filename().string();
    RunResult r;
    if (entry.path().extension() != ".result" || !read_run_file(entry.path().string(), r)) continue;
    struct stat s {};
    ::stat(entry.path().c_str(), &s);
    files[r.id] = {s.st_ino, s.st_mtim.tv_sec * 1000000000LL + s.st_mtim.tv_nsec,
                   read_text(entry.path().string())};
  }
  return files;
}

RunnerOptions local(const std::string& out, std::size_t max_new_runs = 0) {
  RunnerOptions o;
  o.out_dir = out;
  o.jobs = 2;
  o.max_new_runs = max_new_runs;
  o.progress = false;
  return o;
}

TEST(MpiRun, WritesTheSameResultsAsTheThreadPoolApartFromTiming) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-same");
  const std::string suite_file = dir.write("suite.yaml", kTinySuite);
  const Suite suite = read_suite_file(suite_file);
  run_suite(suite, local(dir.path("local")));

  const Outcome r = mpi_run(3, suite_file, dir.path("mpi"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("MPI: 3 ranks; 8 runs, 0 finished before, 8 to run now"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("8 of 8 runs finished (0 from an earlier invocation, 8 now)"),
            std::string::npos)
      << r.output;
  const std::string mpi_csv = read_text(dir.path("mpi/results.csv"));
  EXPECT_EQ(std::count(mpi_csv.begin(), mpi_csv.end(), '\n'), 9);
  EXPECT_EQ(without_timing(suite, mpi_csv),
            without_timing(suite, read_text(dir.path("local/results.csv"))));
  EXPECT_TRUE(fs::exists(dir.path("mpi/summary.md")));
  EXPECT_TRUE(fs::exists(dir.path("mpi/stats.csv")));
  EXPECT_EQ(finished_runs(dir.path("mpi")).size(), 8u);
}

TEST(MpiRun, OneProcessUnderMpirunRunsTheSuiteLocally) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-one");
  const std::string suite_file = dir.write("suite.yaml", R"(name: one
problems:
  instances: [{nqueens: [5, 6]}]
  solvers: [bnb]
)");
  const Outcome r = mpi_run(1, suite_file, dir.path("out"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("MPI:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2 of 2 runs finished"), std::string::npos) << r.output;
}

TEST(MpiRun, HandsOutTheLongestExpectedRunsFirst) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-order");
  // Neither 2 nor 3 queens can be placed, so sls uses its whole 0.1 s on each run; the
  // dispatcher expects the bigger problem to take longer (experiments/execution/run_order.h).
  const std::string suite_file = dir.write("suite.yaml", R"(name: order
problems:
  instances: [{nqueens: [2, 3]}]
  solvers: [sls]
  seeds: [1, 2]
  limits: {time_seconds: 0.1}
)");
  const std::vector<SuiteRun> runs = expand_runs(read_suite_file(suite_file));
  ASSERT_EQ(runs.size(), 4u);
  // One worker records the runs one after another, in the order it was given them.
  const Outcome r = mpi_run(2, suite_file, dir.path("out"));
  ASSERT_EQ(r.status, 0) << r.output;
  std::vector<std::pair<long long, std::string>> by_time;
  for (const auto& [id, written] : finished_runs(dir.path("out"))) {
    by_time.emplace_back(written.mtime_ns, id);
  }
  std::sort(by_time.begin(), by_time.end());
  ASSERT_EQ(by_time.size(), 4u);
  EXPECT_EQ(by_time[0].second, runs[2].id);  // 3-queens, seed 1
  EXPECT_EQ(by_time[1].second, runs[3].id);
  EXPECT_EQ(by_time[2].second, runs[0].id);  // 2-queens, seed 1
  EXPECT_EQ(by_time[3].second, runs[1].id);
}

// 24 runs of about 0.15 s each: 3-queens has no solution, so sls searches until its limit.
// (Open MPI takes about a second to bring a job down after a rank died: with 16 runs the
// surviving worker got through 8 more meanwhile.)
const char* kSlowSuite = R"(name: slow
problems:
  instances: [{nqueens: [3]}]
  solvers: [sls]
  seeds: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23,
          24]
  limits: {time_seconds: 0.15}
)";

constexpr std::size_t kSlowRuns = 24;

TEST(MpiRun, AJobSubmittedAgainAfterARankDiedLosesAndRedoesNoFinishedRun) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-died");
  const std::string suite_file = dir.write("suite.yaml", kSlowSuite);
  const std::string out = dir.path("out");

  // Rank 1 dies (abort) right after recording its second run; Open MPI takes the job down.
  const Outcome died = mpi_run(3, suite_file, out, "SIGHTLINE_TEST_ABORT_AFTER_RUNS=1:2");
  EXPECT_NE(died.status, 0) << died.output;
  EXPECT_NE(died.status, 124) << "the job hung instead of ending: " << died.output;
  const std::map<std::string, Written> before = finished_runs(out);
  ASSERT_GE(before.size(), 2u) << died.output;  // at least rank 1's two recorded runs
  ASSERT_LT(before.size(), kSlowRuns) << "the job was not cut short: " << died.output;
  EXPECT_FALSE(fs::exists(fs::path(out) / "results.csv"));

  // The same command again: only the unfinished runs are done.
  const Outcome again = mpi_run(3, suite_file, out);
  ASSERT_EQ(again.status, 0) << again.output;
  const std::size_t n = before.size();
  EXPECT_NE(
      again.output.find(std::to_string(kSlowRuns) + " of " + std::to_string(kSlowRuns) +
                        " runs finished (" + std::to_string(n) + " from an earlier invocation, " +
                        std::to_string(kSlowRuns - n) + " now)"),
      std::string::npos)
      << again.output;
  const std::map<std::string, Written> after = finished_runs(out);
  EXPECT_EQ(after.size(), kSlowRuns);
  for (const auto& [id, written] : before) {
    ASSERT_TRUE(after.count(id)) << id;
    EXPECT_EQ(after.at(id), written) << id << " was written again";
  }
  // Every run once in results.csv, and no half-written file left behind.
  const std::string csv = read_text(out + "/results.csv");
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header
  std::multiset<std::string> ids;
  while (std::getline(lines, line)) ids.insert(line.substr(0, line.find(',')));
  EXPECT_EQ(ids.size(), kSlowRuns);
  for (const auto& [id, written] : after) EXPECT_EQ(ids.count(id), 1u) << id;
  for (const auto& entry : fs::directory_iterator(fs::path(out) / "runs")) {
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
  }
}

TEST(MpiRun, FinishesASuiteStartedByTheThreadPool) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-resume");
  const std::string suite_file = dir.write("suite.yaml", kTinySuite);
  const Suite suite = read_suite_file(suite_file);
  // Started locally and interrupted after 3 runs.
  const SuiteOutcome first = run_suite(suite, local(dir.path("out"), 3));
  ASSERT_EQ(first.ran, 3u);
  const std::map<std::string, Written> before = finished_runs(dir.path("out"));
  ASSERT_EQ(before.size(), 3u);

  const Outcome r = mpi_run(3, suite_file, dir.path("out"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("8 of 8 runs finished (3 from an earlier invocation, 5 now)"),
            std::string::npos)
      << r.output;
  const std::map<std::string, Written> after = finished_runs(dir.path("out"));
  EXPECT_EQ(after.size(), 8u);
  for (const auto& [id, written] : before) EXPECT_EQ(after.at(id), written) << id;

  run_suite(suite, local(dir.path("fresh")));
  EXPECT_EQ(without_timing(suite, read_text(dir.path("out/results.csv"))),
            without_timing(suite, read_text(dir.path("fresh/results.csv"))));
}

TEST(MpiRun, RefusesAFolderHoldingAnotherSuitesRunsAndKeepsThem) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-foreign");
  const std::string slow_file = dir.write("slow.yaml", kSlowSuite);
  const std::string tiny_file = dir.write("suite.yaml", kTinySuite);
  // The tiny suite's folder, finished locally.
  run_suite(read_suite_file(tiny_file), local(dir.path("out")));
  const std::map<std::string, Written> before = finished_runs(dir.path("out"));
  ASSERT_EQ(before.size(), 8u);
  // Another suite into it under MPI: refused by rank 0 with both suites named, every rank
  // exits, nothing of the folder is touched.
  const Outcome r = mpi_run(3, slow_file, dir.path("out"));
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.status, 124) << "the job hung: " << r.output;
  EXPECT_NE(r.output.find("'tiny'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'slow'"), std::string::npos) << r.output;
  EXPECT_EQ(finished_runs(dir.path("out")), before);
}

TEST(MpiRun, RefusesAnUnwritableFolderOnceAndEveryRankExits) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-unwritable");
  const std::string suite_file = dir.write("suite.yaml", kSlowSuite);
  // A plain file where the folder should be: unwritable even for root.
  const std::string blocker = dir.write("blocker", "not a folder\n");
  const Outcome r = mpi_run(3, suite_file, blocker + "/out");
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.status, 124) << "the job hung: " << r.output;
  EXPECT_NE(r.output.find("sightline: cannot use '" + blocker +
                          "/out' as the output folder: Not a directory"),
            std::string::npos)
      << r.output;
  // Said by rank 0 alone.
  std::size_t said = 0;
  for (std::size_t at = r.output.find("sightline: "); at != std::string::npos;
       at = r.output.find("sightline: ", at + 1)) {
    ++said;
  }
  EXPECT_EQ(said, 1u) << r.output;
}

TEST(MpiRun, StopsEveryRankWhenARunCannotBeRecorded) {
  SKIP_WITHOUT_MPI();
  ScratchDir dir("mpi-unrecordable");
  const std::string suite_file = dir.write("suite.yaml", kSlowSuite);
  const std::vector<SuiteRun> runs = expand_runs(read_suite_file(suite_file));
  // A folder where run 5's temporary result file goes: it cannot be written (even by root).
  // In process, the rank that cannot record is the one to notice, and it stops the job. (An
  // isolated run's child that cannot write is a failed run, recorded by its parent.)
  fs::create_directories(dir.path("out/runs/" + runs[5].id + ".result.tmp"));
  const Outcome r = mpi_run(3, suite_file, dir.path("out"), "", "--in-process");
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.status, 124) << "the job hung: " << r.output;
  EXPECT_NE(r.output.find("run " + runs[5].id + ": cannot write"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path("out/results.csv")));
  // No runs were handed out after the failure: fewer than all finished.
  EXPECT_LT(finished_runs(dir.path("out")).size(), runs.size() - 1);
}

TEST(MpiRun, ABuildWithoutMpiSaysSoUnderMpirun) {
  if (!mpirun_installed()) GTEST_SKIP() << "mpirun is not installed";
  if (SIGHTLINE_BUILT_WITH_MPI) GTEST_SKIP() << "this build has MPI (checked in a build without)";
  ScratchDir dir("mpi-none");
  const std::string suite_file = dir.write("suite.yaml", kSlowSuite);
  const Outcome r = mpi_run(2, suite_file, dir.path("out"));
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("built without MPI"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path("out/results.csv")));
}

}  // namespace
}  // namespace sightline::experiments
