// Suite outputs: what an output folder shows once its runs are in: OUT/results.csv, the
// statistics files (suite_statistics.h) and the Markdown summary.
#pragma once

#include <string>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/suite/suite_results.h"

namespace sightline::experiments {

// Writes OUT/results.csv and OUT/stats.csv from the finished runs and returns the outcome
// (total, reused, failed, results; the caller sets ran and seconds and writes summary.md).
SuiteOutcome write_suite_outputs(const Suite& suite, const std::string& out_dir,
                                 const SuiteState& state);

// The Markdown summary: a per-solver table over all scenes, then one row per run.
std::string markdown_summary(const Suite& suite, const SuiteOutcome& outcome);

}  // namespace sightline::experiments
