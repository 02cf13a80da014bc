// Tests of ceres-refine's guarantees: never worse than its start nor less feasible, from
// random starts and with every phase switched on and off; the back-off along the segment;
// the start kept when optimal; discrete variables kept; deterministic results.
#include <gtest/gtest.h>

#include <random>

#include "sightline/solvers/ceres_refine.h"
#include "tests/solvers/ceres_refine_test_problems.h"

namespace sightline::solvers {
namespace {

using namespace ceres_refine_testing;

// ---------------------------------------------------------------------------------------
// Never worse, never less feasible.

TEST(CeresRefine, NeverWorsensTheScoreNorBreaksAHardConstraintFromRandomStarts) {
  auto problem = guarded_problem();
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> coordinate(-4, 4);
  // Every phase switched on and off: the guarantee must not depend on any of them.
  const std::vector<OptionValues> variants = {
      {},
      {{"guard_hard", "false"}},
      {{"restore_feasibility", "false"}, {"hard_penalty", "0"}},
      {{"smoothing", "0"}, {"backoff_steps", "0"}},
      {{"poll_evaluations", "0"}},
      {{"poll_step", "1"}, {"poll_evaluations", "5000"}, {"hard_penalty", "0"}},
  };
  for (std::size_t variant = 0; variant < variants.size(); ++variant) {
    auto refiner = make_refiner(variants[variant]);
    int improved = 0, feasible_starts = 0, infeasible_starts = 0, restored = 0;
    for (int trial = 0; trial < 100; ++trial) {
      const csp::Assignment start = {coordinate(rng), coordinate(rng)};
      const csp::Score before = problem->score(start);
      const SolverResult r = refiner->solve(*problem, start);
      SCOPED_TRACE("variant " + std::to_string(variant) + " trial " + std::to_string(trial) +
                   ": " + r.brief_report("ceres-refine"));
      ASSERT_TRUE(inside_domains(*problem, r.best));
      const csp::Score after = problem->score(r.best);
      EXPECT_EQ(after.hard, r.score.hard);
      EXPECT_EQ(after.soft, r.score.soft);
      EXPECT_FALSE(before.better_than(after));
      EXPECT_LE(after.hard, before.hard);
      if (before.feasible()) {
        ++feasible_starts;
        EXPECT_TRUE(after.feasible());
      } else {
        ++infeasible_starts;
        restored += after.feasible();
      }
      improved += after.better_than(before);
    }
    // The checks above hold trivially for a solver that returns its start: it must move.
    EXPECT_GT(feasible_starts, 50);
    EXPECT_GT(infeasible_starts, 20);
    if (variant <= 1) {
      EXPECT_EQ(improved, 100) << "variant " << variant;
      // Escaping the disc is always possible, and the restore phase finds the way out.
      EXPECT_EQ(restored, infeasible_starts) << "variant " << variant;
    } else {
      EXPECT_GE(improved, feasible_starts) << "variant " << variant;
    }
  }
}

TEST(CeresRefine, BacksOffAlongTheSegmentWhenTheRefinedPointBreaksAHardConstraint) {
  // Bowl centred at x = 3, hard x <= 1, start 0. Unguarded, Ceres reaches 3 (infeasible);
  // bisecting [0, 3] for the farthest better point ends just below the wall at 1. Known.
  Problem p("wall");
  p.add_variable("x", Domain::real_interval(-5, 5));
  add_jet<Bowl<1>, 1>(p, {0}, Bowl<1>{{3.0}, {1.0}});
  p.add_constraint(
      std::make_unique<HalfSpace>(std::vector<VariableId>{0}, std::vector<double>{1}, 1.0));
  const SolverResult unguarded =
      make_refiner({{"guard_hard", "false"}})->solve(p, csp::Assignment{0.0});
  EXPECT_LE(unguarded.best[0], 1.0) << unguarded.brief_report("ceres-refine");
  EXPECT_GT(unguarded.best[0], 1.0 - 1e-8);
  EXPECT_NE(unguarded.message.find("backed off"), std::string::npos);
  // Guarded, the line search never leaves x <= 1 and ends against the wall.
  const SolverResult guarded = make_refiner()->solve(p, csp::Assignment{0.0});
  EXPECT_TRUE(guarded.feasible());
  EXPECT_GT(guarded.best[0], 0.99) << guarded.brief_report("ceres-refine");
  // No back-off allowed and nothing better on the segment: the start comes back.
  // (The poll, which would then walk to the wall itself, is off.)
  const SolverResult kept =
      make_refiner({{"guard_hard", "false"}, {"backoff_steps", "1"}, {"poll_evaluations", "0"}})
          ->solve(p, csp::Assignment{0.0});
  EXPECT_EQ(kept.best[0], 0.0);
}

TEST(CeresRefine, ReturnsTheStartWhenTheStartIsAlreadyOptimal) {
  auto problem = bowl_problem<2>({1.0, -2.0}, {1.0, 1.0});
  const SolverResult r = make_refiner()->solve(*problem, csp::Assignment{1.0, -2.0});
  EXPECT_EQ(r.best, (csp::Assignment{1.0, -2.0}));
  EXPECT_EQ(r.stop, StopReason::kTargetReached);
}

TEST(CeresRefine, KeepsDiscreteVariablesAtTheirStartValues) {
  auto problem = mixed_problem();
  const csp::Assignment start = {-1.5, 3.0, 0.0, 8.0};
  const SolverResult r = make_refiner()->solve(*problem, start);
  EXPECT_EQ(r.best[1], 3.0);
  EXPECT_TRUE(problem->score(r.best).better_than(problem->score(start)));
  EXPECT_TRUE(inside_domains(*problem, r.best));
}

TEST(CeresRefine, IsDeterministic) {
  auto problem = guarded_problem();
  auto a = make_refiner(), b = make_refiner();
  for (const csp::Assignment& start : {csp::Assignment{-3, 3}, csp::Assignment{3.9, -3.9}}) {
    const SolverResult ra = a->solve(*problem, start), rb = b->solve(*problem, start);
    const SolverResult again = a->solve(*problem, start);
    EXPECT_EQ(ra.best, rb.best);
    EXPECT_EQ(ra.best, again.best);
    EXPECT_EQ(ra.evaluations, again.evaluations);
    EXPECT_EQ(ra.iterations, rb.iterations);
  }
}

}  // namespace
}  // namespace sightline::solvers
