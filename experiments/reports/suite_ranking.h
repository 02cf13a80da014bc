// Ranking the solvers of a suite across its subjects (issue 14): Friedman's average ranks and
// test, and a Wilcoxon signed-rank test between two named solvers on demand.
//
// Solvers are compared family by family, on the suite's headline metrics:
//   camera runs, per subject = scene (x profile, when the suite has several profiles):
//     visible_pct (higher is better), cuts (fewer is better), jerk_p99 (lower is better):
//     what the camera shows, how often it jumps, how smoothly it moves;
//   problem runs, per subject = instance:
//     cost (the soft cost of a feasible answer; an infeasible answer is worse than any
//     feasible one) and par2_s (the run's time when solved within the limit, else twice the
//     limit; "solved" as in time_profiles.h).
// Repetitions over seeds are reduced to their median per (subject, solver) before ranking. A
// finished run that failed, was skipped, or has no value ranks worst (its loss is +infinity,
// so such runs tie among themselves). A subject where some solver has no finished run yet
// (an interrupted suite) is left out of the ranking and said so.
//
// The Wilcoxon test pairs two solvers subject by subject on the same medians. Pairs are
// named in the suite file,
//   statistics:
//     compare: [occlusion-octree, bourne-published]       # one pair, or
//     compare: [[sls, bnb], [sls, tabu]]                   # several
// or with `sightline run --compare A,B`; both names must be solver labels of one family.
#pragma once

#include <string>
#include <vector>

#include "sightline/csp/input_error.h"
#include "sightline/csp/spec.h"
#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/suite/suite_comparisons.h"
#include "sightline/experiments/suite/suite_results.h"

namespace sightline::experiments {


// One metric of one family: the loss (lower is better) of each solver on each subject.
struct RankingTable {
  std::string kind;    // "camera" or "toy"
  std::string metric;  // visible_pct, cuts, jerk_p99; cost, par2_s
  bool higher_is_better = false;
  std::vector<std::string> solvers;   // the family's solver labels, suite order
  std::vector<std::string> subjects;  // subjects with at least one finished run, suite order
  // loss[subject][solver]: the median over seeds of each finished run's loss (the metric,
  // negated when higher is better; +infinity for a failed, skipped or valueless run).
  std::vector<std::vector<double>> loss;
  // finished[subject][solver]: some run of this solver on this subject has finished.
  std::vector<std::vector<char>> finished;
};

// The tables of every family with runs, camera metrics first.
std::vector<RankingTable> ranking_tables(const Suite& suite, const SuiteOutcome& outcome);

// "### Ranking" for each family with >= 2 solvers and >= 2 complete subjects, then
// "### Wilcoxon signed-rank test" for each requested pair. Empty when neither applies.
std::string ranking_markdown(const Suite& suite, const SuiteOutcome& outcome);

// Rows for stats.csv (no header), kind,subject,solver,profile,metric,statistic,value:
//   <kind>,*,<solver>,-,<metric>,average_rank,<r>
//   <kind>,*,*,-,<metric>,friedman_chi_square|friedman_p|friedman_subjects,<v>
//   <kind>,*,<a> vs <b>,-,<metric>,<statistic>,<v>   with statistic wilcoxon_n,
//                          wilcoxon_w_a_better, wilcoxon_w_b_better, wilcoxon_p
std::string ranking_csv_rows(const Suite& suite, const SuiteOutcome& outcome);

}  // namespace sightline::experiments
