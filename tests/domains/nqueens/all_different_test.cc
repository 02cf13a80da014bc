// Tests of the all_different kind: known violations of both measures, incremental deltas,
// commits and involvements against full re-evaluation on random moves (both measures, with
// and without offsets, dense and hash counts), the key range, and the file factory's errors.
#include "sightline/csp/kinds/all_different.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/incremental_evaluator.h"
#include "sightline/csp/problem.h"

namespace sightline::csp {
namespace {

using Measure = AllDifferent::Measure;

std::vector<VariableId> ids(std::size_t n) {
  std::vector<VariableId> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<VariableId>(i);
  return out;
}

TEST(AllDifferent, MeasuresVariablesToChangeOrEqualPairs) {
  const std::vector<double> values = {1, 1, 1, 2, 3, 3, 4};
  // Keys: 1 x3, 2, 3 x2, 4. var: (3-1) + (2-1) = 3. dec: 3 + 1 = 4.
  EXPECT_EQ(AllDifferent(ids(7), {}, Measure::kVariables).violation(values), 3);
  EXPECT_EQ(AllDifferent(ids(7), {}, Measure::kDecomposition).violation(values), 4);
  EXPECT_EQ(AllDifferent(ids(3)).violation(std::vector<double>{5, 6, 7}), 0);
}

TEST(AllDifferent, ComparesValuesPlusOffsets) {
  // Queens on a diagonal: rows 0, 1, 2 in columns 0, 1, 2 share q_i - i = 0.
  const std::vector<double> rows = {0, 1, 2};
  EXPECT_EQ(AllDifferent(ids(3), {0, 0, 0}).violation(rows), 0);
  EXPECT_EQ(AllDifferent(ids(3), {0, -1, -2}).violation(rows), 2);
  EXPECT_EQ(AllDifferent(ids(3), {0, -1, -2}, Measure::kDecomposition).violation(rows), 3);
  EXPECT_EQ(AllDifferent(ids(3), {0, 1, 2}).violation(rows), 0);
  EXPECT_THROW(AllDifferent(ids(3), {0, 1}), std::invalid_argument);
}

// All-zero offsets are not stored (a million-variable alldifferent would keep 8 MB of
// zeros): given as zeros (-0 included) or as none, offsets() is empty, offset(i) is 0, and
// the violation, the bound and the dense and hashed incremental states agree with a count
// of equal values made here; one non-zero offset keeps them all.
TEST(AllDifferent, KeepsNoOffsetsWhenAllAreZeroAndScoresTheSame) {
  std::mt19937 random(11);
  const std::size_t n = 9;
  Problem p("zeros");
  p.add_variables("x", n, Domain::integer_range(0, 5));
  for (const std::vector<double>& given :
       {std::vector<double>{}, std::vector<double>(n, 0.0), std::vector<double>(n, -0.0)}) {
    const auto range = key_range_from_domains(p, ids(n), given);
    ASSERT_TRUE(range.has_value());
    for (const bool dense : {true, false}) {
      const AllDifferent c(ids(n), given, Measure::kDecomposition, 1.0, false,
                           dense ? range : std::nullopt);
      EXPECT_TRUE(c.offsets().empty());
      EXPECT_TRUE(c.has_zero_offsets());
      EXPECT_EQ(c.offset(n - 1), 0.0);
      std::vector<double> values(n);
      for (double& x : values) x = static_cast<double>(random() % 6);
      auto pairs = [&](const std::vector<double>& v) {
        double equal = 0;
        for (std::size_t i = 0; i < n; ++i) {
          for (std::size_t j = i + 1; j < n; ++j) equal += v[i] == v[j];
        }
        return equal;
      };
      EXPECT_EQ(c.violation(values), pairs(values));
      EXPECT_EQ(c.min_violation(values, std::vector<std::uint8_t>(n, 1)), pairs(values));
      const auto state = c.make_incremental_state(values);
      for (int step = 0; step < 50; ++step) {
        const std::size_t i = random() % n;
        const auto value = static_cast<double>(random() % 6);
        std::vector<double> after = values;
        after[i] = value;
        ASSERT_EQ(state->delta(values, i, value), pairs(after) - pairs(values));
        state->commit(values, i, value);
        values = after;
      }
    }
  }
  std::vector<double> one(n, 0.0);
  one[4] = 5;
  const AllDifferent kept(ids(n), one);
  ASSERT_EQ(kept.offsets().size(), n);
  EXPECT_FALSE(kept.has_zero_offsets());
  EXPECT_EQ(kept.offset(4), 5.0);
  EXPECT_EQ(kept.offset(3), 0.0);
}

struct Case {
  const char* name;
  Measure measure;
  int offsets;  // 0: none, 1: +i, -1: -i, 2: random integers, 3: random reals
  bool integer_domain;
};

// Random single-variable moves on an IncrementalEvaluator: every delta must equal the change
// of a full evaluation, every commit must leave the total equal to a full evaluation, and
// every involvement must match a direct count of the variable's equal keys.
TEST(AllDifferent, IncrementalStateAgreesWithFullEvaluationOnRandomMoves) {
  const Case cases[] = {{"var", Measure::kVariables, 0, true},
                        {"dec", Measure::kDecomposition, 0, true},
                        {"var +i", Measure::kVariables, 1, true},
                        {"dec -i", Measure::kDecomposition, -1, true},
                        {"var random", Measure::kVariables, 2, true},
                        {"dec random", Measure::kDecomposition, 2, true},
                        {"var reals", Measure::kVariables, 3, false},
                        {"dec reals", Measure::kDecomposition, 3, false}};
  std::mt19937_64 random(11);
  for (const Case& c : cases) {
    const std::size_t n = 14;
    Problem p;
    const std::vector<double> set = {-1.5, 0.25, 0.5, 1.75, 3};
    for (std::size_t i = 0; i < n; ++i) {
      p.add_variable("x" + std::to_string(i),
                     c.integer_domain ? Domain::integer_range(-3, 5) : Domain::value_set(set));
    }
    std::vector<double> offsets;
    if (c.offsets != 0) {
      for (std::size_t i = 0; i < n; ++i) {
        if (c.offsets == 2)
          offsets.push_back(static_cast<double>(random() % 7) - 3);
        else if (c.offsets == 3)
          offsets.push_back(0.25 * static_cast<double>(random() % 9));
        else
          offsets.push_back(c.offsets * static_cast<double>(i));
      }
    }
    const auto range = key_range_from_domains(p, ids(n), offsets);
    EXPECT_EQ(range.has_value(), c.integer_domain) << c.name;
    auto owned = std::make_unique<AllDifferent>(ids(n), offsets, c.measure, 2.5, false, range);
    const AllDifferent& constraint = *owned;
    p.add_constraint(std::move(owned));

    auto random_value = [&](VariableId v) {
      const Domain& d = p.variable(v).domain;
      return d.value_at(random() % d.size());
    };
    Assignment start(n);
    for (VariableId v = 0; v < n; ++v) start[v] = random_value(v);
    IncrementalEvaluator evaluator(p, start);
    for (int step = 0; step < 400; ++step) {
      const auto v = static_cast<VariableId>(random() % n);
      const double value = random_value(v);
      Assignment probe = evaluator.values();
      const double before = constraint.violation(probe);
      probe[v] = value;
      const double after = constraint.violation(probe);
      ASSERT_DOUBLE_EQ(evaluator.delta(v, value).soft, 2.5 * (after - before)) << c.name;
      if (step % 2) {
        evaluator.assign(v, value);
        ASSERT_DOUBLE_EQ(evaluator.score().soft, 2.5 * after) << c.name;
      }
      // Involvement: 0 without an equal key; var: (count-1)/count; dec: count-1 (pairs).
      const VariableId w = static_cast<VariableId>(random() % n);
      const auto& values = evaluator.values();
      const double key = values[w] + constraint.offset(w);
      double count = 0;
      for (VariableId u = 0; u < n; ++u) count += values[u] + constraint.offset(u) == key;
      const double share = count < 2                          ? 0
                           : c.measure == Measure::kVariables ? (count - 1) / count
                                                              : count - 1;
      ASSERT_DOUBLE_EQ(evaluator.involvement(w), 2.5 * share) << c.name;
    }
  }
}

// min_violation against enumeration: on random partial assignments it never exceeds the
// best completion (brute force over the unassigned variables) and equals the violation
// once everything is assigned.
TEST(AllDifferent, MinViolationBoundsEveryCompletionFromBelow) {
  std::mt19937_64 random(3);
  Problem p;
  const std::size_t n = 5;
  for (std::size_t i = 0; i < n; ++i)
    p.add_variable("x" + std::to_string(i), Domain::integer_range(0, 3));
  for (Measure measure : {Measure::kVariables, Measure::kDecomposition}) {
    const AllDifferent c(ids(n), {0, 1, 0, -1, 2}, measure);
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<double> values(n);
      std::vector<std::uint8_t> assigned(n);
      for (std::size_t i = 0; i < n; ++i) {
        values[i] = static_cast<double>(random() % 4);
        assigned[i] = random() % 2;
      }
      double best = 1e300;
      std::vector<double> completion = values;
      for (int code = 0; code < 1024; ++code) {  // 4^5 completions, assigned ones fixed
        int rest = code;
        bool consistent = true;
        for (std::size_t i = 0; i < n; ++i, rest /= 4) {
          if (assigned[i] && rest % 4 != values[i]) consistent = false;
          completion[i] = rest % 4;
        }
        if (consistent) best = std::min(best, c.violation(completion));
      }
      EXPECT_LE(c.min_violation(values, assigned), best);
      std::fill(assigned.begin(), assigned.end(), 1);
      EXPECT_EQ(c.min_violation(values, assigned), c.violation(values));
    }
  }
}

TEST(AllDifferent, KeyRangeCoversEveryKeyOfIntegerDomains) {
  Problem p;
  p.add_variable("a", Domain::integer_range(0, 7));
  p.add_variable("b", Domain::value_set({-4, 2, 9}));
  const auto range = key_range_from_domains(p, ids(2), std::vector<double>{3, -2});
  ASSERT_TRUE(range.has_value());
  EXPECT_EQ(range->lo, -6);
  EXPECT_EQ(range->hi, 10);
  EXPECT_FALSE(key_range_from_domains(p, ids(2), std::vector<double>{0.5, 0}).has_value());
  p.add_variable("c", Domain::real_interval(0, 1));
  EXPECT_FALSE(key_range_from_domains(p, ids(3), {}).has_value());
}

TEST(AllDifferent, KeyRangeChecksEachDomainOfABatchAndOfSingleVariables) {
  // A batch shares one Domain (checked once); a variable added alone after it has its own,
  // and a fractional value there must still make the range unavailable.
  Problem p;
  const VariableId first = p.add_variables("x", 4, Domain::value_set({1, 5, 8}));
  const std::vector<VariableId> batch = {first, first + 1, first + 2, first + 3};
  const auto range = key_range_from_domains(p, batch, std::vector<double>{0, 1, 2, 3});
  ASSERT_TRUE(range.has_value());
  EXPECT_EQ(range->lo, 1);
  EXPECT_EQ(range->hi, 11);
  const VariableId odd = p.add_variable("odd", Domain::value_set({1, 2.5}));
  EXPECT_FALSE(key_range_from_domains(p, std::vector<VariableId>{first, first + 1, odd}, {})
                   .has_value());
  p.add_variables("y", 2, Domain::value_set({0, 0.5}));
  EXPECT_FALSE(key_range_from_domains(p, std::vector<VariableId>{first, odd + 1, odd + 2}, {})
                   .has_value());
}

// Against brute force: random problems of batches and single variables (integer ranges,
// integer and fractional value sets, real intervals) and random offsets (empty, integer,
// fractional, huge, NaN, infinite); the range must be the min and max of value + offset
// over every value of every scope domain when all are integers, and absent otherwise (or
// when it is wider than the dense limit, which these small ranges never are).
TEST(AllDifferent, KeyRangeIsTheBruteForceRangeOfIntegerKeysOrNothing) {
  std::mt19937 rng(1616);
  const std::vector<double> odd_offsets = {0.5, -2.25, 3e15, -1e16, std::nan(""),
                                           std::numeric_limits<double>::infinity()};
  for (int round = 0; round < 300; ++round) {
    Problem p;
    const auto random_domain = [&]() {
      switch (rng() % 6) {
        case 0: return Domain::real_interval(0, 3);
        case 1: return Domain::value_set({-3, 1.5, 4});
        case 2: return Domain::value_set({-7, 2, 9});
        default: {
          const double lo = static_cast<double>(rng() % 11) - 5;
          return Domain::integer_range(lo, lo + static_cast<double>(rng() % 6));
        }
      }
    };
    while (p.num_variables() < 6) {
      if (rng() % 2 == 0) {
        p.add_variables("b" + std::to_string(p.num_variables()), 1 + rng() % 4, random_domain());
      } else {
        p.add_variable("s" + std::to_string(p.num_variables()), random_domain());
      }
    }
    std::vector<VariableId> scope;
    for (VariableId v = 0; v < p.num_variables(); ++v) {
      if (rng() % 3 != 0) scope.push_back(v);
    }
    if (scope.empty()) scope.push_back(0);
    std::vector<double> offsets;
    if (rng() % 3 != 0) {
      for (std::size_t i = 0; i < scope.size(); ++i) {
        offsets.push_back(rng() % 12 == 0 ? odd_offsets[rng() % odd_offsets.size()]
                                          : static_cast<double>(rng() % 9) - 4);
      }
    }
    bool integers = true;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < scope.size(); ++i) {
      const Domain& d = p.domain(scope[i]);
      const double offset = offsets.empty() ? 0.0 : offsets[i];
      if (!d.is_discrete() || !std::isfinite(offset) || offset != std::floor(offset) ||
          std::abs(offset) > 1e15) {
        integers = false;
        break;
      }
      for (std::size_t k = 0; k < d.size(); ++k) {
        const double key = d.value_at(k) + offset;
        if (key != std::floor(key)) integers = false;
        lo = std::min(lo, key);
        hi = std::max(hi, key);
      }
    }
    const auto range = key_range_from_domains(p, scope, offsets);
    ASSERT_EQ(range.has_value(), integers) << "round " << round;
    if (!integers) continue;
    EXPECT_EQ(range->lo, static_cast<std::int64_t>(lo)) << "round " << round;
    EXPECT_EQ(range->hi, static_cast<std::int64_t>(hi)) << "round " << round;
  }
}

class AllDifferentKind : public ::testing::Test {
 protected:
  AllDifferentKind() {
    for (int i = 0; i < 3; ++i)
      problem.add_variable("q" + std::to_string(i), Domain::integer_range(0, 2));
  }
  std::unique_ptr<Constraint> create(Spec params) {
    const ConstraintRequest request{problem, ids(3), 1.0, true, params, {"queens.yaml", 7, 3}};
    return ConstraintKinds::global().create("all_different", request);
  }
  static Spec field(const std::string& key, Spec value) {
    return Spec::map({{key, std::move(value)}}, {"queens.yaml", 7, 3});
  }
  Problem problem;
};

TEST_F(AllDifferentKind, ReadsOffsetsAndMeasure) {
  const SourceLocation at{"queens.yaml", 8, 5};
  Spec params =
      Spec::map({{"offsets", Spec::list({Spec::number(0), Spec::number(1), Spec::number(2)}, at)},
                 {"measure", Spec::string("dec", at)}},
                at);
  const auto c = create(params);
  const auto& a = dynamic_cast<const AllDifferent&>(*c);
  EXPECT_EQ(a.measure(), Measure::kDecomposition);
  EXPECT_EQ(a.offsets()[2], 2);
  EXPECT_TRUE(a.key_range().has_value());
  EXPECT_TRUE(a.is_hard());
  EXPECT_EQ(dynamic_cast<const AllDifferent&>(*create(Spec::map({}))).measure(),
            Measure::kVariables);
}

TEST_F(AllDifferentKind, RejectsOffsetsOfTheWrongLengthWithTheirLine) {
  const SourceLocation at{"queens.yaml", 9, 14};
  try {
    create(field("offsets", Spec::list({Spec::number(0), Spec::number(1)}, at)));
    FAIL() << "two offsets for three variables accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 9);
    EXPECT_NE(e.detail().find("3 offsets"), std::string::npos) << e.what();
  }
}

TEST_F(AllDifferentKind, RejectsAnUnknownMeasureListingTheKnownOnes) {
  const SourceLocation at{"queens.yaml", 10, 14};
  try {
    create(field("measure", Spec::string("pairs", at)));
    FAIL() << "measure 'pairs' accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 10);
    const std::string message = e.what();
    EXPECT_NE(message.find("'var'"), std::string::npos) << message;
    EXPECT_NE(message.find("'dec'"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sightline::csp
