// Tests of the shared ending of every solver: evaluate_fully against Problem::score and
// Problem::breakdown on random problems, finish_result evaluating each constraint once (and
// not at all when handed the solver's own evaluation), and sls handing over the evaluation
// it checked its zero-cost assignment with.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sightline/solvers/sls.h"
#include "sightline/solvers/solver.h"
#include "tests/solvers/test_problems.h"

namespace sightline::solvers {
namespace {

// A constraint that counts its full evaluations.
class Counted : public csp::Constraint {
 public:
  Counted(std::vector<csp::VariableId> scope, double weight, bool hard, int* calls)
      : Constraint(std::move(scope), weight, hard), calls_(calls) {}
  std::string_view kind() const override { return "test.counted"; }
  double violation(std::span<const double> values) const override {
    ++*calls_;
    double sum = 0;
    for (csp::VariableId v : scope()) sum += values[v];
    return std::abs(sum - 3) * 0.1;
  }

 private:
  int* calls_;
};

// Random problems: 6 variables over 0..4, 12 constraints on 1-3 random variables with
// weights like 0.37 and violations like 0.1 x |sum - t| (sums that round), hard or soft.
std::unique_ptr<csp::Problem> random_problem(std::mt19937& rng) {
  auto p = std::make_unique<csp::Problem>("random");
  for (int i = 0; i < 6; ++i) {
    p->add_variable("x" + std::to_string(i), csp::Domain::integer_range(0, 4));
  }
  std::uniform_int_distribution<int> var(0, 5), arity(1, 3), target(0, 9), coin(0, 1);
  std::uniform_real_distribution<double> weight(0.01, 3.7);
  for (int c = 0; c < 12; ++c) {
    std::vector<csp::VariableId> scope;
    for (int k = arity(rng); k > 0; --k) scope.push_back(static_cast<csp::VariableId>(var(rng)));
    std::sort(scope.begin(), scope.end());
    scope.erase(std::unique(scope.begin(), scope.end()), scope.end());
    const double t = target(rng);
    test_problems::add(
        *p, scope,
        [t](const auto& x) {
          double sum = 0;
          for (double v : x) sum += v;
          return 0.1 * std::abs(sum - t);
        },
        weight(rng), coin(rng) == 1);
  }
  return p;
}

TEST(EvaluateFully, GivesProblemScoreBitForBitAndProblemBreakdown) {
  std::mt19937 rng(16);
  std::uniform_int_distribution<int> value(0, 4);
  for (int trial = 0; trial < 60; ++trial) {
    const auto p = random_problem(rng);
    std::vector<double> values(6);
    for (double& v : values) v = value(rng);
    const csp::Score truth = p->score(values);
    const std::vector<csp::ConstraintCost> parts = p->breakdown(values);
    for (bool keep : {true, false}) {
      const FullEvaluation e = evaluate_fully(*p, values, keep);
      EXPECT_EQ(e.score.hard, truth.hard) << "trial " << trial;  // exactly: the same sums
      EXPECT_EQ(e.score.soft, truth.soft) << "trial " << trial;
      if (!keep) {
        EXPECT_TRUE(e.breakdown.empty());
        continue;
      }
      ASSERT_EQ(e.breakdown.size(), parts.size());
      for (std::size_t i = 0; i < parts.size(); ++i) {
        EXPECT_EQ(e.breakdown[i].id, parts[i].id);
        EXPECT_EQ(e.breakdown[i].violation, parts[i].violation);
        EXPECT_EQ(e.breakdown[i].cost, parts[i].cost);
        EXPECT_EQ(e.breakdown[i].hard, parts[i].hard);
      }
    }
  }
}

TEST(FinishResult, EvaluatesEachConstraintOnceForScoreAndBreakdown) {
  csp::Problem p;
  for (int i = 0; i < 3; ++i)
    p.add_variable("x" + std::to_string(i), csp::Domain::integer_range(0, 4));
  int hard_calls = 0, soft_calls = 0;
  p.add_constraint(
      std::make_unique<Counted>(std::vector<csp::VariableId>{0, 1}, 2.0, true, &hard_calls));
  p.add_constraint(
      std::make_unique<Counted>(std::vector<csp::VariableId>{1, 2}, 0.5, false, &soft_calls));
  const std::vector<double> best{4, 1, 0};  // hard: 0.1 x |5 - 3| x 2; soft: 0.1 x 2 x 0.5
  for (bool want_breakdown : {true, false}) {
    hard_calls = soft_calls = 0;
    SolveContext context;
    context.want_breakdown = want_breakdown;
    Budget budget(context.limits);
    SolverResult result;
    result.best = best;
    finish_result(p, context, budget, result);
    EXPECT_EQ(hard_calls, 1);
    EXPECT_EQ(soft_calls, 1);
    EXPECT_DOUBLE_EQ(result.score.hard, 0.4);
    EXPECT_DOUBLE_EQ(result.score.soft, 0.1);
    EXPECT_EQ(result.breakdown.size(), want_breakdown ? 2u : 0u);
    if (want_breakdown) {
      EXPECT_DOUBLE_EQ(result.breakdown[0].cost, 0.4);
      EXPECT_TRUE(result.breakdown[0].hard);
      EXPECT_DOUBLE_EQ(result.breakdown[1].cost, 0.1);
    }
  }
  // Handed the solver's own evaluation, it evaluates nothing and takes it as it is.
  hard_calls = soft_calls = 0;
  SolveContext context;
  Budget budget(context.limits);
  SolverResult result;
  result.best = best;
  FullEvaluation given = evaluate_fully(p, best, true);
  EXPECT_EQ(hard_calls + soft_calls, 2);
  hard_calls = soft_calls = 0;
  finish_result(p, context, budget, result, given);
  EXPECT_EQ(hard_calls + soft_calls, 0);
  EXPECT_EQ(result.score.hard, given.score.hard);
  EXPECT_EQ(result.score.soft, given.score.soft);
  ASSERT_EQ(result.breakdown.size(), 2u);
  EXPECT_EQ(result.breakdown[1].cost, given.breakdown[1].cost);
}

// sls stops on a zero-cost assignment after checking it from scratch, constraint by
// constraint; that evaluation is the result's score and breakdown, so both must be exactly
// those of a fresh evaluation of result.best, and no breakdown when none is wanted.
TEST(SlsSolver, StopsWithTheScoreAndBreakdownOfAFullEvaluationOfItsBest) {
  for (int k : {6, 15, 30}) {
    csp::Problem p;
    std::vector<csp::VariableId> vars;
    for (int i = 0; i < k; ++i) {
      vars.push_back(p.add_variable("v" + std::to_string(i), csp::Domain::integer_range(0, k - 1)));
    }
    p.add_constraint(std::make_unique<csp::AllDifferent>(
        vars, std::vector<double>{}, csp::AllDifferent::Measure::kVariables, 1.0, true));
    for (int i = 0; i < k; ++i) {  // met by the permutation v_i = (i + 2) mod k only
      test_problems::add(
          p, {vars[i]}, [i, k](const auto& v) { return 0.3 * std::abs(v[0] - (i + 2) % k); }, 0.7);
    }
    for (bool want_breakdown : {true, false}) {
      for (std::uint64_t seed : {1u, 2u}) {
        SlsSolver sls("sls", SlsSolver::Options{});
        SolveContext context;
        context.seed = seed;
        context.want_breakdown = want_breakdown;
        const SolverResult r = sls.solve(p, std::vector<double>(k, 0.0), context);
        ASSERT_EQ(r.stop, StopReason::kTargetReached) << "k " << k << ", seed " << seed;
        const csp::Score truth = p.score(r.best);
        EXPECT_EQ(r.score.hard, truth.hard);
        EXPECT_EQ(r.score.soft, truth.soft);
        if (!want_breakdown) {
          EXPECT_TRUE(r.breakdown.empty());
          continue;
        }
        const std::vector<csp::ConstraintCost> parts = p.breakdown(r.best);
        ASSERT_EQ(r.breakdown.size(), parts.size());
        for (std::size_t i = 0; i < parts.size(); ++i) {
          EXPECT_EQ(r.breakdown[i].id, parts[i].id);
          EXPECT_EQ(r.breakdown[i].violation, parts[i].violation);
          EXPECT_EQ(r.breakdown[i].cost, parts[i].cost);
          EXPECT_EQ(r.breakdown[i].hard, parts[i].hard);
        }
      }
    }
  }
}

}  // namespace
}  // namespace sightline::solvers
