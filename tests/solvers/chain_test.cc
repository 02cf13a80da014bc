// chain against brute force on random small sequences (unary and consecutive-pair tables,
// hard and soft, with and without a stretch constraint), the stretch kind's violation
// against runs counted by hand and its deltas against full evaluation, and the chain's
// refusals.
#include "sightline/solvers/chain.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/csp/brute_force.h"
#include "tests/csp/incremental_check.h"
#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/stretch.h"
#include "sightline/csp/kinds/table.h"
#include "sightline/solvers/registry.h"

namespace sightline::solvers {
namespace {

using csp::VariableId;

// A random chain of `n` variables (2..4 values each) with unary and consecutive-pair tables
// (some hard) and, when `stretch` > 0, a stretch constraint of that minimum over them all.
std::unique_ptr<csp::Problem> random_chain(std::mt19937& rng, std::size_t n, std::size_t stretch,
                                           std::size_t longest = 0) {
  auto p = std::make_unique<csp::Problem>("chain");
  std::uniform_int_distribution<int> size(2, 4), coin(0, 99), cost(0, 6);
  std::vector<std::vector<double>> domains;
  for (std::size_t v = 0; v < n; ++v) {
    std::vector<double> values;
    for (int i = 0, d = size(rng); i < d; ++i) values.push_back(i);
    domains.push_back(values);
    p->add_variable("s" + std::to_string(v), csp::Domain::value_set(values));
  }
  for (std::size_t v = 0; v < n; ++v) {
    std::vector<csp::Table::Entry> entries;
    for (double a : domains[v]) entries.push_back({{a}, double(cost(rng))});
    p->add_constraint(std::make_unique<csp::Table>(std::vector<VariableId>{VariableId(v)}, entries,
                                                   0.0, 1.0, false));
    if (v + 1 == n) continue;
    const bool hard = coin(rng) < 20;
    entries.clear();
    for (double a : domains[v]) {
      for (double b : domains[v + 1]) {
        if (coin(rng) < 60) entries.push_back({{a, b}, hard ? double(coin(rng) < 30) : cost(rng)});
      }
    }
    // Either order of the two variables in the scope.
    const bool reversed = coin(rng) < 30;
    if (reversed) {
      for (auto& e : entries) std::swap(e.values[0], e.values[1]);
    }
    std::vector<VariableId> scope{VariableId(v), VariableId(v + 1)};
    if (reversed) std::swap(scope[0], scope[1]);
    p->add_constraint(std::make_unique<csp::Table>(scope, entries, hard ? 0.0 : cost(rng),
                                                   1.0 + coin(rng) % 3, hard));
  }
  if (stretch > 0) {
    std::vector<VariableId> all(n);
    for (std::size_t v = 0; v < n; ++v) all[v] = VariableId(v);
    p->add_constraint(std::make_unique<csp::StretchConstraint>(all, stretch, 5.0, false, longest));
  }
  return p;
}

SolverResult run_chain(const csp::Problem& p) {
  auto solver = SolverRegistry::global().create("chain");
  EXPECT_EQ(solver->unsuitable_reason(p), "");
  return solver->solve(p, p.default_assignment());
}

TEST(Chain, FindsTheBruteForceOptimumOnRandomChains) {
  std::mt19937 rng(7);
  int feasible = 0;
  for (int round = 0; round < 120; ++round) {
    const std::size_t n = 1 + round % 8;
    // Some with a maximum run length too (at least the minimum).
    const std::size_t min = round % 3 == 0 ? 0 : 1 + round % 4;
    const std::size_t max = min > 0 && round % 2 == 0 ? min + round % 3 : 0;
    auto p = random_chain(rng, n, min, max);
    const auto expected = testing::brute_force_optimum(*p);
    const SolverResult r = run_chain(*p);
    ASSERT_EQ(r.stop, StopReason::kProvenOptimal) << "round " << round;
    ASSERT_EQ(r.feasible(), expected.feasible) << "round " << round;
    if (expected.feasible) {
      ++feasible;
      ASSERT_NEAR(r.cost(), expected.cost, 1e-9) << "round " << round;
    }
    ASSERT_NEAR(p->score(r.best).soft, r.cost(), 1e-12);
  }
  EXPECT_GT(feasible, 80);
}

TEST(Chain, AgreesWithBnbOnLongerChains) {
  std::mt19937 rng(11);
  for (int round = 0; round < 10; ++round) {
    auto p = random_chain(rng, 12, 3);
    const SolverResult r = run_chain(*p);
    const SolverResult b = SolverRegistry::global().create("bnb")->solve(*p, p->default_assignment());
    ASSERT_EQ(b.stop, StopReason::kProvenOptimal);
    ASSERT_EQ(r.feasible(), b.feasible());
    if (r.feasible()) {
      EXPECT_NEAR(r.cost(), b.cost(), 1e-9) << "round " << round;
    }
  }
}

TEST(Chain, RefusesWhatIsNotAChain) {
  csp::Problem p("not a chain");
  for (int v = 0; v < 3; ++v) p.add_variable("x" + std::to_string(v), csp::Domain::integer_range(0, 2));
  p.add_constraint(std::make_unique<csp::Table>(std::vector<VariableId>{0, 2},
                                                std::vector<csp::Table::Entry>{}, 1.0));
  auto chain = SolverRegistry::global().create("chain");
  EXPECT_NE(chain->unsuitable_reason(p).find("consecutive"), std::string::npos);
  EXPECT_THROW(chain->solve(p, p.default_assignment()), std::invalid_argument);

  csp::Problem q("continuous");
  q.add_variable("x", csp::Domain::real_interval(0, 1));
  EXPECT_NE(chain->unsuitable_reason(q).find("continuous"), std::string::npos);

  csp::Problem r("a stretch over part of the sequence");
  for (int v = 0; v < 3; ++v) r.add_variable("x" + std::to_string(v), csp::Domain::integer_range(0, 2));
  r.add_constraint(std::make_unique<csp::StretchConstraint>(std::vector<VariableId>{1, 2}, 2));
  EXPECT_NE(chain->unsuitable_reason(r).find("runs"), std::string::npos);

  auto tight = SolverRegistry::global().create("chain", {{"max_transitions", "10"}});
  csp::Problem big("big");
  big.add_variables("x", 10, csp::Domain::integer_range(0, 9));
  EXPECT_NE(tight->unsuitable_reason(big).find("max_transitions"), std::string::npos);
}

TEST(Stretch, ViolationCountsShortRunsByHand) {
  csp::Problem p("runs");
  p.add_variables("x", 7, csp::Domain::integer_range(0, 3));
  csp::StretchConstraint s({0, 1, 2, 3, 4, 5, 6}, 3);
  // Runs 1 1 1 | 2 | 3 3 | 1: shortfalls 0, 2/3, 1/3, 2/3.
  const std::vector<double> a{1, 1, 1, 2, 3, 3, 1};
  EXPECT_NEAR(s.violation(a), 2.0 / 3 + 1.0 / 3 + 2.0 / 3, 1e-12);
  EXPECT_EQ(s.violation(std::vector<double>{2, 2, 2, 2, 2, 2, 2}), 0.0);
  EXPECT_NEAR(s.violation(std::vector<double>{0, 1, 0, 1, 0, 1, 0}), 7 * 2.0 / 3, 1e-12);
  // With a maximum of 4: one run of 7 is 3 too long (3/4); runs of 3 and 4 cost nothing.
  csp::StretchConstraint bounded({0, 1, 2, 3, 4, 5, 6}, 3, 1, false, 4);
  EXPECT_NEAR(bounded.violation(std::vector<double>{2, 2, 2, 2, 2, 2, 2}), 3.0 / 4, 1e-12);
  EXPECT_NEAR(bounded.violation(std::vector<double>{1, 1, 1, 2, 2, 2, 2}), 0, 1e-12);
}

TEST(Stretch, DeltasMatchFullEvaluation) {
  for (std::size_t min : {1, 2, 3, 5}) {
    csp::Problem p("stretch");
    p.add_variables("x", 12, csp::Domain::integer_range(0, 2));
    std::vector<VariableId> all(12);
    for (VariableId v = 0; v < 12; ++v) all[v] = v;
    p.add_constraint(std::make_unique<csp::StretchConstraint>(all, min, 2.0, false, min == 1 ? 0 : min + 2));
    csp::testing::check_incremental_matches_full(p, 100 + std::uint32_t(min), 400);
  }
}

}  // namespace
}  // namespace sightline::solvers
