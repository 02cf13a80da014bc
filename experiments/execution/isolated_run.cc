#include "sightline/experiments/execution/isolated_run.h"

#include "sightline/experiments/execution/interruption.h"
#include "sightline/experiments/execution/suite_runner.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sightline/experiments/suite/provenance.h"

namespace sightline::experiments {
namespace {

namespace fs = std::filesystem;

std::string number_text(double v, int digits = 17) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

std::string combination_text(const SuiteRun& run) {
  return std::string(run.kind == SuiteRun::Kind::kCamera ? "camera" : "toy") + "/" +
         std::to_string(run.subject) + "/" + std::to_string(run.solver) + "/" +
         std::to_string(run.profile) + "/" + std::to_string(run.seed);
}

// The last non-empty line of the child's log ("" when none), for the result's note.
std::string last_log_line(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  if (last.size() > 300) last = last.substr(0, 300) + "...";
  return last;
}

void remove_quietly(const std::string& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

}  // namespace

RunResult run_isolated(const Suite& suite, const SuiteRun& run, const std::string& out_dir,
                       const std::string& program) {
  if (suite.path.empty()) {
    throw std::runtime_error("suite '" + suite.name +
                             "' was not read from a file, so a child process cannot read it: "
                             "run it in-process");
  }
  const RunLimits& limits = run_limits(suite, run);
  const std::string base = run_file_base(out_dir, run.id);
  const std::string result_path = base + ".result";
  const std::string log_path = base + ".log";
  remove_quietly(result_path);  // a stale file must never stand in for this run's result

  std::vector<std::string> argv = {program, "run-one",       suite.path,
                                   "--out", out_dir,         "--run",
                                   run.id,  "--combination", combination_text(run)};
  if (limits.wall_seconds > 0) {  // enforced here; the child only knows it
    argv.insert(argv.end(), {"--wall-seconds", number_text(limits.wall_seconds)});
  }
  if (limits.cpu_seconds > 0) {
    argv.insert(argv.end(), {"--cpu-seconds", number_text(limits.cpu_seconds)});
  }
  if (limits.memory_mb > 0) {
    argv.insert(argv.end(), {"--memory-mb", std::to_string(limits.memory_mb)});
  }
  argv.insert(argv.end(), {"--command-line", this_process_provenance().command_line});
  const ChildOutcome child = run_child(argv, log_path, limits);
  if (child.how == "spawn-failed") throw std::runtime_error(child.note);
  if (child.how == "crash" && interruption_requested()) {
    // Ctrl-C reached the child too: not this run's failure. Nothing of it stays.
    remove_quietly(log_path);
    remove_quietly(result_path);
    throw RunAbandoned("run " + run.id + " abandoned: the suite was interrupted");
  }

  const bool log_empty = [&] {
    std::error_code ec;
    return fs::file_size(log_path, ec) == 0 || ec;
  }();
  auto with_resources = [&](RunResult r) {
    r.run_wall_s = number_text(child.wall_seconds, 4);
    r.run_cpu_s = number_text(child.cpu_seconds, 4);
    r.run_max_rss_mb = number_text(child.max_rss_mb, 4);
    return r;
  };
  RunResult stored;
  if (child.how == "exited" && child.exit_code == 0 && read_run_file(result_path, stored) &&
      stored.definition == run.definition) {
    if (log_empty) remove_quietly(log_path);
    // The child could not know what it used: the runner adds it to its file.
    RunResult r = with_resources(restore_result(suite, run, stored));
    write_run_file(suite, r, result_path);
    return r;
  }

  // The child left no result: the runner writes one, with what it saw.
  RunResult r = with_resources(restore_result(suite, run, RunResult{}));
  r.provenance = this_process_provenance();
  const std::string said = last_log_line(log_path);
  if (child.how != "exited") {
    r.status = child.how;  // timeout, memout, crash
    r.note = child.note;
    if (child.how == "crash" && !said.empty()) r.note += "; last output: " + said;
  } else if (child.exit_code == kExitSuiteChanged) {
    r.status = "failed";
    r.note = "the suite file changed while the suite ran (" + said + "): run the suite again";
  } else if (child.exit_code == 1 || child.exit_code == 2) {
    r.status = "failed";  // the program's own error exit: bad input, an exception
    r.note = said.empty() ? "the run-one process reported an error" : said;
  } else {
    r.status = "crash";
    r.note = "the run-one process exited with status " + std::to_string(child.exit_code) +
             " without a result" + (said.empty() ? std::string() : "; last output: " + said);
  }
  // Nothing half-done of this run stays behind.
  for (const char* suffix : {".trace.csv", ".trace.csv.tmp", ".anytime.csv", ".anytime.csv.tmp",
                             ".solution.csv", ".solution.csv.tmp", ".result.tmp"}) {
    remove_quietly(base + suffix);
  }
  if (log_empty) remove_quietly(log_path);
  write_run_file(suite, r, result_path);
  return r;
}

int run_one(const RunOneRequest& q) {
  install_child_guards();
  apply_limits_to_this_process(q.limits);
  inject_test_fault(q.run_id, q.limits);

  std::istringstream parts(q.combination);
  std::string kind;
  std::size_t subject = 0, solver = 0, profile = 0;
  std::uint64_t seed = 0;
  char s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  std::getline(parts, kind, '/');
  if (!(parts >> subject >> s1 >> solver >> s2 >> profile >> s3 >> seed) || s1 != '/' ||
      s2 != '/' || s3 != '/' || (kind != "camera" && kind != "toy") || parts.get(s4)) {
    throw std::runtime_error(
        "run-one: --combination must be KIND/SUBJECT/SOLVER/PROFILE/SEED, got '" + q.combination +
        "'");
  }
  const SuiteRun::Kind run_kind = kind == "camera" ? SuiteRun::Kind::kCamera : SuiteRun::Kind::kToy;
  const Suite suite = read_suite_file(q.suite_path, SuiteLoadOnly{run_kind, subject});
  const bool camera = run_kind == SuiteRun::Kind::kCamera;
  const bool in_range =
      camera ? subject < suite.scenes.size() && solver < suite.camera_solvers.size() &&
                   profile < suite.profiles.size()
             : subject < suite.problems.size() && solver < suite.toy_solvers.size();
  if (in_range) {
    const SuiteRun run = make_run(suite, run_kind, subject, solver, profile, seed);
    if (run.id == q.run_id) {
      record_run_here(suite, run, q.out_dir, q.command_line);
      return 0;
    }
  }
  std::cerr << "run " << q.run_id << " is not in " << q.suite_path << " any more\n";
  return kExitSuiteChanged;
}

}  // namespace sightline::experiments
