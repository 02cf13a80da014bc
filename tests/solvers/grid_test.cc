// Tests of the grid solver: against brute-force enumeration written independently here,
// the lattice's endpoints, mixed problems, exact tie counts, the size guard and the limits.
#include "sightline/solvers/grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sightline/solvers/registry.h"
#include "tests/solvers/test_problems.h"

namespace sightline::solvers {
namespace {

using test_problems::add;

GridSolver make_grid(std::int64_t points = 11, std::int64_t max_points = 100'000'000) {
  GridSolver::Options o;
  o.points = points;
  o.max_points = max_points;
  return GridSolver("grid", o);
}

TEST(GridSolver, MatchesBruteForceOnEveryDiscreteCombination) {
  const auto problem = test_problems::tiny_discrete_problem();
  // Brute force: nested loops over the four domains, scored from scratch.
  csp::Score best{1e300, 1e300};
  std::uint64_t ties = 0;
  csp::Assignment x(4);
  const auto& d3 = problem->variable(3).domain;
  for (x[0] = 0; x[0] <= 3; ++x[0]) {
    for (x[1] = 0; x[1] <= 3; ++x[1]) {
      for (x[2] = 0; x[2] <= 3; ++x[2]) {
        for (std::size_t k = 0; k < d3.size(); ++k) {
          x[3] = d3.value_at(k);
          const csp::Score s = problem->score(x);
          if (s.better_than(best)) {
            best = s;
            ties = 1;
          } else if (!best.better_than(s)) {
            ++ties;
          }
        }
      }
    }
  }
  GridSolver grid = make_grid();
  const SolverResult r = grid.solve(*problem, problem->default_assignment());
  EXPECT_EQ(r.stop, StopReason::kProvenOptimal);
  EXPECT_EQ(r.evaluations, 256u);
  EXPECT_DOUBLE_EQ(r.score.hard, best.hard);
  EXPECT_DOUBLE_EQ(r.score.soft, best.soft);
  EXPECT_EQ(r.solutions_at_best, ties);
  EXPECT_EQ(r.breakdown.size(), problem->num_constraints());
}

TEST(GridSolver, LatticeIncludesBothEndpointsOfAContinuousDomain) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::real_interval(0.25, 1.75));
  add(p, {x}, [](const auto& v) { return (v[0] - 5) * (v[0] - 5); });  // best at the top end
  GridSolver grid = make_grid(3);
  const SolverResult r = grid.solve(p, p.default_assignment());
  EXPECT_EQ(r.evaluations, 3u);
  EXPECT_EQ(r.best[0], 1.75);  // exactly the bound
  EXPECT_EQ(r.stop, StopReason::kCompleted) << "a lattice proves nothing about the continuum";
  csp::Problem q;
  const auto y = q.add_variable("y", csp::Domain::real_interval(0.25, 1.75));
  add(q, {y}, [](const auto& v) { return (v[0] + 5) * (v[0] + 5); });  // best at the bottom end
  EXPECT_EQ(grid.solve(q, q.default_assignment()).best[0], 0.25);
}

TEST(GridSolver, CrossesDiscreteValuesWithTheContinuousLattice) {
  csp::Problem p;
  const auto k = p.add_variable("k", csp::Domain::value_set({-2, 1, 4}));
  const auto x = p.add_variable("x", csp::Domain::real_interval(0, 1));
  // Lattice x in {0, .25, .5, .75, 1}; the best pair is k = 1, x = 0.75 (cost 0.0025 + 0).
  add(p, {k, x}, [](const auto& v) { return std::pow(v[1] - 0.7, 2) + std::abs(v[0] - 1); });
  GridSolver grid = make_grid(5);
  const SolverResult r = grid.solve(p, p.default_assignment());
  EXPECT_EQ(r.evaluations, 15u);
  EXPECT_EQ(r.best, (csp::Assignment{1, 0.75}));
  EXPECT_EQ(r.solutions_at_best, 1u);
}

TEST(GridSolver, CountsTiesOnRealValuedCostsExactly) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::real_interval(-1, 1));
  const auto y = p.add_variable("y", csp::Domain::real_interval(-1, 1));
  // Symmetric in x and in y: with 4 points {-1, -1/3, 1/3, 1} the best is (+-1/3, +-1/3),
  // four ties, whatever round-off the incremental sums carry.
  add(p, {x}, [](const auto& v) { return 0.1 * v[0] * v[0] + 0.3; });
  add(p, {y}, [](const auto& v) { return 0.7 * v[0] * v[0] + 0.1; });
  add(p, {x, y}, [](const auto& v) { return 0.2 * v[0] * v[0] * v[1] * v[1]; });
  GridSolver grid = make_grid(4);
  EXPECT_EQ(grid.solve(p, p.default_assignment()).solutions_at_best, 4u);
}

TEST(GridSolver, DeclaresLatticesAboveMaxPointsUnsuitableAndRefusesThem) {
  const auto problem = test_problems::tiny_discrete_problem();  // 256 points
  GridSolver grid = make_grid(11, 255);
  const std::string why = grid.unsuitable_reason(*problem);
  EXPECT_NE(why.find("256"), std::string::npos) << why;
  EXPECT_NE(why.find("max_points"), std::string::npos) << why;
  EXPECT_THROW(grid.solve(*problem, problem->default_assignment()), GridTooLarge);
  EXPECT_EQ(make_grid(11, 256).unsuitable_reason(*problem), "");
}

TEST(GridSolver, StopsAtAnEvaluationLimitWithoutClaimingToBeExhaustive) {
  const auto problem = test_problems::tiny_discrete_problem();
  GridSolver grid = make_grid();
  SolveContext context;
  context.limits.max_evaluations = 100;
  const SolverResult r = grid.solve(*problem, problem->default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kEvaluationLimit);
  EXPECT_EQ(r.evaluations, 100u);
  EXPECT_EQ(r.solutions_at_best, 0u) << "a partial count is not a count";
  EXPECT_NE(r.message.find("100 of 256"), std::string::npos) << r.message;
}

TEST(GridSolver, StopsAtATimeLimitOnAnEnormousLattice) {
  csp::Problem p;
  std::vector<csp::VariableId> vars;
  for (int i = 0; i < 12; ++i) {
    vars.push_back(p.add_variable("x" + std::to_string(i), csp::Domain::integer_range(0, 9)));
  }
  add(p, vars, [](const auto& v) { return v[0] + v[11]; });
  GridSolver grid = make_grid(11, 1'000'000'000'000'000);  // 10^12 points: hours of work
  SolveContext context;
  context.limits.time_limit_seconds = 0.05;
  const SolverResult r = grid.solve(p, p.default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kTimeLimit);
  EXPECT_LT(r.wall_seconds, 5.0);
  EXPECT_EQ(r.cost(), 0.0);  // (0, ..., 0) is the first point visited
}

TEST(GridSolver, RejectsOptionsOutsideTheirRangeNamingThem) {
  for (const char* field : {"points", "max_points"}) {
    try {
      SolverRegistry::global().create("grid", {{field, "0"}});
      ADD_FAILURE() << field << "=0 accepted";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
  GridSolver::Options o;
  o.points = 0;
  EXPECT_NE(o.validate().find("points"), std::string::npos);
}

}  // namespace
}  // namespace sightline::solvers
