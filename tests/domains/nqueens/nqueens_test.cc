// N-queens, the known answers: the grid counts exactly the 92 solutions of 8-queens (and the
// other small counts), sls solves n = 8, 50 and 1000 with zero conflicts, checked by counting
// attacking pairs directly from the returned rows, not by trusting the solver's cost.
#include "sightline/domains/nqueens/nqueens.h"

#include <gtest/gtest.h>

#include <vector>

#include "sightline/solvers/registry.h"

namespace sightline::nqueens {
namespace {

TEST(NQueens, BuildsOneVariablePerColumnAndThreeHardAllDifferents) {
  const auto p = build_nqueens(5);
  ASSERT_EQ(p->num_variables(), 5u);
  EXPECT_EQ(p->variable(3).name, "q3");
  EXPECT_EQ(p->variable(3).domain.describe(), "int[0,4]");
  ASSERT_EQ(p->num_constraints(), 3u);
  for (csp::ConstraintId c = 0; c < 3; ++c) {
    EXPECT_EQ(p->constraint(c).kind(), "all_different");
    EXPECT_TRUE(p->constraint(c).is_hard());
  }
  EXPECT_THROW(build_nqueens(0), std::invalid_argument);
}

TEST(NQueens, AttackingPairsCountsRowsAndDiagonals) {
  EXPECT_EQ(attacking_pairs(std::vector<double>{1, 3, 0, 2}), 0u);  // a 4-queens solution
  EXPECT_EQ(attacking_pairs(std::vector<double>{0, 0, 0, 0}), 6u);  // one row: 4 choose 2
  EXPECT_EQ(attacking_pairs(std::vector<double>{0, 1, 2, 3}), 6u);  // one diagonal
  EXPECT_EQ(attacking_pairs(std::vector<double>{3, 2, 1, 0}), 6u);  // one anti-diagonal
  EXPECT_EQ(attacking_pairs(std::vector<double>{0, 2, 0, 3}), 2u);  // row 0; (0,0)-(3,3)
}

TEST(NQueens, ZeroHardViolationMeansNoQueenAttacksAnother) {
  // Every 5-queens assignment: the problem's score is 0 exactly when no pair attacks.
  const auto p = build_nqueens(5);
  std::vector<double> rows(5, 0.0);
  for (int code = 0; code < 3125; ++code) {
    int c = code;
    for (double& r : rows) {
      r = c % 5;
      c /= 5;
    }
    EXPECT_EQ(p->score(rows).hard == 0, attacking_pairs(rows) == 0) << code;
  }
}

TEST(NQueens, GridCountsEveryKnownNumberOfSolutionsUpToEightQueens) {
  // OEIS A000170: 1, 0, 0, 2, 10, 4, 40, 92.
  const std::vector<std::uint64_t> known = {2, 10, 4, 40, 92};
  auto grid = solvers::SolverRegistry::global().create("grid");
  for (std::size_t n = 4; n <= 8; ++n) {
    const auto p = build_nqueens(n);
    const solvers::SolverResult r = grid->solve(*p, p->default_assignment());
    EXPECT_EQ(r.stop, solvers::StopReason::kProvenOptimal);
    EXPECT_TRUE(r.feasible()) << n;
    EXPECT_EQ(r.solutions_at_best, known[n - 4]) << n << "-queens";
    EXPECT_EQ(attacking_pairs(r.best), 0u);
  }
}

TEST(NQueens, SlsSolvesEightFiftyAndAThousandQueens) {
  auto sls = solvers::SolverRegistry::global().create("sls");
  for (std::size_t n : {8u, 50u, 1000u}) {
    const auto p = build_nqueens(n);
    for (std::uint64_t seed : {1u, 2u}) {
      solvers::SolveContext context;
      context.seed = seed;
      const solvers::SolverResult r = sls->solve(*p, p->default_assignment(), context);
      EXPECT_EQ(r.stop, solvers::StopReason::kTargetReached) << r.brief_report("sls");
      EXPECT_EQ(attacking_pairs(r.best), 0u) << n << "-queens, seed " << seed;
    }
  }
}

TEST(NQueens, SlsSolvesQueensWithoutTheSwapNeighbourhoodToo) {
  auto sls = solvers::SolverRegistry::global().create("sls", {{"permutation_moves", "false"}});
  for (std::size_t n : {8u, 50u}) {
    const auto p = build_nqueens(n);
    const solvers::SolverResult r = sls->solve(*p, p->default_assignment());
    EXPECT_EQ(r.stop, solvers::StopReason::kTargetReached) << r.brief_report("sls");
    EXPECT_EQ(attacking_pairs(r.best), 0u) << n;
  }
}

}  // namespace
}  // namespace sightline::nqueens
