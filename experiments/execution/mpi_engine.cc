#include "sightline/experiments/execution/mpi_engine.h"
#include "sightline/experiments/reports/suite_outputs.h"

#include "sightline/experiments/runs/output_text.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "sightline/experiments/execution/run_order.h"
#include "sightline/experiments/runs/stable_hash.h"

#ifdef SIGHTLINE_HAVE_MPI
// The C API only: Open MPI's and MPICH's headers would otherwise pull in the C++ bindings.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace sightline::experiments {
namespace {

// A positive integer from the environment, or 0.
long positive_env(const char* name) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return 0;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return (*end == '\0' && value > 0) ? value : 0;
}

}  // namespace

int mpi_launch_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const long n = positive_env(name); n > 0) return static_cast<int>(n);
  }
  return 1;
}

SuiteState read_recorded_state(const Suite& suite, const std::string& out_dir,
                               const std::vector<std::size_t>& recorded, int patience_seconds) {
  for (int waited = 0;; ++waited) {
    SuiteState state = read_suite_state(suite, out_dir);
    std::size_t missing = 0;
    for (const std::size_t i : recorded) missing += state.finished.at(i) ? 0 : 1;
    if (missing == 0) return state;
    if (waited >= patience_seconds) {
      throw std::runtime_error(
          std::to_string(missing) + " run(s) reported as recorded do not show in " + out_dir +
          "/runs after " + std::to_string(patience_seconds) +
          " s (a file system that is not coherent between nodes?); submit the same command "
          "again to tabulate them");
    }
    std::this_thread::sleep_for(std::chrono::seconds(1));
  }
}

#ifndef SIGHTLINE_HAVE_MPI

bool mpi_engine_built() { return false; }

std::optional<SuiteOutcome> run_suite_mpi(const Suite&, const MpiRunnerOptions&) {
  throw std::runtime_error(
      "this sightline was built without MPI (CMake found no MPI C library when the build was "
      "configured), so it cannot share a suite between the processes mpirun started: run it "
      "without mpirun, or install libopenmpi-dev and rebuild (docs/CLUSTER.md)");
}

#else

bool mpi_engine_built() { return true; }

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Workers talk to the dispatcher in short texts ("ready", "done 12", "error <why>"); the
// dispatcher answers with a run index, -1 for "stop".
constexpr int kTagToDispatcher = 1;
constexpr int kTagToWorker = 2;
constexpr long long kStop = -1;

// MPI_Init on construction; MPI_Finalize once, by finish() or when leaving the engine
// (also by an exception), so that every rank always finalises and mpirun never waits.
class MpiSession {
 public:
  MpiSession() {
    MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { finish(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  void finish() {
    if (!finished_) {
      finished_ = true;
      MPI_Finalize();
    }
  }
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
  bool finished_ = false;
};

// FNV-1a over the run ids in order: ids carry a hash of each run's whole definition (scene
// file content included), so equal hashes mean the ranks agree on what run i is.
std::uint64_t ids_hash(const std::vector<SuiteRun>& runs) {
  StableHash h;
  for (const SuiteRun& run : runs) h.add(run.id).add("\n");
  return h.value();
}

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%ld:%02ld", s / 60, s % 60);
  return buffer;
}

// Rank 0's progress on stderr in the local runner's words. On a terminal one line rewritten
// in place; otherwise (mpirun's forwarded stderr, a batch job's log) a line at most every
// 30 s and one at the end, so a log shows how far a long job got.
class Progress {
 public:
  Progress(bool enabled, std::size_t total, std::size_t reused, std::size_t to_run, int ranks)
      : enabled_(enabled),
        in_place_(::isatty(STDERR_FILENO) != 0),
        total_(total),
        done_(reused),
        reused_(reused),
        start_(Clock::now()),
        last_line_(start_) {
    if (!enabled_) return;
    std::cerr << "MPI: " << ranks << " ranks; " << total << " runs, " << reused
              << " finished before, " << to_run << " to run now\n";
    if (in_place_) show('\r');
  }
  void finished_one() {
    ++done_;
    if (!enabled_) return;
    if (in_place_) {
      show('\r');
    } else if (Clock::now() - last_line_ >= std::chrono::seconds(30)) {
      show('\n');
    }
  }
  void end() {
    if (!enabled_) return;
    if (in_place_) {
      std::cerr << '\n';
    } else {
      show('\n');
    }
  }

 private:
  void show(char how) {
    last_line_ = Clock::now();
    const double elapsed = std::chrono::duration<double>(last_line_ - start_).count();
    const std::size_t ran = done_ - reused_;
    std::string left = "?";
    if (ran > 0) left = clock_text(elapsed / static_cast<double>(ran) * (total_ - done_));
    if (how == '\r') std::cerr << '\r';
    std::cerr << "runs " << done_ << '/' << total_ << " (" << reused_ << " reused), elapsed "
              << clock_text(elapsed) << ", about " << left << " left   ";
    if (how == '\n') std::cerr << '\n';
    std::cerr << std::flush;
  }
  bool enabled_, in_place_;
  std::size_t total_, done_, reused_;
  Clock::time_point start_, last_line_;
};

void send_text(const std::string& text, int to) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, kTagToDispatcher,
           MPI_COMM_WORLD);
}

// The next message from any worker. Probes and sleeps between probes (20 us, doubling up to
// 1 ms) instead of blocking in MPI_Recv, which in Open MPI spins a core: rank 0 shares its
// node with workers and should leave them the CPU.
std::pair<int, std::string> receive_from_a_worker() {
  MPI_Status status;
  int arrived = 0;
  auto pause = std::chrono::microseconds(20);
  while (true) {
    MPI_Iprobe(MPI_ANY_SOURCE, kTagToDispatcher, MPI_COMM_WORLD, &arrived, &status);
    if (arrived) break;
    std::this_thread::sleep_for(pause);
    pause = std::min<std::chrono::microseconds>(pause * 2, std::chrono::milliseconds(1));
  }
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  std::string text(static_cast<std::size_t>(length), '\0');
  MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kTagToDispatcher, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return {status.MPI_SOURCE, text};
}

// SIGHTLINE_TEST_ABORT_AFTER_RUNS="RANK:K" (a test hook, mpi_engine.h): K for this rank,
// 0 when unset, malformed or for another rank.
std::size_t abort_after_runs(int rank) {
  const char* text = std::getenv("SIGHTLINE_TEST_ABORT_AFTER_RUNS");
  if (text == nullptr) return 0;
  char* end = nullptr;
  const long hook_rank = std::strtol(text, &end, 10);
  if (*end != ':' || hook_rank != rank) return 0;
  const char* count_text = end + 1;
  const long count = std::strtol(count_text, &end, 10);
  return (*end == '\0' && count > 0) ? static_cast<std::size_t>(count) : 0;
}

// A worker rank: asks for runs until told to stop, recording each with run_and_record.
void work(const Suite& suite, const std::vector<SuiteRun>& runs, const std::string& out_dir,
          const IsolationOptions& isolation, int rank) {
  const std::size_t abort_after = abort_after_runs(rank);
  std::size_t recorded = 0;
  std::string message = "ready";
  while (true) {
    send_text(message, 0);
    long long index = kStop;
    MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kTagToWorker, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0 || static_cast<std::size_t>(index) >= runs.size()) return;
    const SuiteRun& run = runs[static_cast<std::size_t>(index)];
    try {
      run_and_record(suite, run, out_dir, isolation);
      ++recorded;
      if (recorded == abort_after) std::abort();  // the test hook: a rank that dies
      message = "done " + std::to_string(index);
    } catch (const std::exception& e) {
      message = "error rank " + std::to_string(rank) + ", run " + run.id + ": " + e.what();
    }
  }
}

}  // namespace

std::optional<SuiteOutcome> run_suite_mpi(const Suite& suite, const MpiRunnerOptions& options) {
  const auto start = Clock::now();
  MpiSession mpi;
  const bool dispatcher = mpi.rank() == 0;

  // Rank 0 reads the folder; every worker expands the suite itself and checks below that
  // it got the same runs in the same order, since only indices travel.
  SuiteState state;
  std::vector<SuiteRun> runs;
  std::string error;
  try {
    if (dispatcher) {
      state = read_suite_state(suite, options.out_dir);
      runs = state.runs;
    } else {
      runs = expand_runs(suite);
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  std::uint64_t header[3] = {error.empty() ? 1u : 0u, runs.size(), ids_hash(runs)};
  MPI_Bcast(header, 3, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  if (header[0] == 0) {  // rank 0 cannot use the folder: every rank stops
    if (!dispatcher) return std::nullopt;
    mpi.finish();
    throw std::runtime_error(error);
  }
  int differs =
      !dispatcher && (!error.empty() || runs.size() != header[1] || ids_hash(runs) != header[2]);
  int any_differs = 0;
  MPI_Allreduce(&differs, &any_differs, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (any_differs) {
    if (!dispatcher) return std::nullopt;
    mpi.finish();
    throw std::runtime_error(
        "some MPI ranks expand the suite to other runs than rank 0 does: do all nodes see the "
        "same suite, scene and problem files?");
  }
  if (!dispatcher) {
    work(suite, runs, options.out_dir, options.isolation, mpi.rank());
    return std::nullopt;
  }

  std::vector<std::size_t> order = longest_first(suite, state.runs, state.pending);
  if (options.max_new_runs > 0 && order.size() > options.max_new_runs) {
    order.resize(options.max_new_runs);
  }
  Progress progress(options.progress, state.runs.size(), state.reused, order.size(), mpi.size());
  std::vector<std::size_t> recorded;  // runs whose worker (or rank 0) reported them done
  std::string write_error;
  if (mpi.size() == 1) {  // no workers: rank 0 runs everything itself
    for (const std::size_t i : order) {
      try {
        run_and_record(suite, state.runs[i], options.out_dir, options.isolation);
      } catch (const std::exception& e) {
        write_error = e.what();
        break;
      }
      recorded.push_back(i);
      progress.finished_one();
    }
  } else {
    // After a run could not be recorded (a full disk, a folder made read-only) no more runs
    // are handed out: every worker is told to stop as it next asks.
    std::size_t next = 0;
    int working = mpi.size() - 1;
    while (working > 0) {
      const auto [worker, text] = receive_from_a_worker();
      if (text.rfind("done ", 0) == 0) {
        recorded.push_back(std::stoull(text.substr(5)));
        progress.finished_one();
      } else if (text.rfind("error ", 0) == 0 && write_error.empty()) {
        write_error = text.substr(6);
      }
      long long reply = kStop;
      if (write_error.empty() && next < order.size()) reply = static_cast<long long>(order[next++]);
      MPI_Send(&reply, 1, MPI_LONG_LONG, worker, kTagToWorker, MPI_COMM_WORLD);
      if (reply == kStop) --working;
    }
  }
  progress.end();
  mpi.finish();  // the workers may exit now; what is left is rank 0's files
  if (!write_error.empty()) throw std::runtime_error(write_error);

  // The folder is the truth: read it again, as the local runner's state would be.
  const SuiteState finished = read_recorded_state(suite, options.out_dir, recorded);
  SuiteOutcome outcome = write_suite_outputs(suite, options.out_dir, finished);
  outcome.reused = state.reused;
  outcome.ran = recorded.size();
  outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  write_atomically((fs::path(options.out_dir) / "summary.md").string(),
                   markdown_summary(suite, outcome));
  return outcome;
}

#endif  // SIGHTLINE_HAVE_MPI

}  // namespace sightline::experiments
