#include "sightline/csp/problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "sightline/csp/kinds/abs_deviation.h"
#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/linear.h"
#include "sightline/csp/kinds/not_equal.h"
#include "bounded_score_check.h"
#include "incremental_check.h"

namespace sightline::csp {
namespace {

// x, y, z in 0..3; hard x != y; soft (weight 2) x + y + z <= 4; soft (weight 0.5) |z - 3|.
std::unique_ptr<Problem> small_problem() {
  auto p = std::make_unique<Problem>("small");
  const VariableId x = p->add_variable("x", Domain::integer_range(0, 3));
  const VariableId y = p->add_variable("y", Domain::integer_range(0, 3));
  const VariableId z = p->add_variable("z", Domain::integer_range(0, 3));
  p->add_constraint(std::make_unique<NotEqual>(x, y, 0, 1, true));
  p->add_constraint(std::make_unique<LinearConstraint>(std::vector<VariableId>{x, y, z},
                                                       std::vector<double>{1, 1, 1},
                                                       Relation::kLessEqual, 4, 2.0));
  p->add_constraint(std::make_unique<AbsDeviation>(std::vector<VariableId>{z},
                                                   std::vector<double>{1}, 0, 3, 0.5));
  return p;
}

TEST(Problem, ScoreSeparatesHardViolationFromSoftCost) {
  const auto p = small_problem();
  // x = y = 2, z = 1: x != y broken (hard 1); sum 5 > 4 by 1 (soft 2); |1 - 3| = 2 (soft 1).
  const Assignment a = {2, 2, 1};
  const Score s = p->score(a);
  EXPECT_DOUBLE_EQ(s.hard, 1.0);
  EXPECT_DOUBLE_EQ(s.soft, 3.0);
  EXPECT_FALSE(p->is_feasible(a));
  EXPECT_DOUBLE_EQ(p->cost(a), 3.0);
  const Assignment good = {0, 1, 3};
  EXPECT_TRUE(p->is_feasible(good));
  EXPECT_DOUBLE_EQ(p->cost(good), 0.0);
}

// A constraint that counts its calls and says it asks an outside world (query_cost 1): the
// violation |x - target| x scale, real-valued so sums round.
class QueriedDistance : public Constraint {
 public:
  QueriedDistance(VariableId x, double target, double scale, double weight, bool hard, int* calls)
      : Constraint({x}, weight, hard), target_(target), scale_(scale), calls_(calls) {}
  std::string_view kind() const override { return "test.queried"; }
  double query_cost() const override { return 1; }
  double violation(std::span<const double> values) const override {
    ++*calls_;
    return std::abs(values[scope()[0]] - target_) * scale_;
  }

 private:
  double target_, scale_;
  int* calls_;
};

// score_below against score on random assignments of a problem mixing constraints with and
// without queries, hard and soft, with bounds just above, at and below each score and far
// from it: a complete answer is score() to the bit; an incomplete one is at least the bound
// and no more than score() (so comparing with the bound decides as score() does), and asked
// none of the queried constraints.
TEST(Problem, ScoreBelowDecidesAsTheFullScoreWithFewerQueries) {
  Problem p("mixed");
  std::vector<VariableId> v;
  for (int i = 0; i < 4; ++i) v.push_back(p.add_variable("v" + std::to_string(i), Domain::real_interval(-3, 3)));
  int calls = 0;
  p.add_constraint(std::make_unique<QueriedDistance>(v[0], 0.3, 1.7, 0.9, false, &calls));
  p.add_constraint(std::make_unique<AbsDeviation>(std::vector<VariableId>{v[1]}, std::vector<double>{1}, 0, 0.7, 1.3));
  p.add_constraint(std::make_unique<QueriedDistance>(v[2], -1.1, 0.37, 1, true, &calls));
  p.add_constraint(std::make_unique<LinearConstraint>(std::vector<VariableId>{v[0], v[3]}, std::vector<double>{1, 2},
                                                      Relation::kLessEqual, 0.5, 0.7));
  p.add_constraint(std::make_unique<AbsDeviation>(std::vector<VariableId>{v[3]}, std::vector<double>{1}, 0, -0.4, 2.1, true));
  std::vector<Score> terms(p.num_constraints());
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(-3, 3);
  int complete_count = 0, partial_count = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Assignment a = {unit(rng), unit(rng), unit(rng), unit(rng)};
    const Score full = p.score(a);
    Score bound = full;
    switch (trial % 6) {
      case 0: bound.soft += 1e-9; break;
      case 1: break;
      case 2: bound.soft -= 1e-9; break;
      case 3: bound.soft += 10; break;
      case 4: bound.hard += 1; break;
      default: bound.hard -= 1; break;
    }
    bool complete = false;
    calls = 0;
    const Score got = p.score_below(a, bound, complete, terms);
    expect_bounded_score(got, complete, full, bound, trial);
    EXPECT_EQ(calls, complete ? 2 : 0) << trial;  // the queried ones only when complete
    ++(complete ? complete_count : partial_count);
  }
  EXPECT_GT(complete_count, 300);
  EXPECT_GT(partial_count, 150);
  std::vector<Score> short_terms(2);
  bool complete = false;
  EXPECT_THROW(p.score_below(Assignment{0, 0, 0, 0}, Score{}, complete, short_terms), std::invalid_argument);
}

TEST(Problem, BreakdownListsEveryConstraintInIdOrder) {
  const auto p = small_problem();
  const auto parts = p->breakdown(Assignment{2, 2, 1});
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].id, 0u);
  EXPECT_TRUE(parts[0].hard);
  EXPECT_DOUBLE_EQ(parts[0].violation, 1);
  EXPECT_DOUBLE_EQ(parts[1].violation, 1);
  EXPECT_DOUBLE_EQ(parts[1].cost, 2);
  EXPECT_FALSE(parts[1].hard);
  EXPECT_DOUBLE_EQ(parts[2].violation, 2);
  EXPECT_DOUBLE_EQ(parts[2].cost, 1);
  // The breakdown adds up to the score.
  EXPECT_DOUBLE_EQ(parts[1].cost + parts[2].cost, p->cost(Assignment{2, 2, 1}));
}

// Messages and tables name a constraint by its label, else by its kind over its variables'
// names; a long scope is cut to its first six names and its size.
TEST(Problem, NamesAConstraintByItsLabelElseByItsVariablesNames) {
  auto p = small_problem();
  EXPECT_EQ(p->constraint_name(0), "not_equal(x, y)");
  EXPECT_EQ(p->constraint_name(1), "linear(x, y, z)");
  p->mutable_constraint(2).set_label("z near 3");
  EXPECT_EQ(p->constraint_name(2), "z near 3");
  Problem queens("queens");
  queens.add_variables("q", 1000, Domain::integer_range(0, 999));
  std::vector<VariableId> all(1000);
  for (VariableId v = 0; v < 1000; ++v) all[v] = v;
  queens.add_constraint(std::make_unique<AllDifferent>(all));
  EXPECT_EQ(queens.constraint_name(0), "all_different(q0, q1, q2, q3, q4, q5, ... 1000 variables)");
}

TEST(Problem, DeltaEqualsFullReEvaluationForEveryMove) {
  const auto p = small_problem();
  for (double x = 0; x <= 3; ++x) {
    for (double y = 0; y <= 3; ++y) {
      for (double z = 0; z <= 3; ++z) {
        Assignment a = {x, y, z};
        for (VariableId v = 0; v < 3; ++v) {
          for (double value = 0; value <= 3; ++value) {
            Assignment b = a;
            b[v] = value;
            const Score expected = p->score(b) - p->score(a);
            const Score got = p->delta(a, v, value);
            EXPECT_DOUBLE_EQ(got.hard, expected.hard);
            EXPECT_DOUBLE_EQ(got.soft, expected.soft);
            EXPECT_EQ(a, (Assignment{x, y, z})) << "delta must restore the assignment";
          }
        }
      }
    }
  }
}

TEST(Problem, IncidencesListEachConstraintAndPosition) {
  const auto p = small_problem();
  const auto z = p->incidences(2);
  ASSERT_EQ(z.size(), 2u);
  EXPECT_EQ(z[0].constraint, 1u);
  EXPECT_EQ(z[0].position, 2u);
  EXPECT_EQ(z[1].constraint, 2u);
  EXPECT_EQ(z[1].position, 0u);
  const auto y = p->incidences(1);
  ASSERT_EQ(y.size(), 2u);
  EXPECT_EQ(y[0].constraint, 0u);
  EXPECT_EQ(y[0].position, 1u);
  EXPECT_EQ(y[1].position, 1u);
  for (VariableId v = 0; v < p->num_variables(); ++v) {
    for (const Incidence& inc : p->incidences(v)) {
      EXPECT_EQ(p->constraint(inc.constraint).scope()[inc.position], v);
    }
  }
}

TEST(Problem, RefusesDuplicateUnknownAndRepeatedVariables) {
  Problem p;
  p.add_variable("x", Domain::integer_range(0, 1));
  EXPECT_THROW(p.add_variable("x", Domain::integer_range(0, 1)), std::invalid_argument);
  EXPECT_THROW(p.add_variable("", Domain::integer_range(0, 1)), std::invalid_argument);
  EXPECT_THROW(p.add_constraint(std::make_unique<NotEqual>(0, 5)), std::invalid_argument);
  EXPECT_THROW(p.add_constraint(std::make_unique<NotEqual>(0, 0)), std::invalid_argument);
  EXPECT_EQ(p.num_constraints(), 0u);
  EXPECT_TRUE(p.find_variable("x").has_value());
  EXPECT_FALSE(p.find_variable("y").has_value());
}

TEST(Problem, AddsNamedBatchesThatLookUpLikeSingleVariables) {
  Problem p;
  p.add_variable("a", Domain::integer_range(0, 1));
  const VariableId first = p.add_variables("q", 12, Domain::integer_range(0, 11));
  EXPECT_EQ(first, 1u);
  ASSERT_EQ(p.num_variables(), 13u);
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_EQ(p.variable(first + i).name, "q" + std::to_string(i));
    EXPECT_EQ(p.variable(first + i).domain.size(), 12u);
    EXPECT_EQ(p.find_variable("q" + std::to_string(i)), first + i);
  }
  EXPECT_EQ(p.find_variable("a"), 0u);
  EXPECT_FALSE(p.find_variable("q12"));
  EXPECT_FALSE(p.find_variable("q01"));
  // Another variable added one at a time after a batch is indexed too.
  const VariableId b = p.add_variable("b", Domain::integer_range(0, 1));
  EXPECT_EQ(p.find_variable("b"), b);
  EXPECT_EQ(p.find_variable("q11"), first + 11);
  // A batch's incidences work as for single variables.
  p.add_constraint(std::make_unique<NotEqual>(first, first + 1));
  EXPECT_EQ(p.incidences(first).size(), 1u);
}

TEST(Problem, RefusesBatchNamesThatAnotherVariableHasAlready) {
  {
    Problem p;
    p.add_variable("q3", Domain::integer_range(0, 1));
    EXPECT_THROW(p.add_variables("q", 5, Domain::integer_range(0, 1)), std::invalid_argument);
  }
  {
    Problem p;  // q03 and q5 are not among q0..q4: no clash
    p.add_variable("q03", Domain::integer_range(0, 1));
    p.add_variable("q5", Domain::integer_range(0, 1));
    EXPECT_NO_THROW(p.add_variables("q", 5, Domain::integer_range(0, 1)));
    EXPECT_THROW(p.add_variable("q4", Domain::integer_range(0, 1)), std::invalid_argument);
  }
  {
    Problem p;  // q10..q14 of a first batch are q1 0..4 of a second
    p.add_variables("q", 20, Domain::integer_range(0, 1));
    EXPECT_THROW(p.add_variables("q1", 5, Domain::integer_range(0, 1)), std::invalid_argument);
    EXPECT_THROW(p.add_variables("q", 1, Domain::integer_range(0, 1)), std::invalid_argument);
    EXPECT_NO_THROW(p.add_variables("r", 3, Domain::integer_range(0, 1)));
    EXPECT_NO_THROW(p.add_variables("qa", 3, Domain::integer_range(0, 1)));  // never digits
    EXPECT_THROW(p.add_variables("", 3, Domain::integer_range(0, 1)), std::invalid_argument);
    EXPECT_EQ(p.find_variable("qa2"), 25u);
    EXPECT_EQ(p.find_variable("q19"), 19u);
    EXPECT_EQ(p.find_variable("r0"), 20u);
  }
  Problem p;
  EXPECT_THROW(p.add_variables("", 3, Domain::integer_range(0, 1)), std::invalid_argument);
}

TEST(Problem, GeneratesBatchNamesAndSharedDomainsOnDemandAsSingleAddsWould) {
  // The same variables added as batches and one at a time: every name, domain and lookup
  // agrees, whichever accessor is used.
  Problem batched, single;
  batched.add_variable("a", Domain::integer_range(0, 1));
  batched.add_variables("x", 105, Domain::integer_range(-3, 7));
  batched.add_variable("b", Domain::value_set({1, 4, 9}));
  batched.add_variables("y_", 3, Domain::real_interval(0, 1));
  single.add_variable("a", Domain::integer_range(0, 1));
  for (int i = 0; i < 105; ++i) single.add_variable("x" + std::to_string(i), Domain::integer_range(-3, 7));
  single.add_variable("b", Domain::value_set({1, 4, 9}));
  for (int i = 0; i < 3; ++i) single.add_variable("y_" + std::to_string(i), Domain::real_interval(0, 1));
  ASSERT_EQ(batched.num_variables(), single.num_variables());
  for (VariableId v = 0; v < single.num_variables(); ++v) {
    const std::string name = single.variable(v).name;
    EXPECT_EQ(batched.variable_name(v), name);
    EXPECT_EQ(batched.variable(v).name, name);
    EXPECT_EQ(batched.domain(v).describe(), single.domain(v).describe());
    EXPECT_EQ(batched.variable(v).domain.describe(), single.variable(v).domain.describe());
    EXPECT_EQ(batched.find_variable(name), v) << name;
  }
  EXPECT_EQ(batched.variables().size(), single.num_variables());
  EXPECT_FALSE(batched.all_discrete());
  EXPECT_FALSE(batched.find_variable("x105"));
  EXPECT_FALSE(batched.find_variable("x007"));
  EXPECT_FALSE(batched.find_variable("y_3"));
  EXPECT_FALSE(batched.find_variable("x"));
}

TEST(Problem, SetDomainOnABatchVariableLeavesItsNeighboursAlone) {
  Problem p;
  const VariableId first = p.add_variables("q", 4, Domain::integer_range(0, 3));
  EXPECT_EQ(p.variable(first + 2).domain.size(), 4u);  // the records exist from here on
  p.set_domain(first + 2, Domain::integer_range(5, 6));
  p.set_domain(first + 2, Domain::integer_range(5, 7));  // its own domain, replaced
  for (VariableId v = first; v < first + 4; ++v) {
    const std::size_t expected = v == first + 2 ? 3u : 4u;
    EXPECT_EQ(p.domain(v).size(), expected);
    EXPECT_EQ(p.variable(v).domain.size(), expected);
  }
  // A batch whose every variable got its own domain no longer counts its old one.
  Problem q;
  q.add_variables("r", 2, Domain::real_interval(0, 1));
  EXPECT_FALSE(q.all_discrete());
  q.set_domain(0, Domain::integer_range(0, 1));
  q.set_domain(1, Domain::integer_range(0, 1));
  EXPECT_TRUE(q.all_discrete());
}

TEST(Problem, IncidencesFollowConstraintsAddedAfterAFirstLookUp) {
  Problem p;
  const VariableId first = p.add_variables("q", 5, Domain::integer_range(0, 4));
  p.add_constraint(std::make_unique<NotEqual>(first + 3, first + 1));
  ASSERT_EQ(p.incidences(first + 1).size(), 1u);
  EXPECT_EQ(p.incidences(first + 1)[0].position, 1u);
  EXPECT_TRUE(p.incidences(first + 4).empty());
  const VariableId late = p.add_variable("late", Domain::integer_range(0, 4));
  p.add_constraint(std::make_unique<NotEqual>(first + 1, late));
  const auto list = p.incidences(first + 1);
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].constraint, 0u);
  EXPECT_EQ(list[1].constraint, 1u);
  EXPECT_EQ(list[1].position, 0u);
  ASSERT_EQ(p.incidences(late).size(), 1u);
  EXPECT_EQ(p.incidences(late)[0].position, 1u);
}

TEST(Problem, CheckAssignmentNamesTheOffendingVariable) {
  const auto p = small_problem();
  EXPECT_NO_THROW(p->check_assignment(Assignment{0, 1, 2}));
  try {
    p->check_assignment(Assignment{0, 7, 2});
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'y'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(p->check_assignment(Assignment{0, 1}), std::invalid_argument);
  EXPECT_THROW(p->check_assignment(Assignment{0, 1, std::nan("")}), std::invalid_argument);
}

// check_assignment tests integer ranges inline and asks the Domain otherwise: on every kind,
// batch or single, it must refuse exactly the values Domain::contains refuses (and NaN), and
// default_assignment must give each variable its own domain's middle.
TEST(Problem, CheckAssignmentAgreesWithTheDomainOnEveryKind) {
  Problem p("kinds");
  p.add_variables("b", 3, Domain::integer_range(-1, 3));
  p.add_variable("s", Domain::value_set({0.5, 2, 7}));
  p.add_variables("c", 2, Domain::integer_range(0, 1));
  p.add_variable("r", Domain::real_interval(-1, 2.5));
  p.add_variable("i", Domain::integer_range(2, 4));
  const Assignment middle = p.default_assignment();
  for (VariableId v = 0; v < p.num_variables(); ++v) {
    EXPECT_EQ(middle[v], p.domain(v).middle()) << "variable " << v;
  }
  EXPECT_NO_THROW(p.check_assignment(middle));
  const double probes[] = {-2, -1, -0.5, 0, 0.5, 1, 2, 2.5, 3, 3.5, 4, 7, 1e300,
                           std::numeric_limits<double>::infinity(), std::nan("")};
  for (VariableId v = 0; v < p.num_variables(); ++v) {
    for (double x : probes) {
      Assignment a = middle;
      a[v] = x;
      const bool valid = !std::isnan(x) && p.domain(v).contains(x);
      if (valid) {
        EXPECT_NO_THROW(p.check_assignment(a)) << "variable " << v << " = " << x;
      } else {
        EXPECT_THROW(p.check_assignment(a), std::invalid_argument)
            << "variable " << v << " = " << x;
      }
    }
  }
}

TEST(Problem, DefaultAssignmentTakesEachDomainsMiddle) {
  const auto p = small_problem();
  EXPECT_EQ(p->default_assignment(), (Assignment{2, 2, 2}));
  EXPECT_TRUE(p->all_discrete());
  EXPECT_FALSE(p->all_continuous());
}

TEST(IncrementalEvaluator, RunningScoreMatchesProblemScoreOnTheSmallProblem) {
  const auto p = small_problem();
  testing::check_incremental_matches_full(*p, 7, 300);
}

TEST(IncrementalEvaluator, InvolvementIsTheWeightedViolationOfTheVariablesConstraints) {
  const auto p = small_problem();
  IncrementalEvaluator e(*p, Assignment{2, 2, 1});
  // x takes part in x != y (1 x 1) and the sum (2 x 1); z in the sum (2) and |z - 3| (0.5 x 2).
  EXPECT_DOUBLE_EQ(e.involvement(0), 3.0);
  EXPECT_DOUBLE_EQ(e.involvement(2), 3.0);
  e.assign(1, 0);  // x != y holds, sum 3 <= 4 holds
  EXPECT_DOUBLE_EQ(e.involvement(0), 0.0);
  EXPECT_DOUBLE_EQ(e.involvement(2), 1.0);
}

// A constraint named constant is scored once and then left out of every delta, assign and
// involvement: the caller promises its moves never change it. Here x != y is named
// constant and only z moves (which it does not read): the running score must still equal
// a full evaluation, and the deltas are those of the other constraints alone.
TEST(IncrementalEvaluator, ConstantConstraintsStayInTheScoreButLeaveTheDeltas) {
  const auto p = small_problem();
  const std::vector<ConstraintId> constant = {0};  // x != y
  IncrementalEvaluator e(*p, Assignment{1, 1, 0}, constant);
  EXPECT_DOUBLE_EQ(e.score().hard, 1.0);    // x == y, counted once
  EXPECT_DOUBLE_EQ(e.involvement(0), 0.0);  // x's only other constraint, the sum, holds
  // Moving x would change x != y, but a constant constraint is not followed: the delta is
  // the sum's alone (x 1 -> 3: 3 + 1 + 0 = 4 still holds).
  EXPECT_DOUBLE_EQ(e.delta(0, 3).hard, 0.0);
  for (double z : {3.0, 1.0, 2.0, 0.0}) {
    e.assign(2, z);
    const Score full = p->score(e.values());
    EXPECT_DOUBLE_EQ(e.score().hard, full.hard) << "z = " << z;
    EXPECT_DOUBLE_EQ(e.score().soft, full.soft) << "z = " << z;
  }
  EXPECT_THROW(IncrementalEvaluator(*p, Assignment{1, 1, 0}, std::vector<ConstraintId>{9}),
               std::invalid_argument);
}

// The evaluator walks the Problem's shared incidence index and skips the constraints named
// constant itself (it used to copy per-variable lists of the others). On random problems
// mixing kinds with and without incremental states, hard and soft, some constraints named
// constant, everything is checked against per-variable lists of the non-constant
// constraints built here from the scopes alone: each delta is the weighted change of those
// constraints only, evaluated in full; evaluations() grows by their number; the running
// score is theirs plus the constant ones' score at the start (constants are not followed);
// can_retract holds exactly when all of them are all_differents (the one kind with partial
// assignments); and a retract / place_delta / place round trip agrees with full evaluation.
TEST(IncrementalEvaluator, SharedIncidencesSkipConstantConstraintsLikeSeparateLists) {
  std::mt19937 rng(2026);
  for (int round = 0; round < 40; ++round) {
    Problem p("random");
    const std::size_t n = 4 + rng() % 9;
    const VariableId first = p.add_variables("x", n, Domain::integer_range(0, 4));
    auto random_scope = [&](std::size_t size) {
      std::vector<VariableId> all(n);
      for (std::size_t i = 0; i < n; ++i) all[i] = first + static_cast<VariableId>(i);
      std::shuffle(all.begin(), all.end(), rng);
      all.resize(std::min(size, n));
      return all;
    };
    const std::size_t m = 2 + rng() % 9;
    std::vector<char> constant(m, 0);
    std::vector<ConstraintId> constant_ids;
    std::vector<char> is_all_different(m, 0);
    for (ConstraintId c = 0; c < m; ++c) {
      const bool hard = rng() % 2 == 0;
      const double weight = 1 + static_cast<double>(rng() % 4);
      switch (rng() % 3) {
        case 0: {
          const auto s = random_scope(2);
          p.add_constraint(std::make_unique<NotEqual>(s[0], s[1], 1, weight, hard));
          break;
        }
        case 1: {
          const auto s = random_scope(1 + rng() % 4);
          std::vector<double> coefficients(s.size());
          for (double& a : coefficients) a = static_cast<double>(rng() % 5) - 2;
          p.add_constraint(std::make_unique<LinearConstraint>(s, coefficients,
                                                              Relation::kLessEqual, 3, weight));
          p.mutable_constraint(c).set_hard(hard);
          break;
        }
        default: {
          const auto s = random_scope(2 + rng() % 4);
          std::vector<double> offsets(s.size());
          for (double& o : offsets) o = static_cast<double>(rng() % 3);
          const auto range = key_range_from_domains(p, s, offsets);
          p.add_constraint(std::make_unique<AllDifferent>(
              s, offsets, AllDifferent::Measure::kVariables, weight, hard, range));
          is_all_different[c] = 1;
        }
      }
      if (rng() % 3 == 0) {
        constant[c] = 1;
        constant_ids.push_back(c);
      }
    }
    // The old layout: per variable, the non-constant constraints and positions, from scopes.
    std::vector<std::vector<ConstraintId>> lists(n);
    for (ConstraintId c = 0; c < m; ++c) {
      if (constant[c]) continue;
      for (VariableId v : p.constraint(c).scope()) lists[v].push_back(c);
    }
    Assignment values(n);
    for (double& x : values) x = static_cast<double>(rng() % 5);
    IncrementalEvaluator e(p, values, constant_ids);
    Score constant_part;
    for (ConstraintId c : constant_ids) constant_part += p.constraint_score(c, values);
    for (VariableId v = 0; v < n; ++v) {
      const bool retractable = std::all_of(lists[v].begin(), lists[v].end(),
                                           [&](ConstraintId c) { return is_all_different[c]; });
      EXPECT_EQ(e.can_retract(v), retractable) << "round " << round << ", variable " << v;
    }
    auto running = [&](const Assignment& a) {
      Score sum = constant_part;
      for (ConstraintId c = 0; c < m; ++c) {
        if (!constant[c]) sum += p.constraint_score(c, a);
      }
      return sum;
    };
    auto close = [](const Score& a, const Score& b) {
      return std::abs(a.hard - b.hard) < 1e-9 && std::abs(a.soft - b.soft) < 1e-9;
    };
    for (int step = 0; step < 60; ++step) {
      const auto v = static_cast<VariableId>(rng() % n);
      const auto value = static_cast<double>(rng() % 5);
      Assignment after = e.values();
      after[v] = value;
      Score expected;
      for (ConstraintId c : lists[v]) {
        expected += p.constraint_score(c, after) - p.constraint_score(c, e.values());
      }
      const std::size_t before = e.evaluations();
      const Score got = e.delta(v, value);
      ASSERT_TRUE(close(got, expected)) << "round " << round << ", step " << step;
      EXPECT_EQ(e.evaluations() - before, value == e.values()[v] ? 0 : lists[v].size());
      if (step % 3 == 2) continue;
      e.assign(v, value);
      ASSERT_TRUE(close(e.score(), running(e.values()))) << "round " << round << ", step " << step;
      if (!e.can_retract(v)) continue;
      e.retract(v);
      const Score retracted = e.score();
      const Score placed = e.place_delta(v, value);
      e.place(v, value);
      ASSERT_TRUE(close(e.score(), running(e.values()))) << "round " << round << ", step " << step;
      EXPECT_TRUE(close(e.score() - retracted, placed)) << "round " << round << ", step " << step;
    }
    // A group retracted at once (whole all_differents cleared in one go, the others one
    // variable at a time): the score is then that of the variables present (min_violation
    // of an all_different counts the repeats among them), and placing them back restores it.
    std::vector<VariableId> group;
    std::vector<std::uint8_t> present(n, 1);
    for (VariableId v = 0; v < n; ++v) {
      if (e.can_retract(v) && rng() % 2 == 0) {
        group.push_back(v);
        present[v] = 0;
      }
    }
    if (group.empty()) continue;
    const Assignment kept = e.values();
    const Score all_present = e.score();
    e.retract(group);
    Score expected = constant_part;
    for (ConstraintId c = 0; c < m; ++c) {
      if (constant[c]) continue;
      const Constraint& k = p.constraint(c);
      const double violation = k.min_violation(kept, present);
      (k.is_hard() ? expected.hard : expected.soft) += k.weight() * violation;
    }
    EXPECT_TRUE(close(e.score(), expected)) << "round " << round << ", " << group.size()
                                            << " retracted";
    for (VariableId v : group) e.place(v, kept[v]);
    EXPECT_TRUE(close(e.score(), all_present)) << "round " << round;
    // A group with a variable that cannot retract is refused before anything changes.
    for (VariableId v = 0; v < n; ++v) {
      if (e.can_retract(v)) continue;
      group.push_back(v);
      EXPECT_THROW(e.retract(group), std::logic_error) << "round " << round;
      EXPECT_TRUE(close(e.score(), all_present)) << "round " << round;
      break;
    }
  }
}

}  // namespace
}  // namespace sightline::csp
