// SuiteRunner: runs every combination of a suite in parallel, resumably, and tabulates them.
//
// Runs are independent, so they go to a Boost.Asio thread_pool, one per core (or --jobs).
// Each run executes in a child process of its own by default (isolated_run.h), under the
// suite's limits, so a crash, a hang or a memory blow-up loses that run only (its output,
// if any, is kept in OUT/runs/<id>.log). OUT/manifest names the suite a folder belongs to
// (output_manifest.h).
// Each finished run leaves two files in OUT/runs/: its trace (camera runs; FORMATS.md) and a
// one-row result file, both written to a ".tmp" name first and renamed, the result last. A
// run counts as finished only when its result file exists, parses, and names the same
// definition (so a half-written result, a stray .tmp, or an edited suite entry is redone);
// a second invocation therefore skips what is done and redoes nothing twice.
// When all runs are in, the reports (reports/suite_outputs.h) write OUT/results.csv, the
// statistics and OUT/summary.md, again by write-then-rename.
//
// Progress goes to stderr, and only when stderr is a terminal: runs done/total, elapsed, an
// estimate of the time left.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/suite/suite_results.h"

namespace sightline::experiments {


// Whether runs execute in child processes (isolated_run.h).
// Isolation needs the sightline program to start as the child: the program itself names it
// ("/proc/self/exe", apps/run_command.cc). A library caller that names none (a test, a
// bench) runs in process, since its own executable is not sightline and would not know the
// child's subcommand; a suite with limits then cannot be run (they need a child).
struct IsolationOptions {
  std::optional<bool> isolated;  // unset: the suite's `isolation:` (default true)
  std::string program;           // the sightline program a child runs; empty: in process
};

struct RunnerOptions {
  std::string out_dir;
  unsigned jobs = 0;             // 0: one per hardware thread
  std::size_t max_new_runs = 0;  // > 0: stop after starting this many unfinished runs
  bool progress = true;          // shown only if stderr is also a terminal
  IsolationOptions isolation;
};



// Why a toy run's answer is wrong ("" when its independent check accepts it): `reported`
// differs from a full re-evaluation of `best` by problem.score (hard and soft to a relative
// 1e-6), or it claims a perfect score (feasible, cost 0) while `broken` (the independent
// judge's count for `best`, -1 when there is none) is above 0.
std::string toy_answer_problem(const csp::Problem& problem, const csp::Assignment& best,
                               const csp::Score& reported, long long broken);

// Thrown by run_and_record for an isolated run whose child an interruption killed: it
// leaves no result and no log, and the suite runs it again when resumed.
class RunAbandoned : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs one combination now, writing its files beside `file_base` (runs/<id>): a camera run's
// <base>.trace.csv, a problem run's <base>.anytime.csv and <base>.solution.csv; none when
// empty. Exceptions become status "failed".
RunResult execute_run(const Suite& suite, const SuiteRun& run, const std::string& file_base);

// --- The run-file protocol, shared by every engine (the thread pool here, MPI) ---
// OUT/runs/<id>: the path of a run's files without extension (".result", ".trace.csv").
std::string run_file_base(const std::string& out_dir, const std::string& id);
// Runs one combination and records it: its trace, then its result file, each written to a
// ".tmp" name and renamed. Isolated (the default, see IsolationOptions) it runs in a child
// process under the run's limits and ends with any status; otherwise in this process.
// Throws std::runtime_error when the files cannot be written or the child cannot start.
RunResult run_and_record(const Suite& suite, const SuiteRun& run, const std::string& out_dir,
                         const IsolationOptions& isolation = {});
// Whether runs of `suite` are isolated under `isolation`; throws std::runtime_error when
// they are not but the suite sets limits (only a child process can be held to them).
bool runs_isolated(const Suite& suite, const IsolationOptions& isolation);
// The in-process half, what an isolated child does: execute_run, then the files, the result
// naming `command_line` as the command that made it.
RunResult record_run_here(const Suite& suite, const SuiteRun& run, const std::string& out_dir,
                          const std::string& command_line);
// Writes a run's result file (write, then rename).
void write_run_file(const Suite& suite, const RunResult& result, const std::string& path);
// A result read by read_run_file, its metrics put back in `suite`'s column order.
RunResult restore_result(const Suite& suite, const SuiteRun& run, const RunResult& stored);

// Claims the folder for the suite first (output_manifest.h: OUT/manifest; refuses another
// suite's folder), then reads OUT/runs (created if missing; std::runtime_error if it
// cannot be).
SuiteState read_suite_state(const Suite& suite, const std::string& out_dir);

// Runs the suite into options.out_dir (created if needed). Throws std::runtime_error if the
// directory cannot be written.
SuiteOutcome run_suite(const Suite& suite, const RunnerOptions& options);


// Reads a result file written by the runner; false when missing, half-written or malformed.
bool read_run_file(const std::string& path, RunResult& result);

}  // namespace sightline::experiments
