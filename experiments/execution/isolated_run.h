// Isolated suite runs: the runner's side (run_isolated) and the child's (run_one, the body
// of the hidden `sightline run-one` subcommand).
//
// The runner starts `PROGRAM run-one SUITE --out DIR --run ID --combination K/S/V/P/SEED`
// with the run's CPU and memory limits on its command line (run_isolation.h). The child
// applies the limits, re-reads the suite file loading only its own scene or problem,
// rebuilds its run from the combination, checks that the id is still the one asked for (the
// suite file may have been edited meanwhile), runs it and writes its result file as an
// in-process run would. The runner then reads that file; when there is none (the child
// crashed, was killed at a limit, ran out of memory) it writes one itself with the status
// and why, so every run ends with a result file and the suite goes on.
// The child's stdout and stderr go to OUT/runs/<id>.log, kept only when not empty.
#pragma once

#include <cstdint>
#include <string>

#include "sightline/experiments/execution/run_isolation.h"
#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/execution/suite_runner.h"

namespace sightline::experiments {

// Runs `run` in a child process of `program` and records it; returns its result (any
// status). Throws std::runtime_error when the suite has no file (it was not read from one)
// or the result file cannot be written.
RunResult run_isolated(const Suite& suite, const SuiteRun& run, const std::string& out_dir,
                       const std::string& program);

// What the runner asks a run-one child to do.
struct RunOneRequest {
  std::string suite_path;
  std::string out_dir;
  std::string run_id;
  std::string combination;   // "camera/SCENE/SOLVER/PROFILE/SEED" or "toy/PROBLEM/SOLVER/0/SEED"
  RunLimits limits;          // CPU and memory are applied; wall is the runner's
  std::string command_line;  // the runner's, recorded as the result's
};

// The child: applies the limits and guards, runs and records the run. Returns the process
// exit status: 0 when recorded, kExitSuiteChanged when the run is no longer in the file.
// Bad input (an unreadable suite file) throws as any command does.
int run_one(const RunOneRequest& request);

}  // namespace sightline::experiments
