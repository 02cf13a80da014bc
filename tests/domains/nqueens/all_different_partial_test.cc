// Tests of all_different's partial assignments (IncrementalState::retract / retract_all /
// place_delta / place / place_free, through IncrementalEvaluator) against an independent
// count: the
// violation of the variables present, recomputed from scratch with a map of keys after
// every operation. Both measures, with and without offsets, dense and hash counts.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "sightline/csp/incremental_evaluator.h"
#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/table.h"
#include "sightline/csp/problem.h"

namespace sightline::csp {
namespace {

using Measure = AllDifferent::Measure;

// The violation of the present variables alone, counted from scratch.
double present_violation(const Assignment& values, const std::vector<char>& present,
                         std::span<const double> offsets, Measure measure) {
  std::map<double, int> counts;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (present[i]) ++counts[values[i] + offsets[i]];
  }
  double total = 0;
  for (const auto& [key, c] : counts) {
    total += measure == Measure::kVariables ? c - 1 : c * (c - 1) / 2.0;
  }
  return total;
}

struct Case {
  const char* name;
  Measure measure;
  bool offsets;
  bool integer_domain;  // dense counts; else hash counts
};

TEST(AllDifferentPartial, RetractAndPlaceAgreeWithACountOfThePresentVariables) {
  const Case cases[] = {{"var dense", Measure::kVariables, false, true},
                        {"dec dense +i", Measure::kDecomposition, true, true},
                        {"var hash +i", Measure::kVariables, true, false},
                        {"dec hash", Measure::kDecomposition, false, false}};
  std::mt19937_64 random(5);
  for (const Case& c : cases) {
    const std::size_t n = 12;
    Problem p;
    std::vector<VariableId> scope;
    for (std::size_t i = 0; i < n; ++i) {
      scope.push_back(p.add_variable("x" + std::to_string(i),
                                     c.integer_domain ? Domain::integer_range(0, 6)
                                                      : Domain::value_set({0.5, 1, 2.5, 3, 4.5})));
    }
    std::vector<double> offsets(n, 0.0);
    if (c.offsets) {
      for (std::size_t i = 0; i < n; ++i) offsets[i] = static_cast<double>(i % 4);
    }
    const auto range = key_range_from_domains(p, scope, offsets);
    ASSERT_EQ(range.has_value(), c.integer_domain) << c.name;
    p.add_constraint(std::make_unique<AllDifferent>(scope, offsets, c.measure, 1.5, true, range));
    auto value_of = [&](VariableId v) {
      const Domain& d = p.variable(v).domain;
      return d.value_at(random() % d.size());
    };
    Assignment start(n);
    for (VariableId v = 0; v < n; ++v) start[v] = value_of(v);
    IncrementalEvaluator evaluator(p, start);
    std::vector<char> present(n, 1);
    ASSERT_TRUE(evaluator.can_retract(0)) << c.name;
    auto expect_matches = [&](int step) {
      const double expected =
          1.5 * present_violation(evaluator.values(), present, offsets, c.measure);
      ASSERT_DOUBLE_EQ(evaluator.score().hard, expected) << c.name << " step " << step;
      ASSERT_DOUBLE_EQ(evaluator.violation(0) * 1.5, expected) << c.name << " step " << step;
    };
    for (int step = 0; step < 600; ++step) {
      const auto v = static_cast<VariableId>(random() % n);
      if (step == 300) {  // everything back, then out at once, then back one by one below
        for (VariableId u = 0; u < n; ++u) {
          if (!present[u]) evaluator.place(u, value_of(u));
        }
        std::fill(present.begin(), present.end(), 1);
        expect_matches(step);
        evaluator.retract(scope);
        std::fill(present.begin(), present.end(), 0);
        expect_matches(step);
        continue;
      }
      if (present[v]) {
        if (random() % 3 == 0) {
          evaluator.retract(v);
          present[v] = 0;
        } else {  // an ordinary move among the present variables
          const double value = value_of(v);
          Assignment probe = evaluator.values();
          const double before = present_violation(probe, present, offsets, c.measure);
          probe[v] = value;
          const double after = present_violation(probe, present, offsets, c.measure);
          ASSERT_DOUBLE_EQ(evaluator.delta(v, value).hard, 1.5 * (after - before)) << c.name;
          evaluator.assign(v, value);
        }
      } else {
        const double value = value_of(v);
        Assignment probe = evaluator.values();
        probe[v] = value;
        std::vector<char> with = present;
        with[v] = 1;
        const double before = present_violation(evaluator.values(), present, offsets, c.measure);
        const double after = present_violation(probe, with, offsets, c.measure);
        ASSERT_DOUBLE_EQ(evaluator.place_delta(v, value).hard, 1.5 * (after - before)) << c.name;
        const bool free = evaluator.place_is_free(v, value);
        ASSERT_EQ(free, after <= before) << c.name;
        // place_free (counts that catch up later, on dense states) where it may be used;
        // the checks after every later operation see whether they caught up right.
        if (free && random() % 2 == 0) {
          evaluator.place_free(v, value);
        } else {
          evaluator.place(v, value);
        }
        present[v] = 1;
      }
      expect_matches(step);
    }
    // All back: the running score is the full one again.
    for (VariableId v = 0; v < n; ++v) {
      if (!present[v]) evaluator.place(v, value_of(v));
    }
    ASSERT_DOUBLE_EQ(evaluator.score().hard, p.score(evaluator.values()).hard) << c.name;
  }
}

// A dense state keeps its violation up to date (the evaluator reads it instead of a full
// evaluation when it builds the state): after every commit, retract, place and place_free
// it must equal the count of the variables present, and its occupied-key bits must say
// which keys those variables hold.
TEST(AllDifferentPartial, DenseStateKeepsItsCurrentViolation) {
  std::mt19937_64 random(9);
  for (Measure measure : {Measure::kVariables, Measure::kDecomposition}) {
    const std::size_t n = 10;
    Problem p;
    std::vector<VariableId> scope;
    for (std::size_t i = 0; i < n; ++i) {
      scope.push_back(p.add_variable("x" + std::to_string(i), Domain::integer_range(0, 5)));
    }
    const std::vector<double> offsets(n, 0.0);
    const AllDifferent c(scope, offsets, measure, 1.0, false,
                         key_range_from_domains(p, scope, offsets));
    Assignment values(n);
    for (double& v : values) v = static_cast<double>(random() % 6);
    const auto state = c.make_incremental_state(values);
    std::vector<char> present(n, 1);
    for (int step = 0; step < 400; ++step) {
      const std::size_t i = random() % n;
      const double value = static_cast<double>(random() % 6);
      if (!present[i]) {
        // Decided from the bits, which do not settle the counts: place_free may follow
        // place_free with nothing in between.
        if (!state->occupied_keys().is_occupied(i, value) && step % 3 != 0) {
          ASSERT_EQ(state->place_free(values, i, value), 0.0);
        } else {
          state->place(values, i, value);
        }
        values[i] = value;
        present[i] = 1;
      } else if (step % 4 == 0) {
        state->retract(values, i);
        present[i] = 0;
      } else {
        state->commit(values, i, value);
        values[i] = value;
      }
      const auto kept = state->current_violation();
      ASSERT_TRUE(kept.has_value());
      ASSERT_DOUBLE_EQ(*kept, present_violation(values, present, offsets, measure)) << step;
      // The occupied-key view: a key is occupied exactly when a present variable holds it.
      const IncrementalState::OccupiedKeys keys = state->occupied_keys();
      ASSERT_NE(keys.occupied, nullptr);
      for (std::size_t position = 0; position < n; ++position) {
        for (int value = 0; value < 6; ++value) {
          bool held = false;
          for (std::size_t j = 0; j < n; ++j) held = held || (present[j] && values[j] == value);
          ASSERT_EQ(keys.is_occupied(position, value), held) << step << " key " << value;
        }
      }
    }
  }
}

TEST(AllDifferentPartial, AVariableWithAConstraintThatCannotRetractIsRefused) {
  Problem p;
  const VariableId x = p.add_variable("x", Domain::integer_range(0, 3));
  const VariableId y = p.add_variable("y", Domain::integer_range(0, 3));
  const VariableId z = p.add_variable("z", Domain::integer_range(0, 3));
  p.add_constraint(std::make_unique<AllDifferent>(std::vector<VariableId>{x, y, z}));
  const std::vector<Table::Entry> entries = {{{0, 0}, 1.0}};
  p.add_constraint(std::make_unique<Table>(std::vector<VariableId>{x, y}, entries, 0.0));
  IncrementalEvaluator evaluator(p, {0, 0, 1});
  EXPECT_FALSE(evaluator.can_retract(x));
  EXPECT_TRUE(evaluator.can_retract(z));
  EXPECT_THROW(evaluator.retract(x), std::logic_error);
  const std::vector<VariableId> both = {y, z};
  EXPECT_THROW(evaluator.retract(both), std::logic_error);
}

// When every constraint the evaluator follows supports partial assignments, can_retract
// answers without walking the variable's links: that shortcut must hold only then. A table
// (no partial support) named constant is not followed and so does not count; not named
// constant, it makes its own variables refused and no other; a variable in no constraint
// can always be retracted.
TEST(AllDifferentPartial, EveryVariableCanRetractExactlyWhenNoFollowedConstraintForbidsIt) {
  Problem p;
  const VariableId x = p.add_variable("x", Domain::integer_range(0, 3));
  const VariableId y = p.add_variable("y", Domain::integer_range(0, 3));
  const VariableId z = p.add_variable("z", Domain::integer_range(0, 3));
  const VariableId lone = p.add_variable("lone", Domain::integer_range(0, 3));
  p.add_constraint(std::make_unique<AllDifferent>(std::vector<VariableId>{x, y, z}));
  const std::vector<Table::Entry> entries = {{{0, 0}, 1.0}};
  const ConstraintId table =
      p.add_constraint(std::make_unique<Table>(std::vector<VariableId>{x, y}, entries, 0.0));
  const std::vector<ConstraintId> constant = {table};
  IncrementalEvaluator followed(p, {0, 0, 1, 2});
  IncrementalEvaluator skipped(p, {0, 0, 1, 2}, constant);
  for (VariableId v : {x, y, z, lone}) {
    EXPECT_EQ(followed.can_retract(v), v == z || v == lone) << v;
    EXPECT_TRUE(skipped.can_retract(v)) << v;
  }
  const std::vector<VariableId> all = {x, y, z};
  skipped.retract(all);  // allowed now, and the all_different alone is followed
  EXPECT_EQ(skipped.violation(0), 0);
  EXPECT_THROW(followed.retract(all), std::logic_error);
}

}  // namespace
}  // namespace sightline::csp
