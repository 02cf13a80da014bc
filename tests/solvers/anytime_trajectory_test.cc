// The anytime trajectory (SolveContext::want_trajectory, SolverResult::trajectory) of every
// registered discrete solver: points in time order, each better than the one before, the last
// equal to the result's score and at the result's time to best, every point's time within
// the solve; none kept unless asked.
#include <gtest/gtest.h>

#include <random>

#include "sightline/csp/kinds/table.h"
#include "sightline/solvers/registry.h"

namespace sightline::solvers {
namespace {

// 10 variables of 4 values, random binary cost tables: several improvements for a local search.
std::unique_ptr<csp::Problem> random_problem() {
  std::mt19937 rng(5);
  auto p = std::make_unique<csp::Problem>("random tables");
  p->add_variables("x", 10, csp::Domain::integer_range(0, 3));
  std::uniform_int_distribution<int> cost(0, 9), var(0, 9);
  for (int k = 0; k < 25; ++k) {
    csp::VariableId a = static_cast<csp::VariableId>(var(rng)), b = static_cast<csp::VariableId>(var(rng));
    if (a == b) continue;
    std::vector<csp::Table::Entry> entries;
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) entries.push_back({{double(i), double(j)}, double(cost(rng))});
    }
    p->add_constraint(std::make_unique<csp::Table>(std::vector<csp::VariableId>{a, b}, entries, 0.0));
  }
  return p;
}

TEST(AnytimeTrajectory, EveryDiscreteSolverKeepsItsImprovementsInOrderEndingAtItsResult) {
  const auto problem = random_problem();
  int solvers_seen = 0;
  for (const std::string& name : SolverRegistry::global().names()) {
    auto solver = SolverRegistry::global().create(name);
    if (!solver->unsuitable_reason(*problem).empty()) continue;
    SolveContext context;
    context.want_trajectory = true;
    context.limits.max_evaluations = 20000;
    const SolverResult r = solver->solve(*problem, problem->default_assignment(), context);
    ASSERT_FALSE(r.trajectory.empty()) << name;
    for (std::size_t i = 1; i < r.trajectory.size(); ++i) {
      EXPECT_LE(r.trajectory[i - 1].seconds, r.trajectory[i].seconds) << name;
      EXPECT_TRUE(r.trajectory[i].score.better_than(r.trajectory[i - 1].score)) << name << " point " << i;
    }
    const AnytimePoint& last = r.trajectory.back();
    EXPECT_FALSE(last.score.better_than(r.score) || r.score.better_than(last.score)) << name;
    EXPECT_LE(last.seconds, r.wall_seconds + 1e-9) << name;
    // Time and evaluations to best (results.csv's time_to_best_s) are the last point's.
    EXPECT_EQ(r.best_found_seconds, last.seconds) << name;
    EXPECT_EQ(r.evaluations_at_best, last.evaluations) << name;
    // Not asked: nothing kept.
    SolveContext plain = context;
    plain.want_trajectory = false;
    EXPECT_TRUE(solver->solve(*problem, problem->default_assignment(), plain).trajectory.empty()) << name;
    ++solvers_seen;
    std::printf("%-14s %zu points, cost %g at %.4f s\n", name.c_str(), r.trajectory.size(),
                r.score.soft, last.seconds);
  }
  EXPECT_GE(solvers_seen, 5);  // grid, sls, bnb, tabu, lns (chain: not a chain)
}

// A problem every solver solves at once, from its start or its first step (a zero-cost
// assignment: the target): when the best was found is still recorded, and it is the last
// point of the trajectory (lns reaching the target in its greedy start recorded none).
TEST(AnytimeTrajectory, ASolverThatReachesItsTargetAtOnceRecordsWhen) {
  auto p = std::make_unique<csp::Problem>("easy");
  p->add_variables("x", 6, csp::Domain::integer_range(0, 3));
  for (csp::VariableId v = 0; v < 6; ++v) {
    p->add_constraint(std::make_unique<csp::Table>(
        std::vector<csp::VariableId>{v}, std::vector<csp::Table::Entry>{{{0}, 0.0}}, 1.0));
  }
  for (const std::string& name : SolverRegistry::global().names()) {
    auto solver = SolverRegistry::global().create(name);
    if (!solver->unsuitable_reason(*p).empty()) continue;
    for (const bool from_optimum : {false, true}) {
      SolveContext context;
      context.want_trajectory = true;
      context.limits.time_limit_seconds = 0.2;
      const csp::Assignment start = from_optimum ? csp::Assignment(6, 0.0) : p->default_assignment();
      const SolverResult r = solver->solve(*p, start, context);
      ASSERT_FALSE(r.trajectory.empty()) << name;
      EXPECT_EQ(r.cost(), 0) << name;
      const std::string what = name + (from_optimum ? " from the optimum" : " from the middle");
      EXPECT_GE(r.best_found_seconds, 0) << what;
      EXPECT_EQ(r.best_found_seconds, r.trajectory.back().seconds) << what;
      EXPECT_EQ(r.evaluations_at_best, r.trajectory.back().evaluations) << what;
    }
  }
}

TEST(AnytimeTrajectory, APipelinePutsItsStagesImprovementsOnItsOwnClock) {
  const auto problem = random_problem();
  auto pipeline = SolverRegistry::global().create("sls>bnb");
  SolveContext context;
  context.want_trajectory = true;
  context.limits.max_evaluations = 200000;
  const SolverResult r = pipeline->solve(*problem, problem->default_assignment(), context);
  ASSERT_GE(r.trajectory.size(), 2u);
  for (std::size_t i = 1; i < r.trajectory.size(); ++i) {
    EXPECT_LE(r.trajectory[i - 1].seconds, r.trajectory[i].seconds);
    EXPECT_LE(r.trajectory[i - 1].evaluations, r.trajectory[i].evaluations);
    EXPECT_TRUE(r.trajectory[i].score.better_than(r.trajectory[i - 1].score));
  }
  EXPECT_NEAR(r.trajectory.back().score.soft, r.score.soft, 1e-12);
}

}  // namespace
}  // namespace sightline::solvers
