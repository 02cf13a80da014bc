// Tests of constructive placement (solvers/detail/group_placement.h) and of how sls uses it:
// on queens built from three all_differents, the variables placed never share a diagonal
// (checked pair by pair, independently of the counts), the values stay a permutation of
// the pool, the evaluator's running score equals a full evaluation afterwards, groups whose
// constraints cannot retract are refused, and sls solves with and without placement.
#include "sightline/solvers/detail/group_placement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/table.h"
#include "sightline/solvers/registry.h"

namespace sightline::solvers {
namespace {

using csp::AllDifferent;

// n queens, one per column: rows (hard all_different, zero offsets) and both diagonals.
std::unique_ptr<csp::Problem> queens(int n) {
  auto p = std::make_unique<csp::Problem>("queens");
  std::vector<csp::VariableId> q;
  for (int i = 0; i < n; ++i) {
    q.push_back(p->add_variable("q" + std::to_string(i), csp::Domain::integer_range(0, n - 1)));
  }
  std::vector<double> up, down;
  for (int i = 0; i < n; ++i) {
    up.push_back(i);
    down.push_back(-i);
  }
  for (const auto& offsets : {std::vector<double>{}, up, down}) {
    const auto range = csp::key_range_from_domains(*p, q, offsets);
    p->add_constraint(std::make_unique<AllDifferent>(q, offsets, AllDifferent::Measure::kVariables,
                                                     1.0, true, range));
  }
  return p;
}

// Pairs among the first `count` columns that share a row or a diagonal, counted directly.
int attacks_among_first(const csp::Assignment& rows, std::size_t count) {
  int pairs = 0;
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = i + 1; j < count; ++j) {
      const double dr = rows[i] - rows[j], dc = static_cast<double>(j - i);
      pairs += dr == 0 || std::abs(dr) == dc;
    }
  }
  return pairs;
}

TEST(GroupPlacement, PlacedVariablesMakeNothingWorseAndTheScoreStaysExact) {
  for (double attempts : {0.0, 0.5, 3.08, 20.0}) {
    const int n = 300;
    const auto problem = queens(n);
    const auto groups = detail::find_permutation_groups(*problem);
    ASSERT_EQ(groups.size(), 1u);
    const detail::PermutationGroup& g = groups[0];
    csp::Assignment start(n);
    for (int i = 0; i < n; ++i) start[i] = i;  // every queen on one diagonal
    const std::vector<csp::ConstraintId> constant = {g.constraint};
    csp::IncrementalEvaluator evaluator(*problem, start, constant);
    ASSERT_TRUE(detail::can_place_group(evaluator, g));
    detail::Random random(7);
    std::vector<double> pool;
    const auto report = detail::place_group(evaluator, g, attempts, random, pool);

    const csp::Assignment& rows = evaluator.values();
    EXPECT_EQ(report.placed + report.left_over, static_cast<std::size_t>(n));
    EXPECT_LE(report.draws, static_cast<std::uint64_t>(std::ceil(attempts * n)));
    std::vector<double> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, start) << "not a permutation of the pool, attempts " << attempts;
    EXPECT_EQ(attacks_among_first(rows, report.placed), 0) << "attempts " << attempts;
    const csp::Score full = problem->score(rows);
    EXPECT_DOUBLE_EQ(evaluator.score().hard, full.hard) << "attempts " << attempts;
    if (attempts == 0) {
      EXPECT_EQ(rows, start);
    }
    if (attempts >= 3) {
      EXPECT_GT(report.placed, static_cast<std::size_t>(n / 2)) << "attempts " << attempts;
    }
  }
}

TEST(GroupPlacement, IsRefusedWhenAConstraintOnTheGroupCannotRetract) {
  auto problem = queens(6);
  const std::vector<csp::Table::Entry> entries = {{{0, 0}, 1.0}};
  problem->add_constraint(
      std::make_unique<csp::Table>(std::vector<csp::VariableId>{0, 1}, entries, 0.0));
  const auto groups = detail::find_permutation_groups(*problem);
  ASSERT_EQ(groups.size(), 1u);
  csp::IncrementalEvaluator evaluator(*problem, {0, 1, 2, 3, 4, 5});
  EXPECT_FALSE(detail::can_place_group(evaluator, groups[0]));
}

// sls with placement (the default), without it (the greedy-swap start), and with a table
// on two queens (placement refused, the group is shuffled instead): every run ends with a
// solution, checked pair by pair.
TEST(GroupPlacement, SlsSolvesQueensWhetherPlacementRunsOrNot) {
  for (const char* attempts : {"3.08", "0"}) {
    for (bool with_table : {false, true}) {
      const int n = 400;
      auto problem = queens(n);
      if (with_table) {
        const std::vector<csp::Table::Entry> entries = {{{0, 0}, 1.0}};
        problem->add_constraint(
            std::make_unique<csp::Table>(std::vector<csp::VariableId>{0, 1}, entries, 0.0));
      }
      auto sls = SolverRegistry::global().create("sls", {{"placement_attempts", attempts}});
      SolveContext context;
      context.seed = 3;
      const SolverResult r = sls->solve(*problem, problem->default_assignment(), context);
      EXPECT_EQ(r.stop, StopReason::kTargetReached) << attempts << " table " << with_table;
      EXPECT_EQ(attacks_among_first(r.best, n), 0) << attempts << " table " << with_table;
    }
  }
}

TEST(GroupPlacement, SlsWithPlacementGivesTheSameResultForTheSameSeed) {
  const auto problem = queens(300);
  auto sls = SolverRegistry::global().create("sls");
  SolveContext context;
  context.seed = 11;
  const SolverResult a = sls->solve(*problem, problem->default_assignment(), context);
  const SolverResult b = sls->solve(*problem, problem->default_assignment(), context);
  EXPECT_EQ(a.best, b.best);
  EXPECT_EQ(a.evaluations, b.evaluations);
  context.seed = 12;
  const SolverResult c = sls->solve(*problem, problem->default_assignment(), context);
  EXPECT_NE(a.best, c.best);  // the seed drives the placement: another seed, another solution
}

TEST(GroupPlacement, SlsKeepsAStartThatIsAlreadyASolution) {
  // A solution of 8-queens: placement must not re-deal a start that is a permutation.
  const csp::Assignment solution = {0, 4, 7, 5, 2, 6, 1, 3};
  ASSERT_EQ(attacks_among_first(solution, 8), 0);
  const auto problem = queens(8);
  auto sls = SolverRegistry::global().create("sls");
  const SolverResult r = sls->solve(*problem, solution, SolveContext{});
  EXPECT_EQ(r.best, solution);
  EXPECT_EQ(r.stop, StopReason::kTargetReached);
}

}  // namespace
}  // namespace sightline::solvers
