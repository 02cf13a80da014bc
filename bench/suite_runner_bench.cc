// The cost of isolating suite runs: a suite of 200 short toy runs (N-queens 4..13 x bnb, sls
// x 10 seeds, each a few milliseconds or less) run by the thread-pool runner in-process and
// isolated (a run-one child per run, experiments/execution/isolated_run.h), with 1 and 2 jobs. Prints
// a Markdown table: wall time of the suite, per run, and the overhead per run of isolation.
// A plain program: it times whole suites. See docs/BENCHMARKS.md.
//
//   build/bench/suite_runner_bench [--repeats 3]
#include <sys/resource.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/execution/suite_runner.h"

namespace fs = std::filesystem;
using namespace sightline::experiments;

// CPU seconds (user + system) of this process and its waited-for children so far.
double cpu_seconds() {
  double total = 0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    ::getrusage(who, &u);
    total += u.ru_utime.tv_sec + u.ru_utime.tv_usec * 1e-6 + u.ru_stime.tv_sec +
             u.ru_stime.tv_usec * 1e-6;
  }
  return total;
}

int main(int argc, char** argv) {
  int repeats = 3;
  CLI::App app{"suite runner overhead: in-process against isolated runs"};
  app.add_option("--repeats", repeats, "suites per setting (the median is shown)")
      ->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);

  const fs::path dir =
      fs::temp_directory_path() / ("suite-runner-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream(dir / "suite.yaml")
        << "name: overhead\nproblems:\n"
           "  instances: [{nqueens: [4, 5, 6, 7, 8, 9, 10, 11, 12, 13]}]\n"
           "  solvers: [bnb, sls]\n"
           "  seeds: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n";
  }
  const Suite suite = read_suite_file((dir / "suite.yaml").string());
  const std::size_t runs = expand_runs(suite).size();

  std::printf(
      "| jobs | mode | suite wall s (median of %d) | wall per run ms | CPU per run ms |"
      " isolation wall overhead per run ms |\n",
      repeats);
  std::printf("|---:|---|---:|---:|---:|---:|\n");
  int serial = 0;
  for (unsigned jobs : {1u, 2u}) {
    double in_process = 0;
    for (bool isolated : {false, true}) {
      std::vector<double> seconds;
      const double cpu_before = cpu_seconds();
      for (int r = 0; r < repeats; ++r) {
        RunnerOptions options;
        options.out_dir = (dir / ("out" + std::to_string(serial++))).string();
        options.jobs = jobs;
        options.progress = false;
        options.isolation.isolated = isolated;
        options.isolation.program = SIGHTLINE_BINARY;
        const auto start = std::chrono::steady_clock::now();
        const SuiteOutcome outcome = run_suite(suite, options);
        seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (outcome.results.size() != runs) {
          std::cerr << "only " << outcome.results.size() << " of " << runs << " runs finished\n";
          return 1;
        }
        fs::remove_all(options.out_dir);
      }
      const double cpu_per_run = (cpu_seconds() - cpu_before) / repeats / runs;
      std::sort(seconds.begin(), seconds.end());
      const double median = seconds[seconds.size() / 2];
      if (!isolated) in_process = median;
      std::printf(
          "| %u | %s | %.3f | %.2f | %.2f | %s |\n", jobs, isolated ? "isolated" : "in-process",
          median, 1000 * median / runs, 1000 * cpu_per_run,
          isolated ? std::to_string(1000 * (median - in_process) / runs * jobs).substr(0, 5).c_str()
                   : "");
    }
  }
  std::printf(
      "\n%zu runs per suite; CPU = this process and its children (user + system); wall "
      "overhead per run = (isolated - in-process) wall / runs x jobs.\n",
      runs);
  fs::remove_all(dir);
  return 0;
}
