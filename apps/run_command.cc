// `sightline run SUITE.yaml --out DIR [--jobs N] [--max-runs K] [--no-report] [--in-process]`:
// runs an experiment suite (docs/EXPERIMENTS.md) in parallel, resumably, each run isolated
// in a child process by default, and writes DIR/results.csv, DIR/summary.md,
// DIR/report.html and per-run traces under DIR/runs/. Prints the Markdown summary. Exits 1
// when a run failed, 2 for a bad suite file or an output folder it may not use.
//
// `sightline run-one ...` (hidden) is the child an isolated run starts
// (experiments/isolated_run.h); people do not type it.
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/solve_options.h"
#include "experiments/isolated_run.h"
#include "experiments/report.h"
#include "experiments/suite.h"
#include "experiments/suite_runner.h"

namespace sightline::apps {
namespace {

struct RunOptions {
  std::string suite;
  std::string out;
  unsigned jobs = 0;
  std::size_t max_runs = 0;
  bool no_report = false;
  bool in_process = false;
};

void run_suite_command(const RunOptions& o) {
  const experiments::Suite suite = experiments::read_suite_file(o.suite);
  experiments::RunnerOptions runner;
  runner.out_dir = o.out;
  runner.jobs = o.jobs;
  runner.max_new_runs = o.max_runs;
  if (o.in_process) runner.isolation.isolated = false;
  const experiments::SuiteOutcome outcome = experiments::run_suite(suite, runner);
  std::cout << experiments::markdown_summary(suite, outcome);
  if (!o.no_report) experiments::write_report(suite, outcome, o.out);
  std::cout << "Results: " << o.out << "/results.csv" << (o.no_report ? "" : ", report: " + o.out + "/report.html")
            << "\n";
  if (outcome.not_ok > 0) {
    std::cout << outcome.not_ok
              << " run(s) ended in timeout, memout, crash or wrong; see the status column\n";
  }
  if (outcome.failed > 0) {
    throw RunFailed(std::to_string(outcome.failed) + " run(s) failed; see the note column of " +
                    o.out + "/results.csv");
  }
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run an experiment suite in parallel (resumable) and write results and a report");
  cmd->add_option("suite", options->suite, "suite file (YAML, see docs/EXPERIMENTS.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", options->out, "output directory (created; finished runs are kept)")
      ->required();
  cmd->add_option("--jobs,-j", options->jobs, "runs at a time (default: one per core)")
      ->check(CLI::Range(1u, 1024u));
  cmd->add_option("--max-runs", options->max_runs,
                  "stop after this many new runs (the rest resume next time)")
      ->check(unsigned_integer());
  cmd->add_flag("--no-report", options->no_report, "skip report.html");
  cmd->add_flag("--in-process", options->in_process,
                "run each combination in this process, not in a child of its own (no "
                "isolation and no limits; the suite's `isolation: false` does the same)");
  cmd->callback([options] { run_suite_command(*options); });

  // The child of an isolated run. Hidden: the runner builds its command line.
  auto one = std::make_shared<experiments::RunOneRequest>();
  CLI::App* child = app.add_subcommand("run-one", "run one combination of a suite (internal)");
  child->group("");
  child->add_option("suite", one->suite_path)->required();
  child->add_option("--out", one->out_dir)->required();
  child->add_option("--run", one->run_id)->required();
  child->add_option("--combination", one->combination)->required();
  child->add_option("--wall-seconds", one->limits.wall_seconds);
  child->add_option("--cpu-seconds", one->limits.cpu_seconds);
  child->add_option("--memory-mb", one->limits.memory_mb);
  child->add_option("--command-line", one->command_line);
  child->callback([one] {
    const int status = experiments::run_one(*one);
    std::cout.flush();
    if (status != 0) std::exit(status);
  });
}

}  // namespace sightline::apps
