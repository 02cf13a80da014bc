// Run isolation: one suite run in a child process, under wall-time, CPU-time and memory
// limits, and how it ended (ok, timeout, memout, crash), as runsolver or BenchExec would say.
//
// A suite of thousands of runs must survive the one that segfaults, loops or eats the
// machine's memory: that run is lost, recorded with its status, and the suite goes on. The
// parent starts the child with posix_spawn (never fork: the runner may live inside an MPI
// rank, where fork is unsafe) in a process group of its own, waits for it polling waitpid
// with a wall-clock deadline, and kills the whole group (the run and anything it started,
// e.g. toulbar2) with SIGKILL when the deadline passes.
//
// posix_spawn cannot set resource limits, so the child applies RLIMIT_CPU and RLIMIT_AS to
// itself (apply_limits_to_this_process, from its command line) before it reads the suite:
// no extra program and no extra exec per run; the price is that the program's own start-up
// is outside the limits, which only makes them a few megabytes more generous.
// An allocation the memory limit refuses ends the child at once with kExitMemout (a
// new-handler, installed by install_memout_handler), so it cannot be mistaken for a crash,
// whichever code asked for the memory.
//
// This file knows processes, not suites: experiments/execution/isolated_run.h runs a suite's run
// through it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sightline/experiments/suite/run_limits.h"

namespace sightline::experiments {


// Exit codes of a run-one child besides 0 (recorded), 1 and 2 (main's own).
constexpr int kExitMemout = 86;        // an allocation failed (the memory limit)
constexpr int kExitSuiteChanged = 87;  // the run is not in the suite file any more

// How an isolated child ended, as seen by the parent.
struct ChildOutcome {
  // "exited" (see exit_code), "timeout" (wall or CPU limit), "memout", "crash" (a signal),
  // or "spawn-failed".
  std::string how;
  int exit_code = -1;  // when how == "exited" or "memout"
  int signal = 0;      // when killed by a signal
  std::string note;    // why, for the result's note
  double wall_seconds = 0;
  double cpu_seconds = 0;  // user + system time of the child
  double max_rss_mb = 0;   // its peak resident memory
};

// Starts `argv` (argv[0] is the program path) in a new process group, stdin from /dev/null,
// stdout and stderr to `log_path`, this environment without MPI's variables (OMPI_*, PMIX_*,
// PMI_*: the child is no part of an MPI job), and waits for it, killing its group at
// `limits.wall_seconds`.
// The memory and CPU limits are the child's own business (it is given them on its command
// line); they are used here to name what killed it.
ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& log_path,
                       const RunLimits& limits);

// --- The child's side ---
// setrlimit RLIMIT_CPU (soft = the limit rounded up, hard one second later) and RLIMIT_AS.
// Throws std::runtime_error if the kernel refuses.
void apply_limits_to_this_process(const RunLimits& limits);
// A new-handler that writes one line to stderr and _exits with kExitMemout, and a parent-death
// signal, so a child whose runner was killed does not run on unwatched.
void install_child_guards();

// A test hook, read only by the run-one child: SIGHTLINE_TEST_FAULT="KIND:TEXT[,KIND:TEXT...]"
// makes the run whose id contains TEXT misbehave before it starts: `crash` (SIGSEGV),
// `hang` (sleeps: for the wall limit), `spin` (burns CPU: for the CPU limit), `memory`
// (allocates until refused: for the memory limit; only under a memory limit, never
// unbounded). The tests use it to make real runs crash, hang and blow up; nothing else
// sets it.
void inject_test_fault(const std::string& run_id, const RunLimits& limits);

}  // namespace sightline::experiments
