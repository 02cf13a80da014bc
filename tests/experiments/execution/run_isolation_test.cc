// Isolated runs (experiments/execution/run_isolation.h, isolated_run.h), run limits in suite files, the
// output folder's manifest (output_manifest.h) and provenance: a run that crashes, hangs or
// blows its memory loses only itself and is recorded with its status; isolated and
// in-process runs give the same results; a folder of another suite is refused.
//
// The misbehaving runs are real runs of the real program (SIGHTLINE_BINARY) made to
// misbehave by its documented test hook, SIGHTLINE_TEST_FAULT (run_isolation.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <climits>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "sightline/csp/kinds/not_equal.h"
#include "sightline/domains/nqueens/nqueens.h"
#include "sightline/experiments/execution/isolated_run.h"
#include "sightline/experiments/execution/output_manifest.h"
#include "sightline/experiments/execution/suite_runner.h"
#include "tests/experiments/comparable_results.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;
using testing::read_text;
using testing::without_timing;
namespace fs = std::filesystem;

// Sets SIGHTLINE_TEST_FAULT for the children this test starts, and clears it after.
class TestFault {
 public:
  explicit TestFault(const std::string& spec) { ::setenv("SIGHTLINE_TEST_FAULT", spec.c_str(), 1); }
  ~TestFault() { ::unsetenv("SIGHTLINE_TEST_FAULT"); }
};

RunnerOptions isolated_options(const std::string& out) {
  RunnerOptions o;
  o.out_dir = out;
  o.jobs = 2;
  o.progress = false;
  o.isolation.isolated = true;
  o.isolation.program = SIGHTLINE_BINARY;
  return o;
}

std::map<std::string, RunResult> by_subject_and_solver(const SuiteOutcome& outcome) {
  std::map<std::string, RunResult> out;
  for (const RunResult& r : outcome.results) out[r.subject + " " + r.solver] = r;
  return out;
}

// --- run_child on plain programs ---

TEST(RunChild, NamesHowAProgramEnded) {
  ScratchDir dir("run-child");
  const std::string log = dir.path("child.log");
  ChildOutcome exited = run_child({"/bin/sh", "-c", "echo hello; exit 3"}, log, {});
  EXPECT_EQ(exited.how, "exited");
  EXPECT_EQ(exited.exit_code, 3);
  EXPECT_EQ(read_text(log), "hello\n");

  ChildOutcome crashed = run_child({"/bin/sh", "-c", "kill -SEGV $$"}, log, {});
  EXPECT_EQ(crashed.how, "crash");
  EXPECT_EQ(crashed.signal, SIGSEGV);

  RunLimits wall;
  wall.wall_seconds = 0.3;
  // The shell and the sleep it started are one process group: both go at the limit.
  const std::string pid_file = dir.path("sleep.pid");
  ChildOutcome slow =
      run_child({"/bin/sh", "-c", "sleep 30 & echo $! > '" + pid_file + "'; wait"}, log, wall);
  EXPECT_EQ(slow.how, "timeout");
  EXPECT_LT(slow.wall_seconds, 10);
  const std::string sleeper = read_text(pid_file).substr(0, read_text(pid_file).find('\n'));
  ASSERT_FALSE(sleeper.empty());
  // Gone, or a zombie waiting for whoever adopted it to reap it: not sleeping on.
  auto alive = [&] {
    std::ifstream stat("/proc/" + sleeper + "/stat");
    std::string pid, name, state;
    return stat >> pid >> name >> state && state != "Z";
  };
  for (int i = 0; i < 100 && alive(); ++i) ::usleep(10000);
  EXPECT_FALSE(alive()) << "the grandchild " << sleeper << " outlived the timeout";

  ChildOutcome memout =
      run_child({"/bin/sh", "-c", "exit " + std::to_string(kExitMemout)}, log, {});
  EXPECT_EQ(memout.how, "memout");

  ChildOutcome missing = run_child({"/no/such/program"}, log, {});
  EXPECT_EQ(missing.how, "spawn-failed");
}

TEST(RunChild, LeavesMpiVariablesOutOfTheChildsEnvironment) {
  ScratchDir dir("run-child-env");
  ::setenv("OMPI_COMM_WORLD_RANK", "2", 1);
  ::setenv("PMIX_RANK", "2", 1);
  ::setenv("SIGHTLINE_KEPT", "yes", 1);
  run_child({"/usr/bin/env"}, dir.path("env.log"), {});
  ::unsetenv("OMPI_COMM_WORLD_RANK");
  ::unsetenv("PMIX_RANK");
  ::unsetenv("SIGHTLINE_KEPT");
  const std::string env = read_text(dir.path("env.log"));
  EXPECT_NE(env.find("SIGHTLINE_KEPT=yes"), std::string::npos) << env;
  EXPECT_EQ(env.find("OMPI_COMM_WORLD_RANK"), std::string::npos) << env;
  EXPECT_EQ(env.find("PMIX_RANK"), std::string::npos) << env;
}

const char* kFaultSuite = R"(name: faults
problems:
  instances: [{nqueens: [6, 8, 10]}]
  solvers: [sls, bnb]
limits: {wall_seconds: 4, memory_mb: 512}
)";

TEST(RunIsolation, ACrashAHangAndAMemoryBlowUpEachLoseOnlyTheirRun) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "under AddressSanitizer a child cannot start under RLIMIT_AS (its shadow "
                  "memory needs terabytes of address space) and reports a segfault as an abort";
#endif
  ScratchDir dir("isolation-faults");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kFaultSuite));
  const TestFault fault("crash:6-queens__sls,hang:8-queens__bnb,memory:10-queens__sls");
  const SuiteOutcome outcome = run_suite(suite, isolated_options(dir.path("out")));
  ASSERT_EQ(outcome.results.size(), 6u);
  auto runs = by_subject_and_solver(outcome);
  EXPECT_EQ(runs["6-queens sls"].status, "crash") << runs["6-queens sls"].note;
  EXPECT_NE(runs["6-queens sls"].note.find("signal 11"), std::string::npos);
  EXPECT_EQ(runs["8-queens bnb"].status, "timeout") << runs["8-queens bnb"].note;
  EXPECT_NE(runs["8-queens bnb"].note.find("wall time limit of 4 s"), std::string::npos);
  EXPECT_EQ(runs["10-queens sls"].status, "memout") << runs["10-queens sls"].note;
  EXPECT_NE(runs["10-queens sls"].note.find("512 MB"), std::string::npos);
  // The other three finished with their answers.
  for (const char* name : {"6-queens bnb", "8-queens sls", "10-queens bnb"}) {
    EXPECT_EQ(runs[name].status, "ok") << name << ": " << runs[name].note;
    EXPECT_EQ(metric_text(metric_columns(suite), runs[name], "feasible"), "1") << name;
  }
  EXPECT_EQ(outcome.not_ok, 3u);
  EXPECT_EQ(outcome.failed, 0u);
  // Every run has its result file; what a killed run half-wrote is gone.
  for (const SuiteRun& run : expand_runs(suite)) {
    RunResult r;
    EXPECT_TRUE(read_run_file(run_file_base(dir.path("out"), run.id) + ".result", r)) << run.id;
    EXPECT_FALSE(fs::exists(run_file_base(dir.path("out"), run.id) + ".result.tmp"));
  }
  // A second invocation keeps them: a timeout is a result, not an unfinished run.
  const SuiteOutcome again = run_suite(suite, isolated_options(dir.path("out")));
  EXPECT_EQ(again.ran, 0u);
  EXPECT_EQ(by_subject_and_solver(again)["8-queens bnb"].status, "timeout");
}

TEST(RunIsolation, ARunPastItsCpuLimitIsATimeout) {
  ScratchDir dir("isolation-cpu");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: cpu
problems:
  instances: [{nqueens: [6]}]
  solvers: [bnb, {solver: sls, limits: {cpu_seconds: 1, wall_seconds: 60}}]
)"));
  EXPECT_FALSE(suite.toy_solvers[0].limits.any());
  EXPECT_EQ(suite.toy_solvers[1].limits.cpu_seconds, 1);
  const TestFault fault("spin:6-queens__sls");
  const SuiteOutcome outcome = run_suite(suite, isolated_options(dir.path("out")));
  auto runs = by_subject_and_solver(outcome);
  EXPECT_EQ(runs["6-queens sls"].status, "timeout") << runs["6-queens sls"].note;
  EXPECT_NE(runs["6-queens sls"].note.find("CPU time limit of 1 s"), std::string::npos)
      << runs["6-queens sls"].note;
  EXPECT_EQ(runs["6-queens bnb"].status, "ok");
  // What the kernel counted: the spinning run used about its second of CPU, the other
  // little. Not >= 1: the kernel checks RLIMIT_CPU on its own sampled clock, and on a
  // contended machine wait4's rusage for the same child has read 0.88-0.96 s (5 of 6 runs
  // with 5 builds beside it; 1.0x s when idle).
  EXPECT_GE(std::stod(runs["6-queens sls"].run_cpu_s), 0.7);
  EXPECT_LT(std::stod(runs["6-queens bnb"].run_cpu_s), 0.9);
  EXPECT_GT(std::stod(runs["6-queens bnb"].run_max_rss_mb), 1);
  EXPECT_GT(std::stod(runs["6-queens bnb"].run_wall_s), 0);
}

// 2 scenes x 2 camera solvers, plus 2 toy problems x 2 solvers.
const char* kTinySuite = R"(name: tiny
camera:
  scenes: [scenes/*.yaml]
  solvers:
    - occlusion-octree
    - {label: bourne-published, solver: bourne-octree, controller: {visibility_guard: false},
       area_adaptation: false}
problems:
  instances: [{nqueens: [6, 8]}, {graph: graph.col, colours: 3}]
  solvers: [sls, bnb]
)";

TEST(RunIsolation, IsolatedAndInProcessRunsWriteTheSameResults) {
  ScratchDir dir("isolation-same");
  dir.write("graph.col", "p edge 4 5\ne 1 2\ne 2 3\ne 3 4\ne 4 1\ne 1 3\n");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTinySuite));
  RunnerOptions in_process = isolated_options(dir.path("here"));
  in_process.isolation.isolated = false;
  const SuiteOutcome here = run_suite(suite, in_process);
  const SuiteOutcome there = run_suite(suite, isolated_options(dir.path("child")));
  ASSERT_EQ(here.results.size(), 10u);
  ASSERT_EQ(there.results.size(), 10u);
  for (const RunResult& r : there.results) {
    EXPECT_EQ(r.status, "ok") << r.id << ": " << r.note;
    EXPECT_FALSE(r.run_cpu_s.empty()) << r.id;  // measured for isolated runs only
  }
  for (const RunResult& r : here.results) EXPECT_TRUE(r.run_cpu_s.empty()) << r.id;
  const std::string a = read_text(dir.path("here/results.csv"));
  const std::string b = read_text(dir.path("child/results.csv"));
  EXPECT_EQ(without_timing(suite, a), without_timing(suite, b));
  // The same traces, byte for byte apart from solve_us (FORMATS.md: column 15).
  auto without_solve_us = [](const std::string& trace) {
    std::istringstream in(trace);
    std::string line, out;
    while (std::getline(in, line)) {
      std::size_t start = 0;
      for (int i = 0; i < 14; ++i) start = line.find(',', start) + 1;
      out += line.substr(0, start) + line.substr(line.find(',', start)) + "\n";
    }
    return out;
  };
  for (const SuiteRun& run : expand_runs(suite)) {
    if (run.kind != SuiteRun::Kind::kCamera) continue;
    const std::string here_trace =
        without_solve_us(read_text(run_file_base(dir.path("here"), run.id) + ".trace.csv"));
    EXPECT_GT(here_trace.size(), 1000u);
    EXPECT_TRUE(here_trace == without_solve_us(read_text(run_file_base(dir.path("child"), run.id) +
                                                         ".trace.csv")))
        << run.id;
  }
}

TEST(RunIsolation, ARunWhoseSuiteFileChangedUnderItFailsWithoutRunningSomethingElse) {
  ScratchDir dir("isolation-changed");
  const std::string path = dir.write("suite.yaml", R"(name: c
problems:
  instances: [{nqueens: [6]}]
  solvers: [bnb]
)");
  const Suite suite = read_suite_file(path);
  const SuiteRun run = expand_runs(suite).at(0);
  fs::create_directories(dir.path("out/runs"));
  IsolationOptions isolation;
  isolation.program = SIGHTLINE_BINARY;
  EXPECT_EQ(run_and_record(suite, run, dir.path("out"), isolation).status, "ok");
  // The file now says 7-queens: the child finds no run with that id and says so.
  dir.write("suite.yaml", "name: c\nproblems:\n  instances: [{nqueens: [7]}]\n  solvers: [bnb]\n");
  const RunResult r = run_and_record(suite, run, dir.path("out"), isolation);
  EXPECT_EQ(r.status, "failed");
  EXPECT_NE(r.note.find("suite file changed"), std::string::npos) << r.note;
  RunResult stored;
  ASSERT_TRUE(read_run_file(run_file_base(dir.path("out"), run.id) + ".result", stored));
  EXPECT_EQ(stored.status, "failed");
}

TEST(RunIsolation, ASuiteWithLimitsRefusesToRunInProcess) {
  ScratchDir dir("isolation-refuse");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kFaultSuite));
  RunnerOptions o = isolated_options(dir.path("out"));
  o.isolation.isolated = false;
  EXPECT_THROW(run_suite(suite, o), std::runtime_error);
}

TEST(RunIsolation, ResultsNameTheirHostCpuBuildAndCommandLine) {
  ScratchDir dir("isolation-provenance");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: p
problems:
  instances: [{nqueens: [5]}]
  solvers: [bnb]
)"));
  const SuiteOutcome outcome = run_suite(suite, isolated_options(dir.path("out")));
  ASSERT_EQ(outcome.results.size(), 1u);
  const Provenance& p = outcome.results[0].provenance;
  char host[HOST_NAME_MAX + 1] = {};
  ::gethostname(host, sizeof host - 1);
  EXPECT_EQ(p.host, host);
  EXPECT_FALSE(p.cpu_model.empty());
  EXPECT_FALSE(p.build_commit.empty());
  // The command that made it is this test program's (the runner's), not the child's.
  EXPECT_EQ(p.command_line, this_process_provenance().command_line);
  EXPECT_EQ(p.command_line.find("run-one"), std::string::npos);
  const std::string csv = read_text(dir.path("out/results.csv"));
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_NE(header.find(",note,host,cpu_model,build_commit,command_line,run_wall_s,run_cpu_s,"
                        "run_max_rss_mb"),
            std::string::npos)
      << header;
  EXPECT_NE(csv.find(p.build_commit), std::string::npos);
  EXPECT_EQ(shell_command_line({"a b", "it's", "plain"}), "'a b' 'it'\\''s' plain");
}

TEST(ToyAnswerCheck, NamesAReportedCostOrFeasibilityThatIsNotTrue) {
  const auto problem = nqueens::build_nqueens(4);
  const csp::Assignment solution = {1, 3, 0, 2};  // rows of the queens, column by column
  const csp::Assignment attacking = {0, 1, 2, 3};
  const csp::Score truth = problem->score(attacking);
  ASSERT_GT(truth.hard, 0);
  EXPECT_EQ(toy_answer_problem(*problem, solution, problem->score(solution), 0), "");
  EXPECT_EQ(toy_answer_problem(*problem, attacking, truth, 6), "");  // honest, infeasible
  // Claims feasible, and a full re-evaluation disagrees.
  EXPECT_NE(toy_answer_problem(*problem, attacking, csp::Score{0, truth.soft}, -1), "");
  // A cost that is not the assignment's.
  EXPECT_NE(toy_answer_problem(*problem, solution, csp::Score{0, 5}, 0), "");
  // The scores agree but the independent judge counts attacking queens.
  EXPECT_NE(toy_answer_problem(*problem, solution, problem->score(solution), 2), "");
  // The wrong number of values.
  EXPECT_NE(toy_answer_problem(*problem, {1, 3}, csp::Score{}, -1), "");

  // A soft model (a colouring as Max-CSP): an honest cost of one conflict that the judge
  // also counts is a right answer; claiming cost 0 for it is not.
  csp::Problem edge("one edge, one colour");
  edge.add_variable("a", csp::Domain::integer_range(0, 0));
  edge.add_variable("b", csp::Domain::integer_range(0, 0));
  edge.add_constraint(std::make_unique<csp::NotEqual>(0, 1));
  const csp::Assignment same = {0, 0};
  const csp::Score conflict = edge.score(same);
  ASSERT_TRUE(conflict.feasible());
  ASSERT_EQ(conflict.soft, 1);
  EXPECT_EQ(toy_answer_problem(edge, same, conflict, 1), "");
  EXPECT_NE(toy_answer_problem(edge, same, csp::Score{0, 0}, 1), "");
}

// --- Limits in the suite file ---

std::string limits_error(const std::string& text) {
  ScratchDir dir("isolation-limits");
  try {
    read_suite_file(dir.write("suite.yaml", text));
  } catch (const csp::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SuiteLimits, LimitsThatMakeNoSenseAreRefusedWithTheirLine) {
  const std::string head = "name: l\nproblems:\n  instances: [{nqueens: [5]}]\n  solvers: [bnb]\n";
  struct Case {
    std::string limits;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"limits: {wall_seconds: 0}", "suite.yaml:5:"},
      {"limits: {wall_seconds: -3}", "wall time limit in seconds > 0"},
      {"limits: {cpu_seconds: .nan}", "CPU time limit"},
      {"limits: {cpu_seconds: soon}", "CPU time limit"},
      {"limits: {memory_mb: 10}", ">= 256"},
      {"limits: {memory_mb: 1.5}", "memory limit in MB"},
      {"limits: {memory: 100}", "memory_mb"},
      {"limits: 60", "expected limits"},
      {"isolation: false\nlimits: {wall_seconds: 5}", "suite.yaml:5:"},
  };
  for (const Case& c : cases) {
    const std::string error = limits_error(head + c.limits + "\n");
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.limits << " -> " << error;
    EXPECT_NE(error.find("suite.yaml:5:"), std::string::npos) << c.limits << " -> " << error;
  }
  // A bad per-solver override names its own line.
  const std::string error = limits_error(
      "name: l\nproblems:\n  instances: [{nqueens: [5]}]\n  solvers:\n"
      "    - bnb\n    - {solver: sls, limits: {wall_seconds: 0}}\n");
  EXPECT_NE(error.find("suite.yaml:6:"), std::string::npos) << error;
  EXPECT_EQ(limits_error(head + "limits: {wall_seconds: 0.5, cpu_seconds: 2, memory_mb: 256}\n"),
            "");
}

TEST(SuiteLimits, LimitsArePartOfARunsDefinitionOnlyWhenSet) {
  ScratchDir dir("isolation-ids");
  const std::string head = "name: l\nproblems:\n  instances: [{nqueens: [5]}]\n  solvers: [bnb]\n";
  const Suite plain = read_suite_file(dir.write("a.yaml", head));
  const Suite limited = read_suite_file(dir.write("b.yaml", head + "limits: {wall_seconds: 9}\n"));
  const SuiteRun a = expand_runs(plain).at(0), b = expand_runs(limited).at(0);
  EXPECT_EQ(a.definition.find("run_limits"), std::string::npos);
  EXPECT_EQ(b.definition, a.definition + ";run_limits=wall=9");
  EXPECT_NE(a.id, b.id);
}

// --- The output folder's manifest ---

const char* kSuiteA =
    "name: alpha\nproblems:\n  instances: [{nqueens: [5, 6]}]\n  solvers: [bnb]\n";
const char* kSuiteB = "name: beta\nproblems:\n  instances: [{nqueens: [5]}]\n  solvers: [bnb]\n";

std::string folder_error(const Suite& suite, const std::string& out) {
  try {
    read_suite_state(suite, out);
  } catch (const OutputFolderError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputManifest, RefusesAFolderHoldingAnotherSuitesResults) {
  ScratchDir dir("manifest-other");
  const Suite a = read_suite_file(dir.write("a.yaml", kSuiteA));
  const Suite b = read_suite_file(dir.write("b.yaml", kSuiteB));
  run_suite(a, isolated_options(dir.path("out")));
  const std::string manifest = read_text(dir.path("out/manifest"));
  EXPECT_NE(manifest.find("suite=alpha\n"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("definition=" + suite_definition_hash(expand_runs(a))),
            std::string::npos);
  const std::string error = folder_error(b, dir.path("out"));
  EXPECT_NE(error.find(dir.path("out")), std::string::npos) << error;
  EXPECT_NE(error.find("'alpha'"), std::string::npos) << error;
  EXPECT_NE(error.find("'beta'"), std::string::npos) << error;
  EXPECT_EQ(read_text(dir.path("out/manifest")), manifest);  // untouched
  // The same suite edited (a size dropped) is still its own folder: nothing is redone.
  const Suite a_less = read_suite_file(dir.write(
      "a2.yaml", "name: alpha\nproblems:\n  instances: [{nqueens: [5]}]\n  solvers: [bnb]\n"));
  EXPECT_EQ(folder_error(a_less, dir.path("out")), "");
  EXPECT_EQ(read_suite_state(a_less, dir.path("out")).reused, 1u);
}

TEST(OutputManifest, AnOlderFolderWithoutAManifestIsAcceptedOnlyIfAllItsRunsBelong) {
  ScratchDir dir("manifest-old");
  const Suite a = read_suite_file(dir.write("a.yaml", kSuiteA));
  const Suite b = read_suite_file(dir.write("b.yaml", kSuiteB));
  run_suite(a, isolated_options(dir.path("old")));
  fs::remove(dir.path("old/manifest"));
  // Beta's only run (5-queens, bnb) is also one of alpha's, but alpha's 6-queens run is not
  // beta's: refused.
  const std::string error = folder_error(b, dir.path("old"));
  EXPECT_NE(error.find("no manifest"), std::string::npos) << error;
  EXPECT_NE(error.find("6-queens"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(dir.path("old/manifest")));
  // Alpha itself takes its old folder back and redoes nothing.
  const SuiteState state = read_suite_state(a, dir.path("old"));
  EXPECT_EQ(state.reused, 2u);
  EXPECT_TRUE(fs::exists(dir.path("old/manifest")));
}

TEST(OutputManifest, RefusesAFolderItCannotCreateOrThatHoldsOtherFiles) {
  ScratchDir dir("manifest-bad");
  const Suite a = read_suite_file(dir.write("a.yaml", kSuiteA));
  // Under a regular file: fails even for root.
  dir.write("plain-file", "x");
  const std::string error = folder_error(a, dir.path("plain-file/out"));
  EXPECT_NE(error.find(dir.path("plain-file/out")), std::string::npos) << error;
  dir.write("notes/todo.txt", "my notes");
  const std::string other = folder_error(a, dir.path("notes"));
  EXPECT_NE(other.find("not empty"), std::string::npos) << other;
  EXPECT_FALSE(fs::exists(dir.path("notes/runs")));
}

}  // namespace
}  // namespace sightline::experiments
