// Tests of sls and its helpers: the permutation structure it detects, the best keeper's undo
// log against explicit copies, swaps that keep permutations intact, restarts, limits on
// problems it cannot finish, continuous convergence and feasibility, and its options.
#include "sightline/solvers/sls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <string>
#include <type_traits>

#include "sightline/solvers/detail/best_keeper.h"
#include "sightline/solvers/detail/permutation_groups.h"
#include "sightline/solvers/grid.h"
#include "sightline/solvers/registry.h"
#include "tests/solvers/test_problems.h"

namespace sightline::solvers {
namespace {

using csp::AllDifferent;
using test_problems::add;

template <class T>
std::vector<std::remove_const_t<T>> as_vector(std::span<T> items) {
  return {items.begin(), items.end()};
}

std::unique_ptr<csp::AllDifferent> all_different(std::vector<csp::VariableId> scope,
                                                 std::vector<double> offsets = {},
                                                 bool hard = true) {
  return std::make_unique<AllDifferent>(std::move(scope), std::move(offsets),
                                        AllDifferent::Measure::kVariables, 1.0, hard);
}

// `count` variables named prefix0, prefix1, ... over 0..values-1, tied by a hard
// all_different; returns their ids.
std::vector<csp::VariableId> add_all_different_variables(csp::Problem& p, const std::string& prefix,
                                                         int count, int values) {
  std::vector<csp::VariableId> vars;
  for (int i = 0; i < count; ++i) {
    vars.push_back(
        p.add_variable(prefix + std::to_string(i), csp::Domain::integer_range(0, values - 1)));
  }
  p.add_constraint(all_different(vars));
  return vars;
}

// k variables over 0..k-1 tied by a hard all_different, plus soft preferences.
std::unique_ptr<csp::Problem> permutation_problem(int k) {
  auto p = std::make_unique<csp::Problem>("permutation");
  const std::vector<csp::VariableId> vars = add_all_different_variables(*p, "p", k, k);
  // Variable i prefers value (3 i) mod k.
  for (int i = 0; i < k; ++i) {
    add(
        *p, {vars[i]}, [i, k](const auto& v) { return std::abs(v[0] - (3 * i) % k); }, 0.1);
  }
  return p;
}

bool is_permutation_of_range(std::span<const double> values, int k) {
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < k; ++i) {
    if (sorted[i] != i) return false;
  }
  return true;
}

SlsSolver make_sls(const std::function<void(SlsSolver::Options&)>& tweak = {}) {
  SlsSolver::Options o;
  if (tweak) tweak(o);
  EXPECT_EQ(o.validate(), "");
  return SlsSolver("sls", o);
}

TEST(PermutationGroups, AreFoundOnlyForHardZeroOffsetAllDifferentsOverExactlyTheirValues) {
  csp::Problem p;
  std::vector<csp::VariableId> a, b, c;
  for (int i = 0; i < 4; ++i)
    a.push_back(p.add_variable("a" + std::to_string(i), csp::Domain::integer_range(1, 4)));
  for (int i = 0; i < 3; ++i)
    b.push_back(p.add_variable("b" + std::to_string(i), csp::Domain::integer_range(0, 3)));
  for (int i = 0; i < 3; ++i)
    c.push_back(p.add_variable("c" + std::to_string(i), csp::Domain::value_set({2, 5, 9})));
  p.add_constraint(all_different(b));                         // 4 values for 3 variables: no
  p.add_constraint(all_different(a, {0, 1, 2, 3}));           // offsets: no
  p.add_constraint(all_different(c, {}, /*hard=*/false));     // soft: no
  p.add_constraint(all_different(a));                         // yes
  p.add_constraint(all_different(c));                         // yes, value sets too
  p.add_constraint(all_different({a[0], a[1], a[2], a[3]}));  // a is taken already
  const auto groups = detail::find_permutation_groups(p);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(as_vector(groups[0].variables), a);
  EXPECT_EQ(groups[0].values, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(as_vector(groups[1].variables), c);
  EXPECT_EQ(groups[1].values, (std::vector<double>{2, 5, 9}));
}

TEST(PermutationGroups, PinTheVariablesThatHardUnaryConstraintsAllowOneValue) {
  csp::Problem p;
  const std::vector<csp::VariableId> a = add_all_different_variables(p, "a", 5, 5);
  const auto hard = [](csp::Problem& q, csp::VariableId v, auto allowed) {
    add(q, {v}, [allowed](const auto& x) { return allowed(x[0]) ? 0.0 : 1.0; }, 1, true);
  };
  hard(p, a[3], [](double x) { return x == 1; });           // one value: pinned
  hard(p, a[1], [](double x) { return x == 0 || x == 4; });  // two values: free
  add(p, {a[0]}, [](const auto& x) { return x[0] == 2 ? 0.0 : 1.0; });  // soft: free
  auto groups = detail::find_permutation_groups(p);
  ASSERT_EQ(groups.size(), 1u);
  using Pin = std::pair<csp::VariableId, double>;
  EXPECT_EQ(groups[0].pinned, (std::vector<Pin>{{a[3], 1.0}}));
  EXPECT_EQ(as_vector(groups[0].free_variables()),
            (std::vector<csp::VariableId>{a[0], a[1], a[2], a[4]}));
  EXPECT_EQ(as_vector(groups[0].free_values()), (std::vector<double>{0, 2, 3, 4}));

  // Two variables pinned to the same value cannot both hold: no pins at all.
  hard(p, a[2], [](double x) { return x == 1; });
  groups = detail::find_permutation_groups(p);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_TRUE(groups[0].pinned.empty());
  EXPECT_EQ(as_vector(groups[0].free_variables()), a);
  EXPECT_EQ(as_vector(groups[0].free_values()), groups[0].values);
}

TEST(BestKeeper, ReconstructsTheBestFromItsUndoLogLikeAnExplicitCopy) {
  std::mt19937_64 random(5);
  for (std::size_t log_limit : {3u, 50u, 100000u}) {
    csp::Assignment current(20, 0.0);
    detail::BestKeeper keeper;
    keeper.reset(current, {0, 100}, log_limit);
    csp::Assignment expected = current;
    double cost = 100;
    for (int step = 0; step < 5000; ++step) {
      const auto v = static_cast<csp::VariableId>(random() % current.size());
      keeper.log_change(v, current[v]);
      if (step % 3 == 0) keeper.check_log(current);  // before the change ...
      current[v] = static_cast<double>(random() % 7);
      if (step % 3 == 1) keeper.check_log(current);  // ... or after it, as swaps do
      cost += static_cast<double>(random() % 5) - 2.2;
      if (cost < keeper.score().soft) {
        keeper.improved({0, cost});
        expected = current;
      }
      if (step % 997 == 0) {  // a restart materialises in the middle of the search
        keeper.materialise(current);
        ASSERT_EQ(keeper.best(), expected) << "log limit " << log_limit << ", step " << step;
      }
    }
    keeper.materialise(current);
    EXPECT_EQ(keeper.best(), expected) << "log limit " << log_limit;
    EXPECT_EQ(keeper.take_best(), expected) << "log limit " << log_limit;
    EXPECT_TRUE(keeper.best().empty());  // moved out, not copied
  }
}

TEST(SlsSolver, StaysInsidePermutationsWhenTheStructureAllowsSwaps) {
  const auto problem = permutation_problem(30);
  std::vector<double> start(30, 0.0);  // not a permutation: sls must start from one
  for (std::uint64_t limit : {1u, 2u, 20u, 500u}) {
    SlsSolver sls = make_sls();
    SolveContext context;
    context.limits.max_evaluations = limit;
    const SolverResult r = sls.solve(*problem, start, context);
    EXPECT_TRUE(is_permutation_of_range(r.best, 30)) << "after " << limit << " evaluations";
    EXPECT_TRUE(r.feasible());
  }
}

TEST(SlsSolver, FindsThePermutationOptimumThatGridProves) {
  const auto problem = permutation_problem(6);  // 6^6 = 46,656 assignments
  GridSolver grid("grid", {});
  const SolverResult reference = grid.solve(*problem, problem->default_assignment());
  ASSERT_EQ(reference.stop, StopReason::kProvenOptimal);
  for (bool swaps : {true, false}) {
    SlsSolver sls = make_sls([swaps](auto& o) { o.permutation_moves = swaps; });
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SolveContext context;
      context.seed = seed;
      const SolverResult r = sls.solve(*problem, problem->default_assignment(), context);
      EXPECT_TRUE(r.feasible());
      EXPECT_NEAR(r.cost(), reference.cost(), 1e-12) << "swaps " << swaps << ", seed " << seed;
    }
  }
}

TEST(SlsSolver, UsesItsRestartsThenReportsCompletionWhenNoZeroCostExists) {
  const auto problem = test_problems::tiny_discrete_problem();  // optimum cost > 0
  SlsSolver sls = make_sls([](auto& o) {
    o.restarts = 3;
    o.stall_moves = 50;
  });
  const SolverResult r = sls.solve(*problem, problem->default_assignment());
  EXPECT_EQ(r.stop, StopReason::kCompleted);
  EXPECT_NE(r.message.find("3 restarts"), std::string::npos) << r.message;
  EXPECT_GT(r.cost(), 0);
}

TEST(SlsSolver, StopsAtZeroCostOnlyWhenAsked) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::integer_range(0, 9));
  const auto y = p.add_variable("y", csp::Domain::integer_range(0, 9));
  add(p, {x, y}, [](const auto& v) { return std::abs(v[0] + v[1] - 7); });
  SlsSolver stopping = make_sls();
  SolverResult r = stopping.solve(p, std::vector<double>{0, 0});
  EXPECT_EQ(r.stop, StopReason::kTargetReached);
  EXPECT_EQ(r.cost(), 0);
  SlsSolver running = make_sls([](auto& o) {
    o.stop_at_zero = false;
    o.restarts = 2;
    o.stall_moves = 20;
  });
  r = running.solve(p, std::vector<double>{0, 0});
  EXPECT_EQ(r.stop, StopReason::kCompleted);
  EXPECT_EQ(r.cost(), 0);
}

// When sls stops on a zero-cost assignment it has scored that assignment from scratch, and
// reports that score instead of computing it again: it must be the assignment's true score,
// hard and soft parts alike, and the breakdown must agree with it.
TEST(SlsSolver, ReportsTheTrueScoreOfTheAssignmentItStopsOn) {
  for (int k : {5, 12, 40}) {
    csp::Problem p;
    const std::vector<csp::VariableId> vars = add_all_different_variables(p, "v", k, k);
    // A pin (hard unary), and soft wishes that the permutation v_i = (i + 2) mod k meets.
    add(p, {vars[0]}, [](const auto& v) { return v[0] == 2 ? 0.0 : 1.0; }, 1, true);
    for (int i = 1; i < k; ++i) {
      add(p, {vars[i]}, [i, k](const auto& v) { return std::abs(v[0] - (i + 2) % k); }, 0.5);
    }
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SlsSolver sls = make_sls();
      SolveContext context;
      context.seed = seed;
      const SolverResult r = sls.solve(p, std::vector<double>(k, 0.0), context);
      ASSERT_EQ(r.stop, StopReason::kTargetReached) << "k " << k << ", seed " << seed;
      const csp::Score truth = p.score(r.best);
      EXPECT_EQ(r.score.hard, truth.hard);
      EXPECT_EQ(r.score.soft, truth.soft);
      EXPECT_EQ(truth.hard, 0);
      EXPECT_EQ(truth.soft, 0);
      EXPECT_EQ(r.best[vars[0]], 2);
      double breakdown_total = 0;
      for (const csp::ConstraintCost& c : r.breakdown) breakdown_total += c.cost;
      EXPECT_EQ(breakdown_total, 0);
    }
  }
}

TEST(SlsSolver, StopsAtEachLimitOnAProblemItCannotSolve) {
  // 3-queens-like: three variables in 0..1 all different: always one conflict at least.
  csp::Problem p;
  add_all_different_variables(p, "v", 3, 2);
  SlsSolver sls = make_sls([](auto& o) { o.restarts = 1'000'000'000; });
  SolveContext context;
  context.limits.max_evaluations = 777;
  SolverResult r = sls.solve(p, p.default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kEvaluationLimit);
  EXPECT_EQ(r.evaluations, 777u);
  context.limits = {};
  context.limits.max_iterations = 555;
  r = sls.solve(p, p.default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kIterationLimit);
  EXPECT_EQ(r.iterations, 555u);
  context.limits = {};
  context.limits.time_limit_seconds = 0.05;
  r = sls.solve(p, p.default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kTimeLimit);
  EXPECT_LT(r.wall_seconds, 5.0);
  EXPECT_EQ(r.score.hard, 1.0);  // the best possible
}

TEST(SlsSolver, ConvergesOnAContinuousBowlFromAFarCorner) {
  const auto problem = test_problems::tiny_continuous_problem();
  SlsSolver sls = make_sls();
  const SolverResult r = sls.solve(*problem, std::vector<double>{-1, 1});
  EXPECT_NEAR(r.best[0], test_problems::kContinuousOptimum[0], 1e-3);
  EXPECT_NEAR(r.best[1], test_problems::kContinuousOptimum[1], 1e-3);
  EXPECT_EQ(r.stop, StopReason::kCompleted);
}

TEST(SlsSolver, ReachesFeasibilityBeforeCostOnContinuousProblems) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::real_interval(-1, 1));
  const auto y = p.add_variable("y", csp::Domain::real_interval(-1, 1));
  add(p, {x, y}, [](const auto& v) { return v[0] * v[0] + v[1] * v[1]; });
  add(
      p, {x, y}, [](const auto& v) { return std::max(0.0, 0.5 - v[0] - v[1]); }, 1, true);
  SlsSolver sls = make_sls();
  const SolverResult r = sls.solve(p, std::vector<double>{-1, -1});
  EXPECT_TRUE(r.feasible());
  // The feasible optimum is (0.25, 0.25), cost 0.125, on the hard boundary.
  EXPECT_NEAR(r.cost(), 0.125, 1e-4);
}

TEST(SlsSolver, HandlesMixedDiscreteAndContinuousVariables) {
  csp::Problem p;
  const auto k = p.add_variable("k", csp::Domain::integer_range(-20, 20));
  const auto x = p.add_variable("x", csp::Domain::real_interval(-5, 5));
  add(p, {k, x}, [](const auto& v) { return std::abs(v[0] - 13) + std::pow(v[1] - 1.7, 2); });
  SlsSolver sls = make_sls([](auto& o) { o.stop_at_zero = false; });
  const SolverResult r = sls.solve(p, std::vector<double>{-20, -5});
  EXPECT_EQ(r.best[0], 13);
  EXPECT_NEAR(r.best[1], 1.7, 1e-3);
}

TEST(SlsSolver, SamplesValuesOfLargeDomainsAndStillSolves) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::integer_range(0, 1'000'000));
  const auto y = p.add_variable("y", csp::Domain::integer_range(0, 1'000'000));
  add(p, {x, y}, [](const auto& v) { return v[0] < v[1] ? 0.0 : 1.0; });
  add(p, {x}, [](const auto& v) { return v[0] >= 500'000 ? 0.0 : 1.0; });
  SlsSolver sls = make_sls([](auto& o) { o.value_samples = 8; });
  const SolverResult r = sls.solve(p, std::vector<double>{0, 0});
  EXPECT_EQ(r.cost(), 0);
  EXPECT_LE(r.evaluations, 100'000u);
}

TEST(SlsSolver, RejectsBadOptionsNamingTheField) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"walk_probability", "1.5"}, {"tabu_tenure", "-1"}, {"value_samples", "0"},
      {"swap_samples", "0"},       {"restarts", "-2"},    {"shrink", "1"},
      {"initial_radius", "0"},     {"min_radius", "0"},   {"patience", "0"},
      {"greedy_samples", "0"},     {"stall_moves", "-1"}};
  for (const auto& [field, value] : bad) {
    try {
      SolverRegistry::global().create("sls", {{field, value}});
      ADD_FAILURE() << field << "=" << value << " accepted";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
  SlsSolver::Options o;
  o.min_radius = 2 * o.initial_radius;
  EXPECT_NE(o.validate().find("min_radius"), std::string::npos);
}

}  // namespace
}  // namespace sightline::solvers
