// `sightline run SUITE.yaml --out DIR [--jobs N] [--max-runs K] [--compare A,B] [--no-report]
// [--report-assets inline|beside] [--in-process]`:
// runs an experiment suite (docs/EXPERIMENTS.md) in parallel, resumably, each run isolated
// in a child process by default, and writes DIR/results.csv, DIR/summary.md,
// DIR/report.html and per-run traces under DIR/runs/. Prints the Markdown summary. Exits 1
// when a run failed, 2 for a bad suite file or an output folder it may not use.
//
// `sightline run-one ...` (hidden) is the child an isolated run starts
// (experiments/execution/isolated_run.h); people do not type it.
// Started by mpirun with more than one process, the ranks share the suite instead
// (experiments/execution/mpi_engine.h, docs/CLUSTER.md): rank 0 prints and writes the report.
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/solve_options.h"
#include "sightline/experiments/execution/interruption.h"
#include "sightline/experiments/execution/mpi_engine.h"
#include "sightline/experiments/reports/suite_outputs.h"
#include "sightline/experiments/execution/isolated_run.h"
#include "sightline/experiments/reports/report.h"
#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/reports/suite_ranking.h"
#include "sightline/experiments/execution/suite_runner.h"

namespace sightline::apps {
namespace {

struct RunOptions {
  std::string suite;
  std::string out;
  unsigned jobs = 0;
  std::size_t max_runs = 0;
  std::string report_assets;  // --report-assets inline|beside; empty: as the suite file says
  bool no_report = false;
  std::vector<std::string> compare;  // "A,B" pairs for the Wilcoxon test
  bool in_process = false;
};

void run_suite_command(const RunOptions& o) {
  experiments::Suite suite = experiments::read_suite_file(o.suite);
  for (const std::string& pair : o.compare) experiments::add_comparison_option(suite, pair);
  experiments::SuiteOutcome outcome;
  if (experiments::mpi_launch_size() > 1) {
    // One run per rank: --jobs does not apply (docs/CLUSTER.md).
    experiments::MpiRunnerOptions mpi;
    mpi.out_dir = o.out;
    mpi.max_new_runs = o.max_runs;
    mpi.isolation.program = "/proc/self/exe";  // this program is sightline: its own child
    if (o.in_process) mpi.isolation.isolated = false;
    std::optional<experiments::SuiteOutcome> on_rank_0 = experiments::run_suite_mpi(suite, mpi);
    if (!on_rank_0) return;  // a worker rank: rank 0 reports
    outcome = std::move(*on_rank_0);
  } else {
    experiments::RunnerOptions runner;
    runner.out_dir = o.out;
    runner.jobs = o.jobs;
    runner.max_new_runs = o.max_runs;
    runner.isolation.program = "/proc/self/exe";
    if (o.in_process) runner.isolation.isolated = false;
    outcome = experiments::run_suite(suite, runner);
  }
  std::cout << experiments::markdown_summary(suite, outcome);
  experiments::ReportOptions report;
  if (o.report_assets == "inline") report.replay_assets = experiments::ReportOptions::ReplayAssets::kInline;
  if (o.report_assets == "beside") report.replay_assets = experiments::ReportOptions::ReplayAssets::kBeside;
  if (!o.no_report) experiments::write_report(suite, outcome, o.out, report);
  std::cout << "Results: " << o.out << "/results.csv" << (o.no_report ? "" : ", report: " + o.out + "/report.html")
            << "\n";
  if (outcome.not_ok > 0) {
    std::cout << outcome.not_ok
              << " run(s) ended in timeout, memout, crash or wrong; see the status column\n";
  }
  if (outcome.interrupted) {
    throw Interrupted(experiments::interruption_text(outcome) + "; resume with: sightline run " +
                      o.suite + " --out " + o.out);
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
  cmd->add_option("--compare", options->compare,
                  "A,B: a Wilcoxon signed-rank test between solvers A and B in the summary "
                  "(repeatable)")
      ->allow_extra_args(false);
  cmd->add_flag("--no-report", options->no_report, "skip report.html");
  cmd->add_option("--report-assets", options->report_assets,
                  "the 3D replay's three.js and scene data: inline (one file) or beside "
                  "(DIR/report-assets/); default: the suite's report: replay_assets")
      ->check(CLI::IsMember({"inline", "beside"}));
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
