// `sightline run SUITE.yaml --out DIR [--jobs N] [--max-runs K] [--no-report]`: runs an
// experiment suite (docs/EXPERIMENTS.md) in parallel, resumably, and writes DIR/results.csv,
// DIR/summary.md, DIR/report.html and per-run traces under DIR/runs/. Prints the Markdown
// summary. Exits 1 when a run failed, 2 for a bad suite file.
#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/solve_options.h"
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
  std::string report_assets;  // --report-assets inline|beside; empty: as the suite file says
  bool no_report = false;
};

void run_suite_command(const RunOptions& o) {
  const experiments::Suite suite = experiments::read_suite_file(o.suite);
  experiments::RunnerOptions runner;
  runner.out_dir = o.out;
  runner.jobs = o.jobs;
  runner.max_new_runs = o.max_runs;
  const experiments::SuiteOutcome outcome = experiments::run_suite(suite, runner);
  std::cout << experiments::markdown_summary(suite, outcome);
  experiments::ReportOptions report;
  if (o.report_assets == "inline") report.replay_assets = experiments::ReportOptions::ReplayAssets::kInline;
  if (o.report_assets == "beside") report.replay_assets = experiments::ReportOptions::ReplayAssets::kBeside;
  if (!o.no_report) experiments::write_report(suite, outcome, o.out, report);
  std::cout << "Results: " << o.out << "/results.csv" << (o.no_report ? "" : ", report: " + o.out + "/report.html")
            << "\n";
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
  cmd->add_option("--report-assets", options->report_assets,
                  "the 3D replay's three.js and scene data: inline (one file) or beside "
                  "(DIR/report-assets/); default: the suite's report: replay_assets")
      ->check(CLI::IsMember({"inline", "beside"}));
  cmd->callback([options] { run_suite_command(*options); });
}

}  // namespace sightline::apps
