// Suite results: one row of results.csv per run (RunResult), what an output folder holds
// (SuiteState), a whole invocation's outcome (SuiteOutcome), and the results' columns.
//
// The records both the execution (execution/: the runner, isolation, MPI) and the reports
// (reports/: statistics, rankings, summaries) work with, so neither needs the other's
// headers for them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sightline/experiments/suite/provenance.h"
#include "sightline/experiments/suite/suite.h"

namespace sightline::experiments {

// One row of results.csv. `values` line up with result_columns(suite).
struct RunResult {
  std::string id;
  std::string kind;     // "camera" or "toy"
  std::string subject;  // scene or problem label
  std::string solver;
  std::string profile;  // "-" for toy runs
  std::uint64_t seed = 1;
  // "ok"; "skipped" (the solver declared the problem unsuitable); "failed" (an exception,
  // e.g. a file the run needs is unreadable); "wrong" (the run's answer fails its
  // independent check: a toy run's reported cost or hard violation differs from a full
  // re-evaluation, or it claims a perfect score while the independent judge counts broken
  // conditions); and for isolated runs "timeout" (wall or CPU limit), "memout" (an
  // allocation refused) or "crash" (a signal, or an exit without a result).
  std::string status;
  std::vector<std::string> values;  // metric values as text ("" where not applicable)
  std::string note;  // why skipped, failed, wrong, ...; the definition is kept in the run file
  std::string definition;
  Provenance provenance;  // who made the result: host, CPU, build commit, command line
  // What an isolated run's process used, as the kernel counted it (wait4): its wall time,
  // CPU time (user + system, with what it started and waited for) and peak resident memory.
  // "" for in-process runs.
  std::string run_wall_s, run_cpu_s, run_max_rss_mb;
};

struct SuiteOutcome {
  std::size_t total = 0;     // combinations in the suite
  std::size_t reused = 0;    // finished by an earlier invocation
  std::size_t ran = 0;       // done by this one
  std::size_t failed = 0;    // status "failed" (this invocation or earlier)
  std::size_t not_ok = 0;    // timeout, memout, crash or wrong (this invocation or earlier)
  std::vector<RunResult> results;  // every finished run, in the suite's order
  double seconds = 0;
  bool interrupted = false;  // SIGINT or SIGTERM stopped it (execution/interruption.h)
  std::size_t abandoned = 0; // runs in flight the interruption killed (left to run again)
};

// What an output folder holds for a suite: every run of expand_runs(suite), which of them
// are finished (a result file naming the same definition) and their results.
struct SuiteState {
  std::vector<SuiteRun> runs;
  std::vector<RunResult> results;  // meaningful where finished[i]
  std::vector<char> finished;
  std::vector<std::size_t> pending;  // indices of the unfinished runs, in suite order
  std::size_t reused = 0;            // finished before this call
};

// Metric columns for this suite: the camera metrics if it has camera runs, then the toy
// metrics if it has toy runs.
std::vector<std::string> metric_columns(const Suite& suite);
// A result's metric `name` among `columns` (metric_columns of its suite): its text ("" when
// the run has none or the name is not a column), and its number (NaN then, or when the
// text is not a number).
std::string metric_text(const std::vector<std::string>& columns, const RunResult& r,
                        const std::string& name);
double metric_value(const std::vector<std::string>& columns, const RunResult& r,
                    const std::string& name);
// All results.csv columns: id, kind, scene (or problem), solver, profile, seed, status,
// the metric columns, note, then the provenance columns host, cpu_model, build_commit,
// command_line, then an isolated run's resources run_wall_s, run_cpu_s, run_max_rss_mb.
std::vector<std::string> result_columns(const Suite& suite);
// Names of the timing columns (they differ between repeats of the same run), including
// the resource columns run_wall_s, run_cpu_s and run_max_rss_mb.
bool is_timing_column(const std::string& column);
// Names of the provenance columns (they differ between machines, builds and invocations).
bool is_provenance_column(const std::string& column);

}  // namespace sightline::experiments
