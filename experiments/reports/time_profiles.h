// Solved against time, for the problem (toy and WCSP) runs of a suite (issue 14): which runs
// count as solved and when, cactus curves and Dolan-More performance profiles, as CSV.
//
// One definition of "solved" serves PAR-2, the cactus plot, the performance profile and the
// PAR-2 ranking, so the numbers in summary.md, stats.csv, cactus.csv, profiles.csv and the
// report's figures always agree:
//   a run is solved when its status is ok, its answer is feasible (no hard violation), the
//   solver stopped on its own (stop "completed", "proven optimal" or "target reached": an
//   anytime solver stopped by a limit has not solved anything), and its time_s is within the
//   time limit;
//   the time limit is the suite's `problems.limits.time_seconds` when set, else the slowest
//   problem run's time_s (so every run is within it and PAR-2 counts an unsolved run as
//   twice the slowest).
// The performance profile works per instance: a solver's repetitions over seeds are reduced
// to their median time, an unsolved run counting as infinitely slow (so the median run
// decides whether the instance is solved). The cactus curve counts every run (instance x
// seed), which is what "runs solved within t" means.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sightline/experiments/reports/statistics.h"
#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/suite/suite_results.h"

namespace sightline::experiments {

// The problem runs' time limit as defined above (> 0; 1e-6 when every time is 0).
double problem_time_limit(const Suite& suite, const SuiteOutcome& outcome);

// A problem's reference value (`problems: references:`): the value given for its label, else
// the proven optimum of the reference solver's runs on it; nullopt without either.
std::optional<double> problem_reference(const Suite& suite, const SuiteOutcome& outcome,
                                        const std::string& problem_label);

// A problem run as a TimedRun, apart from the time limit (which the scores apply). With a
// reference for its problem: solved when it is feasible with a cost within the suite's
// tolerance of the reference, at its time to best (time_s when the solver records none), so
// anytime solvers on optimisation problems count; without one: solved as defined above
// (feasible and the solver's own stop says so), seconds = time_s (0 when none).
TimedRun problem_timed_run(const Suite& suite, const SuiteOutcome& outcome,
                           const std::vector<std::string>& columns, const RunResult& run);

// The rule above as this suite applies it, in words, for the legends that state it (the
// report's "Solved against time", the summary's PAR-2): "a run is solved when it is
// feasible and its cost is within 1e-09 of its problem's reference value (the suite's
// references:), at its time to best" or the stop rule, and both when some problem may
// have no reference.
std::string solved_rule_text(const Suite& suite);

struct TimeProfiles {
  std::vector<std::string> solvers;    // problem solver labels with at least one run, suite order
  std::vector<std::string> instances;  // problem labels with at least one run, suite order
  double time_limit = 0;
  // Per solver: every run (instance x seed), for the cactus curves and PAR-2.
  std::vector<std::vector<TimedRun>> runs;
  // Per solver: cactus_curve(runs[s], time_limit).
  std::vector<std::vector<CactusPoint>> cactus;
  // ratios[instance][solver]: Dolan-More ratio of the median run (infinite when unsolved, or
  // when the solver has no run on that instance).
  std::vector<std::vector<double>> ratios;
  // The taus where some profile steps (every finite ratio, and 1), ascending.
  std::vector<double> taus;
};

// Empty solvers when the suite has no problem runs.
TimeProfiles problem_time_profiles(const Suite& suite, const SuiteOutcome& outcome);

// cactus.csv: `solver,runs_solved,seconds`, one row per point of each solver's curve (point
// i: i runs solved, each within `seconds`), solvers in suite order. A solver that solved
// nothing has no rows.
std::string cactus_csv(const TimeProfiles& profiles);
// profiles.csv: `solver,tau,fraction`, for each solver one row per tau of profiles.taus:
// rho_s(tau), the fraction of instances whose ratio is <= tau.
std::string profiles_csv(const TimeProfiles& profiles);

}  // namespace sightline::experiments
