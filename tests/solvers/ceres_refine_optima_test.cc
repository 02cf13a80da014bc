// Tests of ceres-refine against known optima: quadratic bowls inside and outside the box,
// Rosenbrock within bounds and on an active bound, absolute deviations (kinked), an
// expression constraint, a constrained optimum on a hard wall, and after coarse solvers in
// pipelines.
#include <gtest/gtest.h>

#include <random>

#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/kinds/expression.h"
#include "sightline/solvers/ceres_refine.h"
#include "tests/solvers/ceres_refine_test_problems.h"

namespace sightline::solvers {
namespace {

using namespace ceres_refine_testing;

// ---------------------------------------------------------------------------------------
// Known optima of smooth problems.

template <int N>
void expect_bowls_minimum_found(std::mt19937_64& rng, double centre_spread) {
  std::uniform_real_distribution<double> coordinate(-5, 5), spread(-centre_spread, centre_spread),
      curvature(0.2, 20);
  auto refiner = make_refiner();
  for (int trial = 0; trial < 10; ++trial) {
    std::array<double, N> centre, weights;
    for (int i = 0; i < N; ++i) {
      centre[i] = spread(rng);
      weights[i] = curvature(rng);
    }
    auto problem = bowl_problem<N>(centre, weights);
    csp::Assignment start(N);
    for (auto& x : start) x = coordinate(rng);
    const SolverResult r = refiner->solve(*problem, start);
    ASSERT_TRUE(inside_domains(*problem, r.best));
    for (int i = 0; i < N; ++i) {
      // The bowl is separable, so the box optimum is the centre clamped to the box.
      EXPECT_NEAR(r.best[i], std::clamp(centre[i], -5.0, 5.0), 1e-5)
          << N << " dims, trial " << trial << ", " << r.brief_report("ceres-refine");
    }
  }
}

TEST(CeresRefine, ReachesTheCentreOfQuadraticBowlsInOneToFiveDimensions) {
  std::mt19937_64 rng(11);
  expect_bowls_minimum_found<1>(rng, 4.5);
  expect_bowls_minimum_found<2>(rng, 4.5);
  expect_bowls_minimum_found<3>(rng, 4.5);
  expect_bowls_minimum_found<4>(rng, 4.5);
  expect_bowls_minimum_found<5>(rng, 4.5);
}

TEST(CeresRefine, StopsOnTheBoxWhenTheBowlsCentreIsOutsideIt) {
  std::mt19937_64 rng(12);
  expect_bowls_minimum_found<2>(rng, 12);
  expect_bowls_minimum_found<5>(rng, 12);
}

TEST(CeresRefine, ReachesTheBowlsCentreWithEveryLineSearchDirection) {
  auto problem = bowl_problem<3>({1.0, -2.0, 0.5}, {1.0, 4.0, 0.5});
  for (const char* direction : {"lbfgs", "bfgs", "nonlinear_cg", "steepest_descent"}) {
    const SolverResult r =
        make_refiner({{"line_search_direction", direction}, {"max_iterations", "2000"}})
            ->solve(*problem, csp::Assignment{-4.0, 4.0, 4.0});
    EXPECT_NEAR(r.best[0], 1.0, 1e-4) << direction << ": " << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[1], -2.0, 1e-4) << direction;
    EXPECT_NEAR(r.best[2], 0.5, 1e-4) << direction;
  }
}

TEST(CeresRefine, ReachesTheRosenbrockMinimumWithinBounds) {
  Problem p("rosenbrock");
  p.add_variable("x", Domain::real_interval(-2, 2));
  p.add_variable("y", Domain::real_interval(-2, 2));
  add_jet<Rosenbrock, 2>(p, {0, 1}, Rosenbrock{});
  const SolverResult r =
      make_refiner({{"max_iterations", "500"}})->solve(p, csp::Assignment{-1.2, 1.0});
  EXPECT_NEAR(r.best[0], 1.0, 1e-4) << r.brief_report("ceres-refine");
  EXPECT_NEAR(r.best[1], 1.0, 1e-4);
  EXPECT_LT(r.cost(), 1e-8);
}

TEST(CeresRefine, ReachesTheRosenbrockMinimumOnAnActiveBound) {
  // With x <= 0.5 the minimum is on the bound: y = x^2 there, so (0.5, 0.25), cost 0.25.
  Problem p("rosenbrock-cut");
  p.add_variable("x", Domain::real_interval(-2, 0.5));
  p.add_variable("y", Domain::real_interval(-2, 2));
  add_jet<Rosenbrock, 2>(p, {0, 1}, Rosenbrock{});
  const SolverResult r =
      make_refiner({{"max_iterations", "500"}})->solve(p, csp::Assignment{-1.2, 1.0});
  EXPECT_NEAR(r.best[0], 0.5, 1e-4) << r.brief_report("ceres-refine");
  EXPECT_NEAR(r.best[1], 0.25, 1e-4);
  EXPECT_NEAR(r.cost(), 0.25, 1e-6);
}

TEST(CeresRefine, ReachesTheUniqueOptimumOfAbsoluteDeviations) {
  // 1 |x - 1| + 1 |x - 2| + 1 |x - 4| + 3 |y - x| + 1 |x + y + z - 7| (abs_deviation kind).
  // x's three terms are minimised at their median x = 2 (slope -1 + ... changes sign only
  // there, and the other terms can be zeroed at x = 2: y = 2, z = 3): unique optimum, cost 3.
  Problem p("medians");
  p.add_variable("x", Domain::real_interval(-10, 10));
  p.add_variable("y", Domain::real_interval(-10, 10));
  p.add_variable("z", Domain::real_interval(-10, 10));
  auto deviation = [&](std::vector<VariableId> scope, std::vector<double> a, double target,
                       double weight) {
    p.add_constraint(std::make_unique<csp::AbsDeviation>(std::move(scope), std::move(a), 0.0,
                                                         csp::NumberOrParameter(target), weight));
  };
  deviation({0}, {1}, 1, 1);
  deviation({0}, {1}, 2, 1);
  deviation({0}, {1}, 4, 1);
  deviation({1, 0}, {1, -1}, 0, 3);
  deviation({0, 1, 2}, {1, 1, 1}, 7, 1);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-10, 10);
  auto refiner = make_refiner({{"max_iterations", "300"}});
  for (int trial = 0; trial < 10; ++trial) {
    const csp::Assignment start = {coordinate(rng), coordinate(rng), coordinate(rng)};
    const SolverResult r = refiner->solve(p, start);
    EXPECT_NEAR(r.best[0], 2.0, 1e-3) << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[1], 2.0, 1e-3);
    EXPECT_NEAR(r.best[2], 3.0, 1e-3);
    EXPECT_NEAR(r.cost(), 3.0, 1e-3);
  }
}

// ---------------------------------------------------------------------------------------
// User-defined constraints and pipelines.

TEST(CeresRefine, RefinesAnExpressionConstraintThroughFiniteDifferences) {
  // (x - 1.5)^2 + (y + 0.5)^2 written as a formula: no exact gradient, same optimum.
  Problem p("expression");
  p.add_variable("x", Domain::real_interval(-3, 3));
  p.add_variable("y", Domain::real_interval(-3, 3));
  p.add_constraint(std::make_unique<csp::ExpressionConstraint>(
      std::vector<VariableId>{0, 1}, std::vector<std::string>{"x", "y"},
      "(x - 1.5)^2 + (y + 0.5)^2", &p.parameters()));
  ASSERT_FALSE(p.constraint(0).has_exact_gradient());
  const SolverResult r = make_refiner()->solve(p, csp::Assignment{-2.0, 2.5});
  EXPECT_NEAR(r.best[0], 1.5, 1e-4) << r.brief_report("ceres-refine");
  EXPECT_NEAR(r.best[1], -0.5, 1e-4);
}

TEST(CeresRefine, SlidesAlongAWallToTheConstrainedOptimum) {
  // Isotropic bowl centred at (0.5, 0) inside a hard disc of radius 1 around the origin: the
  // constrained optimum is the disc's point nearest the bowl's centre, (1, 0), cost 0.25.
  // The guarded search stops where it first meets the wall; the slide phase follows it.
  Problem p("slide");
  p.add_variable("x", Domain::real_interval(-3, 3));
  p.add_variable("y", Domain::real_interval(-3, 3));
  add_jet<Bowl<2>, 2>(p, {0, 1}, Bowl<2>{{0.5, 0.0}, {1.0, 1.0}});
  p.add_constraint(std::make_unique<DiscExclusion>(0, 1, 0.0, 0.0, 1.0));
  for (const csp::Assignment& start :
       {csp::Assignment{-0.5, 2.0}, csp::Assignment{2.5, -2.5}, csp::Assignment{-1.5, -0.3}}) {
    const SolverResult r = make_refiner()->solve(p, start);
    EXPECT_TRUE(r.feasible()) << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[0], 1.0, 1e-4) << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[1], 0.0, 1e-4);
    // Without the slide phase (and the poll, which also follows walls) it stalls on the wall
    // somewhere else (the reason they exist).
    const SolverResult stalled =
        make_refiner({{"hard_penalty", "0"}, {"poll_evaluations", "0"}})->solve(p, start);
    EXPECT_TRUE(stalled.feasible());
    EXPECT_GT(stalled.cost(), r.cost() + 1e-3) << stalled.brief_report("no slide");
  }
}

TEST(CeresRefine, AfterACoarseSolverInAPipelineIsBetterAndLocallyOptimal) {
  auto problem = guarded_problem();
  for (const std::string coarse_name : {"grid", "sliding-octree"}) {
    auto coarse = SolverRegistry::global().create(coarse_name);
    auto pipeline = SolverRegistry::global().create(coarse_name + ">ceres-refine");
    const csp::Assignment start = problem->default_assignment();
    const SolverResult alone = coarse->solve(*problem, start);
    const SolverResult refined = pipeline->solve(*problem, start);
    SCOPED_TRACE(alone.brief_report(coarse_name) + "\n" +
                 refined.brief_report(coarse_name + ">ceres-refine"));
    EXPECT_FALSE(alone.score.better_than(refined.score));
    EXPECT_TRUE(refined.feasible());
    // The coarse solvers miss the kinked optimum on the disc's edge; refinement finds it:
    // no feasible point within 0.1 (a 0.5 mm lattice) is better by more than 1e-6.
    EXPECT_LT(refined.cost(), alone.cost() - 1e-3);
    EXPECT_GT(best_nearby(*problem, refined.best, 200, 0.0005), refined.cost() - 1e-6);
  }
}

TEST(CeresRefine, FindsTheKnownOptimumOfTheShelfExampleAfterEveryCoarseSolver) {
  // examples/problems/shelf.yaml: L1 wishes (abs_deviation), a hard budget (linear), an
  // expression hinge; known unique optimum x = 0.7, y = 4, z = 1.2, cost 2.3.
  const auto problem =
      csp::read_problem_file(std::string(SIGHTLINE_SOURCE_DIR) + "/examples/problems/shelf.yaml");
  for (const std::string name : {"ceres-refine", "grid>ceres-refine", "sliding-octree>ceres-refine",
                                 "sls>ceres-refine"}) {
    const SolverResult r = SolverRegistry::global().create(name)->solve(
        *problem, problem->default_assignment());
    SCOPED_TRACE(r.brief_report(name));
    EXPECT_TRUE(r.feasible());
    EXPECT_NEAR(r.cost(), 2.3, 1e-4);
    EXPECT_NEAR(r.best[0], 0.7, 1e-3);
    EXPECT_NEAR(r.best[1], 4.0, 1e-3);
    EXPECT_NEAR(r.best[2], 1.2, 1e-3);
  }
}

}  // namespace
}  // namespace sightline::solvers
