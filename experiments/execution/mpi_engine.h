// MpiEngine: runs a suite across the processes of an MPI job, `mpirun -np N sightline run`.
//
// Rank 0 is the dispatcher: it reads the output folder with the same code as the local
// runner (read_suite_state), orders the unfinished runs longest expected first
// (run_order.h) and hands them out on demand: a worker says "ready" (or "done i"), rank 0
// answers with the next run's index or "stop". Ranks 1..N-1 execute and record each run
// with run_and_record, so every run lands in OUT/runs/ by write-then-rename exactly as under
// the thread pool, and a suite started by one engine can be finished by the other. When all
// workers have stopped, rank 0 reads the folder again and writes results.csv, stats.csv and
// summary.md (write_suite_outputs, markdown_summary). With one process rank 0 runs
// everything itself. Only rank 0 touches the folder besides the runs' own files, so no
// locking is needed, on a local disk or on NFS/Lustre (docs/CLUSTER.md).
//
// Open MPI 4 has no fault tolerance: a rank that dies takes the job down. Nothing finished
// is lost (each run was renamed into place when it finished) and the cure is to submit the
// same command again, which redoes only the unfinished runs.
//
// Bad input: an output folder that cannot be written, or ranks that expand the suite to
// different runs (nodes seeing different files), make rank 0 throw std::runtime_error after
// telling every worker to stop, so the whole job exits, non-zero, without hanging.
//
// This header does not include mpi.h: the program builds and runs without MPI, and
// mpi_engine_built() says whether this build has the engine.
//
// Test hook: SIGHTLINE_TEST_ABORT_AFTER_RUNS="RANK:K" makes worker RANK call std::abort()
// right after recording its K-th run (before reporting it), as a crashed rank would; the
// tests use it to check that a resubmitted job loses and redoes nothing.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/execution/suite_runner.h"

namespace sightline::experiments {

// The number of processes an MPI launcher started together with this one, read from the
// environment before MPI is initialised (Open MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE as
// MPICH's Hydra and Slurm's PMI-2 set it); 1 when this process was not started by one.
int mpi_launch_size();

// True when this program was built with MPI (CMake found it), so run_suite_mpi can run.
bool mpi_engine_built();

struct MpiRunnerOptions {
  std::string out_dir;
  std::size_t max_new_runs = 0;  // > 0: hand out at most this many unfinished runs
  bool progress = true;          // rank 0's progress on stderr
  IsolationOptions isolation;    // each run in a child of its own (default), as locally
};

// The folder once a job's runs are in: read_suite_state, read again once a second for up to
// `patience_seconds` until every run in `recorded` (indices into expand_runs(suite)) shows as
// finished. On NFS the dispatcher's node may remember for a while that a result file did not
// exist (negative lookup caching) after another node renamed it into place: until the
// directory's cached attributes expire, up to acdirmax, 60 s by default. A coherent file
// system (a local disk, Lustre, GPFS) shows them at the first reading. Throws
// std::runtime_error saying how many are missing when they do not show in time.
SuiteState read_recorded_state(const Suite& suite, const std::string& out_dir,
                               const std::vector<std::size_t>& recorded, int patience_seconds = 90);

// Initialises MPI, runs the suite across the job's ranks and finalises MPI. Returns the
// outcome on rank 0 (summary.md written) and nothing on the workers. Throws
// std::runtime_error on rank 0 for an unwritable folder, a run that could not be recorded,
// or ranks that disagree about the runs; and when the program was built without MPI.
std::optional<SuiteOutcome> run_suite_mpi(const Suite& suite, const MpiRunnerOptions& options);

}  // namespace sightline::experiments
