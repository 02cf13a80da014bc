// suite_dispatch_bench: the scheduling overhead per run of `sightline run`, the local thread
// pool against the MPI engine, on a suite of very short runs (docs/BENCHMARKS.md).
//
//   suite_dispatch_bench [--runs 200] [--workers 2] [--repeats 5] [--no-mpi]
//
// The suite is N-queens 8 with bnb over seeds 1..runs: each run takes well under a
// millisecond, so what is measured is the engine, not the solver. Per engine:
//   T_full   the whole command (`sightline run --jobs W`, or `mpirun --oversubscribe -np W+1
//            sightline run`) on an empty folder;
//   T_fixed  the same command on the finished folder: start-up (mpirun's included), reading
//            the folder, writing results.csv/stats.csv/summary.md: paid once a submission;
//   T_runs   the runs alone: one process calling run_and_record on each in turn;
//   overhead per run = (W x (T_full - T_fixed) - T_runs) / runs: worker time a run costs
//            beyond its own execution (hand-out, messages, idle workers, contention).
// Medians over the repeats. A plain program, not Google Benchmark: it times whole commands.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/execution/suite_runner.h"

namespace {

using namespace sightline;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

std::string ms(double seconds) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(seconds < 0.01 ? 2 : 0) << seconds * 1e3 << " ms";
  return out.str();
}

std::string us(double seconds) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << seconds * 1e6 << " us";
  return out.str();
}

// Seconds the shell command took; exits the program if it failed.
double time_command(const std::string& command) {
  const auto start = Clock::now();
  const int status = std::system((command + " >/dev/null 2>&1").c_str());
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (status != 0) {
    std::cerr << "suite_dispatch_bench: failed: " << command << '\n';
    std::exit(1);
  }
  return seconds;
}

struct Figures {
  double full = 0, fixed = 0;
};

Figures time_engine(const std::string& command_before_out, const fs::path& out, int repeats) {
  std::vector<double> full, fixed;
  for (int i = 0; i < repeats; ++i) {
    fs::remove_all(out);
    const std::string command = command_before_out + " --out '" + out.string() + "' --no-report";
    full.push_back(time_command(command));
    fixed.push_back(time_command(command));
  }
  return {median(full), median(fixed)};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Scheduling overhead per run of sightline run: thread pool against MPI"};
  int runs = 200, workers = 2, repeats = 5;
  bool no_mpi = false;
  app.add_option("--runs", runs, "runs in the suite")->check(CLI::Range(1, 100000));
  app.add_option("--workers", workers, "runs at a time (--jobs; MPI ranks minus one)")
      ->check(CLI::Range(1, 1024));
  app.add_option("--repeats", repeats, "repeats (medians are shown)")->check(CLI::Range(1, 100));
  app.add_flag("--no-mpi", no_mpi, "time the thread pool only");
  CLI11_PARSE(app, argc, argv);

  const fs::path dir =
      fs::temp_directory_path() / ("sightline-dispatch-bench-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path suite_file = dir / "suite.yaml";
  {
    std::ofstream suite(suite_file);
    suite << "name: dispatch\nproblems:\n  instances: [{nqueens: [8]}]\n  solvers: [bnb]\n"
          << "  seeds: [";
    for (int s = 1; s <= runs; ++s) suite << (s > 1 ? ", " : "") << s;
    suite << "]\n";
  }

  // The runs alone, in this process, one after another.
  const experiments::Suite suite = experiments::read_suite_file(suite_file.string());
  std::vector<double> alone;
  for (int i = 0; i < repeats; ++i) {
    const fs::path out = dir / "alone";
    fs::remove_all(out);
    const experiments::SuiteState state = experiments::read_suite_state(suite, out.string());
    const auto start = Clock::now();
    for (const std::size_t r : state.pending) {
      experiments::run_and_record(suite, state.runs[r], out.string());
    }
    alone.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  const double t_runs = median(alone);

  const std::string program =
      std::string("'") + SIGHTLINE_BINARY + "' run '" + suite_file.string() + "'";
  struct Row {
    std::string engine;
    Figures figures;
  };
  std::vector<Row> rows;
  rows.push_back(
      {"thread pool, --jobs " + std::to_string(workers),
       time_engine(program + " --jobs " + std::to_string(workers), dir / "local", repeats)});
  if (!no_mpi) {
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    ::setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
    rows.push_back(
        {"MPI, mpirun -np " + std::to_string(workers + 1),
         time_engine("mpirun --oversubscribe -np " + std::to_string(workers + 1) + " " + program,
                     dir / "mpi", repeats)});
  }

  std::cout << runs << " runs (8-queens, bnb), " << workers << " workers, median of " << repeats
            << "; the runs alone, one after another in one process: " << ms(t_runs) << " ("
            << us(t_runs / runs) << " a run)\n\n"
            << "| engine | command, " << runs << " runs | command, nothing to run | "
            << "overhead per run |\n| --- | ---: | ---: | ---: |\n";
  for (const Row& row : rows) {
    const double overhead = (workers * (row.figures.full - row.figures.fixed) - t_runs) / runs;
    std::cout << "| " << row.engine << " | " << ms(row.figures.full) << " | "
              << ms(row.figures.fixed) << " | " << us(overhead) << " |\n";
  }
  fs::remove_all(dir);
  return 0;
}
