// The statistics part of a suite's results (issue 14): repetitions over seeds and PAR-2.
//
// From the finished runs of a suite (SuiteOutcome), in the suite's order:
//  - when the suite repeats runs over more than one seed, per (scene or problem, solver,
//    profile): n, median and mean of each headline metric with percentile-bootstrap 95%
//    confidence intervals (statistics.h; fixed seed, so reruns give the same numbers).
//    Headline metrics: camera visible_pct, cost_mean, cuts, solve_us_p99; toy cost, time_s.
//  - for toy suites with several solvers, PAR-2 per solver over all its toy runs. A run is
//    solved when its status is ok, it is feasible and it stopped on its own ("completed",
//    "proven optimal", "target reached"); the time limit is the suite's toy time limit when
//    it has one, else the largest time_s observed (x 1.0), so a run never solved counts
//    twice the slowest run.
// Both go into summary.md (markdown) and OUT/stats.csv in a long format, one number a row:
//   kind,subject,solver,profile,metric,statistic,value
// statistic is n, median, mean, mean_ci_low, mean_ci_high, median_ci_low, median_ci_high;
// PAR-2 rows have subject "*", metric "time_s" and statistic runs, solved, par2_s,
// time_limit_s. Ranking rows (average ranks, Friedman, Wilcoxon) follow: suite_ranking.h.
// Problem suites also get OUT/cactus.csv and OUT/profiles.csv (time_profiles.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/suite/suite_results.h"

namespace sightline::experiments {

// The Markdown sections ("Repetitions over seeds", "PAR-2"); empty when neither applies.
std::string statistics_markdown(const Suite& suite, const SuiteOutcome& outcome);

// stats.csv's text: the header line, then the rows described above (possibly none).
std::string statistics_csv(const Suite& suite, const SuiteOutcome& outcome);

// Every statistics file of the output folder as (file name, text): stats.csv always, and
// cactus.csv and profiles.csv when the suite has problem runs.
std::vector<std::pair<std::string, std::string>> statistics_files(const Suite& suite,
                                                                  const SuiteOutcome& outcome);

}  // namespace sightline::experiments
