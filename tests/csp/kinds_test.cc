// The built-in kinds not_equal, linear and abs_deviation: their violation against the
// definitions, their incremental states against full re-evaluation, their gradients against
// finite differences, and their registry entries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sightline/csp/kinds/builder.h"
#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/abs_deviation.h"
#include "sightline/csp/kinds/linear.h"
#include "sightline/csp/kinds/not_equal.h"
#include "incremental_check.h"

namespace sightline::csp {
namespace {

using testing::check_incremental_matches_full;

// ---- not_equal -------------------------------------------------------------------------

TEST(NotEqual, IsViolatedExactlyWhenXEqualsYPlusOffset) {
  const NotEqual plain(0, 1);
  const NotEqual shifted(0, 1, 2.0);
  for (double x = -3; x <= 3; ++x) {
    for (double y = -3; y <= 3; ++y) {
      const double v[] = {x, y};
      EXPECT_EQ(plain.violation(v), x == y ? 1.0 : 0.0);
      EXPECT_EQ(shifted.violation(v), x == y + 2 ? 1.0 : 0.0);
    }
  }
  EXPECT_EQ(plain.kind(), "not_equal");
}

TEST(NotEqual, DeltasAndInvolvementMatchFullReEvaluation) {
  // A random graph colouring: 12 nodes, 4 colours, 30 edges with offsets 0 or 1, some hard.
  std::mt19937 rng(11);
  ProblemBuilder b;
  for (int i = 0; i < 12; ++i) b.integer("n" + std::to_string(i), 0, 3);
  std::uniform_int_distribution<VariableId> node(0, 11);
  for (int e = 0; e < 30; ++e) {
    const VariableId a = node(rng);
    VariableId c = node(rng);
    if (c == a) c = (a + 1) % 12;
    b.add(std::make_unique<NotEqual>(a, c, e % 3 == 0 ? 1.0 : 0.0, 1.0 + e % 4, e % 5 == 0));
  }
  const auto p = b.build();
  check_incremental_matches_full(*p, 1, 2000);

  std::mt19937 rng2(3);
  IncrementalEvaluator ev(*p, testing::random_assignment(*p, rng2));
  for (int step = 0; step < 200; ++step) {
    const VariableId v = node(rng2);
    double expected = 0;
    for (const Incidence& inc : p->incidences(v)) {
      const Constraint& c = p->constraint(inc.constraint);
      expected += c.weight() * c.violation(ev.values());
    }
    EXPECT_DOUBLE_EQ(ev.involvement(v), expected);
    ev.assign(v, testing::random_value(p->variable(v).domain, rng2));
  }
}

TEST(NotEqual, RegistryRefusesAScopeOfThree) {
  ProblemBuilder b;
  b.integer("x", 0, 2);
  b.integer("y", 0, 2);
  b.integer("z", 0, 2);
  EXPECT_THROW(b.constrain("not_equal", {"x", "y", "z"}), std::invalid_argument);
  const ConstraintId id = b.constrain("not_equal", {"x", "y"}, spec_from({{"offset", 1}}));
  const auto p = b.build();
  const double v[] = {2, 1, 0};
  EXPECT_EQ(p->constraint(id).violation(v), 1.0);
}

// ---- in, not_in, equals (unary) -------------------------------------------------------------

TEST(ValueSetConstraint, UnaryKindsAgainstMembershipAndTheirDeltas) {
  ProblemBuilder b;
  b.integer("x", 0, 5);
  b.integer("y", 0, 5);
  const ConstraintId in = b.constrain("in", {"x"}, spec_from({{"values", std::vector<double>{1, 4, 2}}}), 3);
  const ConstraintId out = b.constrain("not_in", {"y"}, spec_from({{"values", std::vector<double>{0}}}));
  const ConstraintId eq = b.constrain("equals", {"y"}, spec_from({{"value", 3}}), 1, true);
  EXPECT_THROW(b.constrain("in", {"x", "y"}, spec_from({{"values", std::vector<double>{1}}})),
               std::invalid_argument);
  EXPECT_THROW(b.constrain("in", {"x"}, spec_from({{"values", std::vector<double>{}}})),
               std::invalid_argument);
  EXPECT_THROW(b.constrain("equals", {"x"}), std::invalid_argument);  // no value
  const auto p = b.build();
  for (double x = 0; x <= 5; ++x) {
    for (double y = 0; y <= 5; ++y) {
      const double v[] = {x, y};
      EXPECT_EQ(p->constraint(in).violation(v), (x == 1 || x == 2 || x == 4) ? 0.0 : 1.0);
      EXPECT_EQ(p->constraint(out).violation(v), y == 0 ? 1.0 : 0.0);
      EXPECT_EQ(p->constraint(eq).violation(v), y == 3 ? 0.0 : 1.0);
    }
  }
  EXPECT_EQ(p->constraint(in).kind(), "in");
  check_incremental_matches_full(*p, 5, 300);
}

// ---- linear ---------------------------------------------------------------------------------

TEST(LinearConstraint, ViolationIsTheAmountTheRelationIsBrokenBy) {
  const std::vector<VariableId> scope = {0, 1};
  const std::vector<double> a = {2, -1};
  const LinearConstraint le(scope, a, Relation::kLessEqual, 3);
  const LinearConstraint eq(scope, a, Relation::kEqual, 3);
  const LinearConstraint ge(scope, a, Relation::kGreaterEqual, 3);
  for (double x = -2; x <= 4; x += 0.5) {
    for (double y = -2; y <= 4; y += 0.5) {
      const double v[] = {x, y};
      const double s = 2 * x - y;
      EXPECT_DOUBLE_EQ(le.violation(v), std::max(0.0, s - 3));
      EXPECT_DOUBLE_EQ(eq.violation(v), std::abs(s - 3));
      EXPECT_DOUBLE_EQ(ge.violation(v), std::max(0.0, 3 - s));
    }
  }
}

TEST(LinearConstraint, RelationMayBeWrittenAsSymbolOrWord) {
  const std::pair<const char*, const char*> same[] = {
      {"<=", "le"}, {"=", "eq"}, {"==", "eq"}, {">=", "ge"}};
  for (const auto& [symbol, word] : same) {
    ProblemBuilder b;
    b.integer("x", -5, 5);
    b.constrain("linear", {"x"}, spec_from({{"op", symbol}, {"rhs", 1}}));
    b.constrain("linear", {"x"}, spec_from({{"op", word}, {"rhs", 1}}));
    const auto p = b.build();
    const auto& c = dynamic_cast<const LinearConstraint&>(p->constraint(0));
    EXPECT_EQ(c.relation(), dynamic_cast<const LinearConstraint&>(p->constraint(1)).relation());
    for (double x = -5; x <= 5; ++x) {
      const double v[] = {x};
      EXPECT_EQ(p->constraint(0).violation(v), p->constraint(1).violation(v)) << symbol;
    }
  }
}

TEST(LinearConstraint, RejectsMismatchedOrNonFiniteCoefficients) {
  EXPECT_THROW(LinearConstraint({0, 1}, {1}, Relation::kEqual, 0), std::invalid_argument);
  EXPECT_THROW(LinearConstraint({0}, {std::nan("")}, Relation::kEqual, 0), std::invalid_argument);
}

// A random problem of linear and abs_deviation constraints over integer and real variables,
// some right-hand sides and targets read from parameters.
std::unique_ptr<Problem> random_linear_problem(std::uint32_t seed) {
  std::mt19937 rng(seed);
  ProblemBuilder b("random-linear");
  std::vector<std::string> names;
  for (int i = 0; i < 4; ++i) names.push_back("i" + std::to_string(i));
  for (int i = 0; i < 4; ++i) names.push_back("r" + std::to_string(i));
  for (int i = 0; i < 4; ++i) b.integer(names[i], -3, 3);
  for (int i = 4; i < 8; ++i) b.real(names[i], -2, 2);
  b.parameter("goal", 1.5);
  std::uniform_real_distribution<double> coefficient(-2, 2);
  const char* ops[] = {"<=", "=", ">="};
  for (int k = 0; k < 24; ++k) {
    std::vector<std::string> pool = names;
    std::shuffle(pool.begin(), pool.end(), rng);
    const std::size_t arity = 1 + k % 4;
    std::vector<std::string> scope(pool.begin(), pool.begin() + static_cast<long>(arity));
    std::vector<double> a;
    for (std::size_t i = 0; i < arity; ++i)
      a.push_back(k % 7 == 0 && i == 0 ? 0.0 : coefficient(rng));
    const double weight = 0.5 + k % 3;
    const bool hard = k % 5 == 0;
    Spec params;
    params.set("coefficients", spec_from({{"c", a}}).at("c"));
    if (k % 2 == 0) {
      params.set("op", Spec::string(ops[k % 3]));
      params.set("rhs", k % 4 == 0 ? Spec::string("goal") : Spec::number(coefficient(rng)));
      b.constrain("linear", scope, params, weight, hard);
    } else {
      params.set("constant", Spec::number(coefficient(rng)));
      params.set("target", k % 3 == 0 ? Spec::string("goal") : Spec::number(coefficient(rng)));
      b.constrain("abs_deviation", scope, params, weight, hard);
    }
  }
  return b.build();
}

TEST(LinearConstraint, DeltasMatchFullReEvaluationOnRandomMoves) {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const auto p = random_linear_problem(seed);
    check_incremental_matches_full(*p, seed, 1500);
  }
}

TEST(LinearConstraint, DeltasFollowAParameterChangedBetweenMoves) {
  const auto p = random_linear_problem(9);
  std::mt19937 rng(9);
  IncrementalEvaluator ev(*p, testing::random_assignment(*p, rng));
  p->parameters().set("goal", -0.75);
  // The evaluator's cached violations are stale now; its deltas must not be.
  for (int step = 0; step < 200; ++step) {
    const VariableId v = std::uniform_int_distribution<VariableId>(0, 7)(rng);
    const double value = testing::random_value(p->variable(v).domain, rng);
    Assignment after = ev.values();
    after[v] = value;
    const Score expected = p->score(after) - p->score(ev.values());
    const Score got = ev.delta(v, value);
    ASSERT_NEAR(got.hard, expected.hard, 1e-9);
    ASSERT_NEAR(got.soft, expected.soft, 1e-9);
  }
}

TEST(LinearConstraint, InvolvementIsTheViolationUnlessTheCoefficientIsZero) {
  const LinearConstraint c({0, 1}, {0, 1}, Relation::kLessEqual, 1);
  const double v[] = {5, 3};
  auto state = c.make_incremental_state(v);
  ASSERT_NE(state, nullptr);
  EXPECT_DOUBLE_EQ(state->involvement(v, 0), 0.0);  // x cannot help
  EXPECT_DOUBLE_EQ(state->involvement(v, 1), 2.0);
}

TEST(LinearConstraint, RhsNamingAParameterIsReadAtEveryEvaluation) {
  Parameters table;
  table.add("limit", 3);
  const LinearConstraint c({0}, {1}, Relation::kLessEqual,
                           NumberOrParameter(ParameterRef(&table, 0)));
  const double v[] = {5};
  EXPECT_DOUBLE_EQ(c.violation(v), 2);
  table.set("limit", 4.5);
  EXPECT_DOUBLE_EQ(c.violation(v), 0.5);
}

// ---- gradients -----------------------------------------------------------------------------

// Central differences of `f` along each scope variable.
template <class F>
std::vector<double> finite_differences(const Constraint& c, Assignment x, F f) {
  std::vector<double> g;
  for (VariableId v : c.scope()) {
    const double h = 1e-6;
    const double x0 = x[v];
    x[v] = x0 + h;
    const double up = f(x);
    x[v] = x0 - h;
    const double down = f(x);
    x[v] = x0;
    g.push_back((up - down) / (2 * h));
  }
  return g;
}

TEST(LinearForm, GradientsMatchFiniteDifferencesAwayFromKinks) {
  const auto p = random_linear_problem(4);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> any(-3, 3);
  int checked = 0;
  for (int trial = 0; trial < 100; ++trial) {
    Assignment x(p->num_variables());
    for (double& xi : x) xi = any(rng);  // gradients do not care about integrality
    for (ConstraintId id = 0; id < p->num_constraints(); ++id) {
      const auto& c = dynamic_cast<const LinearForm&>(p->constraint(id));
      ASSERT_TRUE(c.has_exact_gradient());
      const double s = c.sum(x);
      // Stay clear of the kink, where the one-sided slopes differ.
      if (std::abs(c.violation_of_sum(s + 1e-4) + c.violation_of_sum(s - 1e-4) -
                   2 * c.violation_of_sum(s)) > 1e-12) {
        continue;
      }
      std::vector<double> g(c.scope().size());
      const double value = c.violation_and_gradient(x, g);
      EXPECT_DOUBLE_EQ(value, c.violation(x));
      const auto fd = finite_differences(c, x, [&](const Assignment& y) { return c.violation(y); });
      for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(g[i], fd[i], 1e-6);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(LinearForm, GradientAtTheKinkIsTheZeroSubgradient) {
  const AbsDeviation c({0, 1}, {1, 2}, 0.5, 3.5);  // |x + 2y + 0.5 - 3.5|, zero at x + 2y = 3
  const double v[] = {1, 1};
  double g[2] = {7, 7};
  EXPECT_EQ(c.violation_and_gradient(v, g), 0.0);
  EXPECT_EQ(g[0], 0.0);
  EXPECT_EQ(g[1], 0.0);
}

TEST(LinearForm, SmoothedViolationIsZeroWhereTheViolationIsAndHasMatchingGradients) {
  const auto p = random_linear_problem(6);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> any(-3, 3);
  for (int trial = 0; trial < 50; ++trial) {
    Assignment x(p->num_variables());
    for (double& xi : x) xi = any(rng);
    for (ConstraintId id = 0; id < p->num_constraints(); ++id) {
      const Constraint& c = p->constraint(id);
      std::vector<double> g(c.scope().size());
      const double smoothing = 0.3;
      const double smooth = c.smooth_violation_and_gradient(x, g, smoothing);
      const double exact = c.violation(x);
      if (exact == 0) {
        EXPECT_EQ(smooth, 0.0);
      }
      EXPECT_LE(smooth, exact + 1e-12);
      EXPECT_GE(smooth, exact - smoothing - 1e-12);
      std::vector<double> scratch(g.size());
      const auto fd = finite_differences(c, x, [&](const Assignment& y) {
        return c.smooth_violation_and_gradient(y, scratch, smoothing);
      });
      for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(g[i], fd[i], 1e-5);
    }
  }
}

TEST(LinearForm, MinViolationBoundsEveryCompletionAndNeverDecreasesAsVariablesAreAssigned) {
  const auto p = random_linear_problem(8);
  std::mt19937 rng(8);
  const std::size_t n = p->num_variables();
  int tight = 0;
  for (int trial = 0; trial < 200; ++trial) {
    // Assign the variables one at a time in a random order, checking the bound at each stage.
    std::vector<VariableId> order(n);
    for (VariableId v = 0; v < n; ++v) order[v] = v;
    std::shuffle(order.begin(), order.end(), rng);
    const Assignment full = testing::random_assignment(*p, rng);
    Assignment partial(n, 1e6);  // unassigned entries are garbage on purpose
    std::vector<std::uint8_t> assigned(n, 0);
    std::vector<double> previous(p->num_constraints(), 0.0);
    for (std::size_t k = 0; k <= n; ++k) {
      for (ConstraintId id = 0; id < p->num_constraints(); ++id) {
        const Constraint& c = p->constraint(id);
        const double bound = c.min_violation(partial, assigned);
        EXPECT_GE(bound, previous[id] - 1e-12) << "the bound went down";
        previous[id] = bound;
        // Random completions of the partial assignment never beat the bound.
        for (int sample = 0; sample < 5; ++sample) {
          Assignment completion = testing::random_assignment(*p, rng);
          for (VariableId v = 0; v < n; ++v) {
            if (assigned[v]) completion[v] = partial[v];
          }
          EXPECT_GE(c.violation(completion), bound - 1e-12);
        }
        if (k == n) {
          EXPECT_NEAR(bound, c.violation(full), 1e-12);  // exact once all is known
        } else if (bound > 0) {
          ++tight;
        }
      }
      if (k < n) {
        partial[order[k]] = full[order[k]];
        assigned[order[k]] = 1;
      }
    }
  }
  EXPECT_GT(tight, 100) << "the bound should prune before the scope is complete";
}

TEST(LinearForm, MinViolationIsTheClosestSumToTheTargetOverTheBox) {
  // |x + y - 10| with x, y in int[0, 3]: with x = 1 assigned, y <= 3 gives at best 6.
  ProblemBuilder b;
  b.integer("x", 0, 3);
  b.integer("y", 0, 3);
  b.constrain("abs_deviation", {"x", "y"}, spec_from({{"target", 10}}));
  const auto p = b.build();
  const double values[] = {1, 0};
  const std::uint8_t only_x[] = {1, 0};
  const std::uint8_t none[] = {0, 0};
  EXPECT_DOUBLE_EQ(p->constraint(0).min_violation(values, only_x), 6);
  EXPECT_DOUBLE_EQ(p->constraint(0).min_violation(values, none), 4);
}

// ---- abs_deviation --------------------------------------------------------------------------

TEST(AbsDeviation, ViolationIsTheDistanceOfTheSumToItsTarget) {
  const AbsDeviation c({0, 1}, {1, -1}, 0.25, 2);
  for (double x = -2; x <= 2; x += 0.25) {
    for (double y = -2; y <= 2; y += 0.25) {
      const double v[] = {x, y};
      EXPECT_DOUBLE_EQ(c.violation(v), std::abs(x - y + 0.25 - 2));
    }
  }
  EXPECT_EQ(c.kind(), "abs_deviation");
}

TEST(AbsDeviation, DefaultsAreUnitCoefficientsZeroConstantAndZeroTarget) {
  ProblemBuilder b;
  b.real("x", -5, 5);
  b.real("y", -5, 5);
  b.constrain("abs_deviation", {"x", "y"});
  const auto p = b.build();
  const double v[] = {1.5, -4};
  EXPECT_DOUBLE_EQ(p->constraint(0).violation(v), 2.5);
}

TEST(ConstraintKinds, BuiltInKindsAreRegisteredWithTheirFields) {
  const ConstraintKinds& kinds = ConstraintKinds::global();
  for (const char* name : {"not_equal", "linear", "abs_deviation", "expression"}) {
    ASSERT_TRUE(kinds.contains(name)) << name;
    EXPECT_FALSE(kinds.get(name, {}).description.empty()) << name;
  }
  const auto& linear = kinds.get("linear", {});
  EXPECT_EQ(linear.fields, (std::vector<std::string>{"coefficients", "op", "rhs"}));
  try {
    kinds.get("no_such_kind", {"f.yaml", 3, 1});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.yaml:3:1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("abs_deviation"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sightline::csp
