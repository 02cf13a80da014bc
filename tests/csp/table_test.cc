// The table kind against plain references: a std::map of the listed tuples for violation,
// full re-evaluation for deltas, enumeration of the completions for min_violation.
#include "sightline/csp/kinds/table.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/input_error.h"
#include "sightline/csp/problem.h"

namespace sightline::csp {
namespace {

// A random table over `arity` variables with values 0..d-1 (plus a few off-domain values
// in the tuples when `odd_values`), its reference map, and a default.
struct RandomTable {
  std::vector<Table::Entry> entries;
  std::map<std::vector<double>, double> reference;
  double default_cost = 0;
};

RandomTable make_random_table(std::mt19937& rng, std::size_t arity, int d, std::size_t tuples,
                              bool odd_values) {
  RandomTable t;
  std::uniform_int_distribution<int> value(0, d - 1), cost(0, 9), coin(0, 9);
  t.default_cost = cost(rng);
  for (std::size_t attempt = 0; t.entries.size() < tuples && attempt < 20 * tuples; ++attempt) {
    std::vector<double> values(arity);
    for (double& v : values) v = odd_values && coin(rng) == 0 ? 0.5 + 7 * value(rng) : value(rng);
    if (t.reference.count(values)) continue;
    const double c = cost(rng);
    t.reference[values] = c;
    t.entries.push_back({values, c});
  }
  return t;
}

double reference_cost(const RandomTable& t, const std::vector<double>& tuple) {
  auto it = t.reference.find(tuple);
  return it == t.reference.end() ? t.default_cost : it->second;
}

std::vector<VariableId> iota_scope(std::size_t arity) {
  std::vector<VariableId> scope(arity);
  for (std::size_t i = 0; i < arity; ++i) scope[i] = static_cast<VariableId>(i);
  return scope;
}

TEST(Table, ViolationIsTheListedCostOrTheDefault) {
  Table t({0, 1}, {{{0, 1}, 5}, {{1, 1}, 0}, {{2, 0}, 3}}, 7);
  EXPECT_EQ(t.violation(std::vector<double>{0, 1}), 5);
  EXPECT_EQ(t.violation(std::vector<double>{1, 1}), 0);
  EXPECT_EQ(t.violation(std::vector<double>{2, 0}), 3);
  EXPECT_EQ(t.violation(std::vector<double>{0, 0}), 7);  // listed values, unlisted tuple
  EXPECT_EQ(t.violation(std::vector<double>{9, 1}), 7);  // value in no tuple
  EXPECT_EQ(t.min_cost(), 0);
  EXPECT_EQ(t.num_tuples(), 3u);
  EXPECT_EQ(t.tuple_value(2, 0), 2);
  EXPECT_EQ(t.tuple_cost(2), 3);
}

TEST(Table, DenseAndSparseStorageAgreeWithAMapOfTheTuples) {
  std::mt19937 rng(7);
  // Small key spaces are dense, a wide table with few tuples is sparse; both must agree
  // with the map on every tuple of the domains (and off-domain values map to the default).
  struct Case {
    std::size_t arity;
    int d;
    std::size_t tuples;
    bool dense;
  };
  for (const Case& c : {Case{3, 6, 100, true}, Case{2, 4, 16, true}, Case{6, 6, 40, false}}) {
    RandomTable rt = make_random_table(rng, c.arity, c.d, c.tuples, true);
    Table t(iota_scope(c.arity), rt.entries, rt.default_cost);
    EXPECT_EQ(t.is_dense(), c.dense) << "arity " << c.arity;
    std::vector<double> tuple(c.arity, 0);
    std::size_t checked = 0;
    while (true) {
      ASSERT_EQ(t.violation(tuple), reference_cost(rt, tuple));
      ASSERT_EQ(t.cost_of(tuple), reference_cost(rt, tuple));
      ++checked;
      std::size_t p = 0;
      for (; p < c.arity; ++p) {
        if (++tuple[p] < c.d) break;
        tuple[p] = 0;
      }
      if (p == c.arity) break;
    }
    for (const auto& e : rt.entries) ASSERT_EQ(t.violation(e.values), e.cost);
    EXPECT_GT(checked, 0u);
  }
}

TEST(Table, IncrementalDeltaMatchesFullReevaluation) {
  std::mt19937 rng(11);
  for (std::size_t arity : {1u, 2u, 3u, 5u}) {
    RandomTable rt = make_random_table(rng, arity, 4, 30, true);
    // The scope is spread over a larger assignment, in a scrambled order.
    std::vector<VariableId> scope;
    for (std::size_t i = 0; i < arity; ++i)
      scope.push_back(static_cast<VariableId>(2 * (arity - i)));
    Table t(scope, rt.entries, rt.default_cost);
    std::vector<double> values(2 * arity + 2, 0.0);
    auto state = t.make_incremental_state(values);
    std::uniform_int_distribution<std::size_t> position(0, arity - 1);
    std::uniform_int_distribution<int> value(-1, 4);
    double current = t.violation(values);
    for (int step = 0; step < 2000; ++step) {
      const std::size_t p = position(rng);
      const int raw = value(rng);
      const double v = raw == 4 ? 7.5 : raw;  // 7.5 appears in some tuples, -1 in none
      std::vector<double> moved = values;
      moved[scope[p]] = v;
      const double expected = t.violation(moved) - current;
      ASSERT_DOUBLE_EQ(state->delta(values, p, v), expected) << "step " << step;
      if (step % 3 != 0) {
        state->commit(values, p, v);
        values = moved;
        current = t.violation(values);
        ASSERT_DOUBLE_EQ(state->involvement(values, p), current);
      }
    }
  }
}

TEST(Table, MinViolationIsTheCheapestCompatibleTupleOrTheDefault) {
  std::mt19937 rng(3);
  const int d = 4;
  for (int round = 0; round < 40; ++round) {
    const std::size_t arity = 1 + round % 4;
    RandomTable rt = make_random_table(rng, arity, d, 3 + round % 20, false);
    Table t(iota_scope(arity), rt.entries, rt.default_cost);
    std::uniform_int_distribution<int> value(0, d - 1), coin(0, 1);
    for (int probe = 0; probe < 30; ++probe) {
      std::vector<double> values(arity);
      std::vector<std::uint8_t> assigned(arity);
      for (std::size_t p = 0; p < arity; ++p) {
        values[p] = value(rng);
        assigned[p] = static_cast<std::uint8_t>(coin(rng));
      }
      // Brute force over the completions within the domains 0..d-1.
      double true_min = std::numeric_limits<double>::infinity();
      bool any_unassigned = false;
      for (std::size_t p = 0; p < arity; ++p) any_unassigned |= !assigned[p];
      std::vector<double> tuple = values;
      std::vector<int> free_index(arity, 0);
      while (true) {
        for (std::size_t p = 0; p < arity; ++p) {
          if (!assigned[p]) tuple[p] = free_index[p];
        }
        true_min = std::min(true_min, reference_cost(rt, tuple));
        std::size_t p = 0;
        for (; p < arity; ++p) {
          if (assigned[p]) continue;
          if (++free_index[p] < d) break;
          free_index[p] = 0;
        }
        if (p == arity) break;
      }
      // What the header promises: listed compatible tuples, and the default when some
      // variable is unassigned.
      double promised = any_unassigned ? rt.default_cost : std::numeric_limits<double>::infinity();
      for (const auto& e : rt.entries) {
        bool compatible = true;
        for (std::size_t p = 0; p < arity; ++p)
          compatible &= !assigned[p] || e.values[p] == values[p];
        if (compatible) promised = std::min(promised, e.cost);
      }
      if (!any_unassigned) promised = reference_cost(rt, values);
      const double got = t.min_violation(values, assigned);
      ASSERT_EQ(got, promised) << "round " << round << " probe " << probe;
      ASSERT_LE(got, true_min);  // a valid lower bound
    }
  }
}

TEST(Table, AHugeDefaultCostTableIsStoredSparselyWithoutEnumeratingItsComplement) {
  // 30 variables with a million values each: 10^180 tuples, three listed.
  const std::size_t arity = 30;
  std::vector<Table::Entry> entries;
  for (int k = 0; k < 3; ++k) entries.push_back({std::vector<double>(arity, 1000.0 * k), 1.0 * k});
  Table t(iota_scope(arity), entries, 50);
  EXPECT_FALSE(t.is_dense());
  EXPECT_EQ(t.violation(std::vector<double>(arity, 1000.0)), 1.0);
  std::vector<double> mixed(arity, 1000.0);
  mixed[7] = 2000.0;
  EXPECT_EQ(t.violation(mixed), 50.0);
  mixed[7] = 999999.0;
  EXPECT_EQ(t.violation(mixed), 50.0);
  EXPECT_EQ(t.min_cost(), 0.0);
}

TEST(Table, RefusesDuplicateTuplesNegativeCostsAndWrongLengths) {
  try {
    Table({0, 1}, {{{0, 1}, 1}, {{1, 1}, 2}, {{0, 1}, 3}}, 0);
    FAIL() << "expected a TableError";
  } catch (const TableError& e) {
    EXPECT_EQ(e.entry(), 2u);
    EXPECT_EQ(e.first_entry(), 0u);
    EXPECT_NE(std::string(e.what()).find("listed twice"), std::string::npos);
  }
  try {
    Table({0}, {{{0}, 1}, {{1}, -2}}, 0);
    FAIL() << "expected a TableError";
  } catch (const TableError& e) {
    EXPECT_EQ(e.entry(), 1u);
  }
  try {
    Table({0, 1}, {{{0, 1, 2}, 1}}, 0);
    FAIL() << "expected a TableError";
  } catch (const TableError& e) {
    EXPECT_EQ(e.entry(), 0u);
  }
  EXPECT_THROW(Table({0}, std::vector<Table::Entry>{}, -1), TableError);
  // 64 positions with two distinct values each: 2^64 keys.
  std::vector<Table::Entry> wide = {{std::vector<double>(64, 0.0), 1},
                                    {std::vector<double>(64, 1.0), 1}};
  EXPECT_THROW(Table(iota_scope(64), wide, 0), TableError);
}

TEST(TableKind, ReadsBothTupleFormsFromAProblemFile) {
  auto p = parse_problem(R"(
variables:
  - {names: [x, y], int: [0, 2]}
constraints:
  - kind: table
    scope: [x, y]
    default: 4
    tuples:
      - [0, 1, 0]
      - {values: [2, 2], cost: 1.5}
)",
                         "inline.yaml");
  ASSERT_EQ(p->num_constraints(), 1u);
  EXPECT_EQ(p->constraint(0).kind(), "table");
  EXPECT_EQ(p->cost(std::vector<double>{0, 1}), 0);
  EXPECT_EQ(p->cost(std::vector<double>{2, 2}), 1.5);
  EXPECT_EQ(p->cost(std::vector<double>{1, 1}), 4);
}

std::string problem_error(const std::string& constraint) {
  try {
    parse_problem("variables:\n  - {names: [x, y], int: [0, 2]}\nconstraints:\n" + constraint,
                  "bad.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TableKind, ReportsBadTuplesWithTheirLine) {
  EXPECT_NE(problem_error("  - kind: table\n    scope: [x, y]\n    tuples:\n      - [0, 1, 2]\n"
                          "      - [0, 1, 3]\n")
                .find("bad.yaml:8"),
            std::string::npos);
  const std::string out_of_domain =
      problem_error("  - kind: table\n    scope: [x, y]\n    tuples:\n      - [0, 5, 2]\n");
  EXPECT_NE(out_of_domain.find("bad.yaml:7"), std::string::npos) << out_of_domain;
  EXPECT_NE(out_of_domain.find("not in the domain"), std::string::npos) << out_of_domain;
  EXPECT_NE(problem_error("  - {kind: table, scope: [x, y], tuples: [[0, 1]]}\n")
                .find("2 values followed by its cost"),
            std::string::npos);
  EXPECT_NE(problem_error("  - {kind: table, scope: [x, y], tuples: [[0, 1, -1]]}\n")
                .find("costs must be >= 0"),
            std::string::npos);
  EXPECT_NE(problem_error("  - {kind: table, scope: [x, y], default: -2}\n").find(">= 0"),
            std::string::npos);
}

}  // namespace
}  // namespace sightline::csp
