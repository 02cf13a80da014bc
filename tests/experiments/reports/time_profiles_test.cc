// Solved against time on hand-made problem runs: what counts as solved, cactus.csv and
// profiles.csv with contents worked out in the comments, and the files beside stats.csv.
#include "sightline/experiments/reports/time_profiles.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sightline/experiments/reports/suite_statistics.h"

namespace sightline::experiments {
namespace {

// Problems p and q, solvers A and B, seeds 1 2 3, time limit 10 s.
Suite two_by_two() {
  Suite suite;
  suite.name = "hand-made";
  for (const char* p : {"p", "q"}) {
    suite.problems.push_back({});
    suite.problems.back().label = p;
  }
  suite.toy_solvers.resize(2);
  suite.toy_solvers[0].label = "A";
  suite.toy_solvers[1].label = "B";
  suite.toy_seeds = {1, 2, 3};
  suite.toy_limits.time_limit_seconds = 10;
  return suite;
}

RunResult run(const Suite& suite, const std::string& problem, const std::string& solver,
              std::uint64_t seed, const std::string& seconds, const std::string& stop,
              const std::string& feasible = "1", const std::string& status = "ok") {
  RunResult r;
  r.kind = "toy";
  r.subject = problem;
  r.solver = solver;
  r.profile = "-";
  r.seed = seed;
  r.status = status;
  const std::vector<std::string> columns = metric_columns(suite);
  r.values.assign(columns.size(), "");
  auto set = [&](const std::string& name, const std::string& text) {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == name) r.values[c] = text;
  };
  set("cost", "0");
  set("feasible", feasible);
  set("time_s", seconds);
  set("stop", stop);
  return r;
}

// A on p: 1 1 1 s, completed.         A on q: 4, 4 (proven optimal), 100 s (over the limit).
// B on p: 2 s, 3 s (target reached), a time-limit stop (unsolved).   B on q: three time-limit
// stops at 10 s.
// Cactus (every run): A solves 1 1 1 4 4; B solves 2 3.
// Profile (median run per instance, unsolved = infinite): p: A 1, B median{2, 3, inf} = 3 ->
// ratios A 1, B 3; q: A median{4, 4, inf} = 4, B unsolved -> A 1, B inf.
// taus {1, 3}: A 1 at both; B 0 at 1, 1/2 at 3.
SuiteOutcome outcome_of(const Suite& suite) {
  SuiteOutcome o;
  o.results = {
      run(suite, "p", "A", 1, "1", "completed"),      run(suite, "p", "A", 2, "1", "completed"),
      run(suite, "p", "A", 3, "1", "completed"),      run(suite, "p", "B", 1, "2", "completed"),
      run(suite, "p", "B", 2, "3", "target reached"), run(suite, "p", "B", 3, "10", "time limit"),
      run(suite, "q", "A", 1, "4", "proven optimal"), run(suite, "q", "A", 2, "4", "completed"),
      run(suite, "q", "A", 3, "100", "completed"),    run(suite, "q", "B", 1, "10", "time limit"),
      run(suite, "q", "B", 2, "10", "time limit"),    run(suite, "q", "B", 3, "10", "time limit")};
  o.total = o.results.size();
  return o;
}

TEST(TimeProfiles, CactusCsvListsEachSolversSolvedRunsByTime) {
  const Suite suite = two_by_two();
  const TimeProfiles p = problem_time_profiles(suite, outcome_of(suite));
  EXPECT_EQ(cactus_csv(p),
            "solver,runs_solved,seconds\n"
            "A,1,1\nA,2,1\nA,3,1\nA,4,4\nA,5,4\n"
            "B,1,2\nB,2,3\n");
}

TEST(TimeProfiles, ProfilesCsvHoldsTheFractionWithinEachTau) {
  const Suite suite = two_by_two();
  const TimeProfiles p = problem_time_profiles(suite, outcome_of(suite));
  ASSERT_EQ(p.taus, (std::vector<double>{1.0, 3.0}));
  EXPECT_EQ(profiles_csv(p),
            "solver,tau,fraction\n"
            "A,1,1\nA,3,1\n"
            "B,1,0\nB,3,0.5\n");
}

TEST(TimeProfiles, InfeasibleFailedOrLimitStoppedRunsAreNotSolved) {
  const Suite suite = two_by_two();
  const std::vector<std::string> columns = metric_columns(suite);
  EXPECT_TRUE(problem_timed_run(suite, {}, columns, run(suite, "p", "A", 1, "1", "completed")).solved);
  EXPECT_TRUE(problem_timed_run(suite, {}, columns, run(suite, "p", "A", 1, "1", "proven optimal")).solved);
  EXPECT_FALSE(problem_timed_run(suite, {}, columns, run(suite, "p", "A", 1, "1", "time limit")).solved);
  EXPECT_FALSE(problem_timed_run(suite, {}, columns, run(suite, "p", "A", 1, "1", "evaluation limit")).solved);
  EXPECT_FALSE(problem_timed_run(suite, {}, columns, run(suite, "p", "A", 1, "1", "completed", "0")).solved);
  EXPECT_FALSE(
      problem_timed_run(suite, {}, columns, run(suite, "p", "A", 1, "1", "completed", "1", "failed")).solved);
  EXPECT_DOUBLE_EQ(problem_timed_run(suite, {}, columns, run(suite, "p", "A", 1, "2.5", "completed")).seconds,
                   2.5);
}

// With reference values, an optimisation run is solved when it reaches its problem's
// reference within the tolerance, at its time to best, whatever stopped it: a time-limited
// anytime run that found the optimum counts; one that did not, does not.
TEST(TimeProfiles, RunsReachingTheReferenceAreSolvedAtTheirTimeToBest) {
  Suite suite = two_by_two();
  suite.references["p"] = 5;
  suite.reference_tolerance = 0.5;
  const std::vector<std::string> columns = metric_columns(suite);
  auto with = [&](RunResult r, const std::string& cost, const std::string& to_best) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c] == "cost") r.values[c] = cost;
      if (columns[c] == "time_to_best_s") r.values[c] = to_best;
    }
    return r;
  };
  const TimedRun reached =
      problem_timed_run(suite, {}, columns, with(run(suite, "p", "A", 1, "10", "time limit"), "5.4", "2.5"));
  EXPECT_TRUE(reached.solved);
  EXPECT_DOUBLE_EQ(reached.seconds, 2.5);
  EXPECT_FALSE(problem_timed_run(suite, {}, columns,
                                 with(run(suite, "p", "A", 1, "10", "time limit"), "6", "1")).solved);
  // Without a time to best, the run's time.
  EXPECT_DOUBLE_EQ(problem_timed_run(suite, {}, columns,
                                     with(run(suite, "p", "A", 1, "7", "completed"), "5", "")).seconds, 7);
  // q has no value: the reference solver's proven optimum stands in.
  suite.reference_from = "B";
  SuiteOutcome outcome;
  outcome.results = {with(run(suite, "q", "B", 1, "3", "proven optimal"), "2", "")};
  EXPECT_EQ(problem_reference(suite, outcome, "q"), 2.0);
  EXPECT_TRUE(problem_timed_run(suite, outcome, columns,
                                with(run(suite, "q", "A", 1, "9", "time limit"), "2", "0.5")).solved);
  EXPECT_FALSE(problem_reference(suite, {}, "q").has_value());
}

// Without a suite time limit the slowest problem run (100 s) is the limit, so A's 100 s run
// on q now counts: A solves 1 1 1 4 4 100.
TEST(TimeProfiles, WithoutATimeLimitTheSlowestRunSetsIt) {
  Suite suite = two_by_two();
  suite.toy_limits.time_limit_seconds = 0;
  const SuiteOutcome o = outcome_of(suite);
  EXPECT_DOUBLE_EQ(problem_time_limit(suite, o), 100.0);
  const TimeProfiles p = problem_time_profiles(suite, o);
  ASSERT_EQ(p.cactus[0].size(), 6u);
  EXPECT_DOUBLE_EQ(p.cactus[0].back().seconds, 100.0);
}

TEST(TimeProfiles, ProblemSuitesWriteCactusAndProfilesBesideStats) {
  const Suite suite = two_by_two();
  const auto files = statistics_files(suite, outcome_of(suite));
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].first, "stats.csv");
  EXPECT_EQ(files[1].first, "cactus.csv");
  EXPECT_EQ(files[1].second, cactus_csv(problem_time_profiles(suite, outcome_of(suite))));
  EXPECT_EQ(files[2].first, "profiles.csv");
  // No problem runs: stats.csv only.
  EXPECT_EQ(statistics_files(suite, SuiteOutcome{}).size(), 1u);
}

}  // namespace
}  // namespace sightline::experiments
