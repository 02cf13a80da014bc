// Writing .wcsp: every instance read, written and read back scores every assignment tried
// the same (feasibility and soft cost); problems built in C++ keep their weighted costs;
// what .wcsp cannot express is refused by name.
#include "sightline/csp/files/wcsp_writer.h"

#include <gtest/gtest.h>

#include "sightline/csp/kinds/builder.h"

#include <random>
#include <set>
#include <sstream>

#include "tests/csp/brute_force.h"
#include "sightline/csp/files/cfn_reader.h"
#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/files/table_writers.h"
#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/not_equal.h"
#include "sightline/csp/kinds/table.h"

namespace sightline::csp {
namespace {

const std::string kDataDir = std::string(SIGHTLINE_SHARED_DIR) + "/data/wcsp/";

std::unique_ptr<Problem> round_trip(const Problem& p) {
  std::ostringstream out;
  write_wcsp(p, out);
  std::istringstream in(out.str());
  return parse_wcsp(in, "written.wcsp");
}

void expect_same_scores(const Problem& a, const Problem& b, const std::vector<double>& values) {
  const Score sa = a.score(values), sb = b.score(values);
  ASSERT_EQ(sa.feasible(), sb.feasible());
  if (sa.feasible()) {
    ASSERT_EQ(sa.soft, sb.soft);
  }
}

TEST(WcspWriter, EveryInstanceReadsBackWithTheSameScores) {
  std::mt19937 rng(8);
  for (const char* name : {"4queens", "base2", "example", "golomb4", "magic3", "oconnell", "sudoku",
                           "warehouse", "zebra"}) {
    SCOPED_TRACE(name);
    auto original = read_wcsp_file(kDataDir + name + ".wcsp");
    auto again = round_trip(*original);
    ASSERT_EQ(again->num_variables(), original->num_variables());
    for (int round = 0; round < 300; ++round) {
      std::vector<double> values(original->num_variables());
      for (std::size_t v = 0; v < values.size(); ++v) {
        std::uniform_int_distribution<std::size_t> index(0,
                                                         original->variable(v).domain.size() - 1);
        values[v] = static_cast<double>(index(rng));
      }
      expect_same_scores(*original, *again, values);
    }
  }
  // base2 exhaustively: its feasible assignments too.
  auto base2 = read_wcsp_file(kDataDir + "base2.wcsp");
  auto again = round_trip(*base2);
  testing::for_each_assignment(*base2, [&](const std::vector<double>& values) {
    expect_same_scores(*base2, *again, values);
  });
}

TEST(WcspWriter, KeepsWeightedCostsAndWritesValuesAsDomainIndices) {
  Problem p("weighted example");
  p.add_variable("a", Domain::value_set({-1, 0.5, 2}));
  p.add_variable("b", Domain::integer_range(3, 4));
  p.add_variable("c", Domain::integer_range(0, 2));
  p.add_variable("d", Domain::value_set({-1, 0.5, 2}));
  // Soft table, weight 2; a tuple with a value outside the domains is dropped.
  p.add_constraint(std::make_unique<Table>(std::vector<VariableId>{0, 1},
                                           std::vector<Table::Entry>{{{0.5, 4}, 3}, {{7, 4}, 1}}, 1,
                                           2.0));
  p.add_constraint(std::make_unique<Table>(std::vector<VariableId>{2},
                                           std::vector<Table::Entry>{{{1}, 1}}, 0, 1.0, true));
  p.add_constraint(std::make_unique<AllDifferent>(std::vector<VariableId>{0, 3},
                                                  std::vector<double>{},
                                                  AllDifferent::Measure::kDecomposition, 5.0));
  std::ostringstream out;
  write_wcsp(p, out);
  // UB = 1 + 2 * 3 (table) + 5 * 1 (all_different) = 12.
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "weighted_example 4 3 3 12");
  auto q = round_trip(p);
  // Original values -> indices: a, d: -1 -> 0, 0.5 -> 1, 2 -> 2; b: 3 -> 0, 4 -> 1.
  testing::for_each_assignment(p, [&](const std::vector<double>& values) {
    std::vector<double> indices(4);
    for (VariableId v = 0; v < 4; ++v) indices[v] = *p.variable(v).domain.index_of(values[v]);
    const Score sp = p.score(values), sq = q->score(indices);
    ASSERT_EQ(sp.feasible(), sq.feasible());
    if (sp.feasible()) {
      ASSERT_EQ(sp.soft, sq.soft);
    }
  });
}

TEST(WcspWriter, RefusesWhatWcspCannotExpress) {
  std::ostringstream out;
  Problem q;
  q.add_variable("x", Domain::integer_range(0, 1));
  q.add_constraint(std::make_unique<Table>(std::vector<VariableId>{0},
                                           std::vector<Table::Entry>{{{0}, 0.5}}, 0));
  try {
    write_wcsp(q, out);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not a non-negative integer"), std::string::npos) << e.what();
    // Named by its variables' names, as every message names a constraint.
    EXPECT_NE(std::string(e.what()).find("table(x)"), std::string::npos) << e.what();
  }
  Problem r;
  r.add_variable("x", Domain::real_interval(0, 1));
  EXPECT_THROW(write_wcsp(r, out), std::invalid_argument);
  // Too large to expand: 1001^2 tuples.
  Problem big;
  big.add_variable("x", Domain::integer_range(0, 1000));
  big.add_variable("y", Domain::integer_range(0, 1000));
  big.add_constraint(std::make_unique<NotEqual>(0, 1));
  try {
    write_wcsp(big, out);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tuples"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not_equal(x, y)"), std::string::npos) << e.what();
  }
  // A labelled constraint by its label.
  q.mutable_constraint(0).set_label("x's price");
  try {
    write_wcsp(q, out, WcspWriteOptions{0});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("x's price"), std::string::npos) << e.what();
  }
}

TEST(WcspWriter, ScalesFractionalCostsByTheFewestPowerOfTenWhenAllowed) {
  Problem p("quarters");
  p.add_variable("x", Domain::integer_range(0, 2));
  p.add_constraint(std::make_unique<Table>(std::vector<VariableId>{0},
                                           std::vector<Table::Entry>{{{1}, 0.25}, {{2}, 1.5}}, 0));
  std::ostringstream out;
  EXPECT_EQ(write_wcsp(p, out, WcspWriteOptions{6}), 100.0);
  // UB = 1 + 150; the tuples' costs 25 and 150.
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "quarters 1 3 1 151");
  std::istringstream in(out.str());
  const auto back = parse_wcsp(in, "quarters.wcsp");
  EXPECT_EQ(back->score(std::vector<double>{1}).soft, 25);
  std::ostringstream integers;
  Problem whole("whole");
  whole.add_variable("x", Domain::integer_range(0, 1));
  whole.add_constraint(std::make_unique<Table>(std::vector<VariableId>{0},
                                               std::vector<Table::Entry>{{{1}, 3}}, 0));
  EXPECT_EQ(write_wcsp(whole, integers, WcspWriteOptions{6}), 1.0);
  // Seven places are more than six.
  p.add_constraint(std::make_unique<Table>(std::vector<VariableId>{0},
                                           std::vector<Table::Entry>{{{1}, 0.1234567}}, 0));
  EXPECT_THROW(write_wcsp(p, out, WcspWriteOptions{6}), std::invalid_argument);
}

// The variables every case draws its scope from: small domains of several shapes.
constexpr const char* kKindVariables = R"(variables:
  - {name: a, int: [0, 3]}
  - {name: b, int: [-1, 2]}
  - {name: c, int: [0, 4]}
  - {name: d, values: [0, 2, 5]}
  - {name: e, int: [0, 3]}
)";

// Problems of one constraint each: every registered kind by its own example
// (ConstraintKindInfo::example, over its first example_arity variables), soft with weight 3
// and hard, so a kind is covered by being registered; then the cases examples do not reach
// (an all_different over differing domains, with offsets; fractional weights).
struct KindProblem {
  std::string entry;  // the constraint as a problem file writes it
  std::unique_ptr<Problem> problem;
};

std::vector<KindProblem> kind_problems() {
  std::vector<std::string> entries;
  const ConstraintKinds& kinds = ConstraintKinds::global();
  for (const std::string& name : kinds.names()) {
    const ConstraintKindInfo& info = kinds.get(name, {});
    std::string scope;
    for (std::size_t i = 0; i < info.example_arity; ++i) scope += std::string(i ? ", " : "") + "abcde"[i];
    const std::string fields = info.example.empty() ? "" : ", " + info.example;
    entries.push_back("{kind: " + name + ", scope: [" + scope + "], weight: 3" + fields + "}");
    entries.push_back("{kind: " + name + ", scope: [" + scope + "], hard: true" + fields + "}");
  }
  entries.push_back("{kind: all_different, scope: [a, b, c], offsets: [0, 1, 2], weight: 4}");
  entries.push_back("{kind: all_different, scope: [a, b, d]}");  // d's domain differs: a table
  entries.push_back("{kind: stretch, scope: [a, b, c, e], min: 2, weight: 1.5}");
  entries.push_back("{kind: linear, scope: [a, c], op: '==', rhs: 3, weight: 0.25}");
  std::vector<KindProblem> problems;
  for (const std::string& entry : entries) {
    problems.push_back({entry, parse_problem("name: kind\n" + std::string(kKindVariables) +
                                                 "constraints:\n  - " + entry + "\n",
                                             "kind.yaml")});
  }
  return problems;
}

TEST(KindProblems, TakeEveryRegisteredKind) {
  const auto problems = kind_problems();
  std::set<std::string> kinds;
  for (const auto& p : problems) kinds.insert(std::string(p.problem->constraint(0).kind()));
  for (const std::string& name : ConstraintKinds::global().names()) EXPECT_TRUE(kinds.count(name)) << name;
  for (const char* name : {"equals", "not_in", "table", "stretch", "in", "expression"}) {
    EXPECT_TRUE(kinds.count(name)) << name;
  }
}

// Writes each problem with `write` (which returns the factor its costs were multiplied by),
// reads it back with `read`, and compares the scores of random assignments: soft costs equal
// (times the factor), feasibility equal. `by_index`: the format's values are domain indices
// (.wcsp, .cfn), else the values themselves.
template <class Write, class Read>
void check_round_trip(const std::vector<KindProblem>& problems, Write write, Read read,
                      bool by_index) {
  std::mt19937_64 rng(11);
  for (const auto& [entry, original] : problems) {
    SCOPED_TRACE(entry);
    std::stringstream text;
    const double scale = write(*original, text);
    const std::unique_ptr<Problem> back = read(text.str());
    const std::size_t n = original->num_variables();
    ASSERT_EQ(back->num_variables(), n);
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<double> values(n), written(n);
      for (VariableId v = 0; v < n; ++v) {
        const Domain& d = original->domain(v);
        const std::size_t i = std::uniform_int_distribution<std::size_t>(0, d.size() - 1)(rng);
        values[v] = d.value_at(i);
        written[v] = by_index ? back->domain(v).value_at(i) : values[v];
      }
      const Score want = original->score(values);
      const Score got = back->score(written);
      EXPECT_EQ(want.feasible(), got.feasible()) << "trial " << trial;
      if (want.feasible()) {
        EXPECT_NEAR(want.soft * scale, got.soft, 1e-9 * scale) << "trial " << trial;
      }
    }
  }
}

// Every registered kind over finite domains goes to .wcsp as a cost table (or its own table,
// or salldiff): read back, the problem scores every assignment as the kind itself does
// (soft: the weighted cost, fractional ones scaled to integers; hard: feasibility), on random
// assignments.
TEST(WcspWriter, EveryKindIsWrittenAsATableThatScoresAsTheKind) {
  check_round_trip(
      kind_problems(),
      [](const Problem& p, std::ostream& out) { return write_wcsp(p, out, WcspWriteOptions{6}); },
      [](const std::string& text) {
        std::istringstream in(text);
        return parse_wcsp(in, "kind.wcsp");
      },
      true);
}

// The same through .cfn and through this project's problem file (sightline convert --to
// cfn|yaml).
TEST(TableWriters, EveryKindGoesToCfnAndToAProblemFileAndScoresAsTheKind) {
  const auto problems = kind_problems();
  check_round_trip(
      problems, [](const Problem& p, std::ostream& out) { write_cfn(p, out); return 1.0; },
      [](const std::string& text) { return parse_cfn(text, "kind.cfn"); }, true);
  check_round_trip(
      problems, [](const Problem& p, std::ostream& out) { write_problem_yaml(p, out); return 1.0; },
      [](const std::string& text) { return parse_problem(text, "kind.yaml"); }, false);
}

TEST(TableWriters, RefuseAContinuousScopeNamingIt) {
  ProblemBuilder b("continuous");
  b.real("x", 0, 1);
  b.integer("y", 0, 2);
  b.constrain("linear", {"x", "y"}, spec_from({{"op", "<="}, {"rhs", 1}}));
  const auto p = b.build();
  std::stringstream out;
  try {
    write_problem_yaml(*p, out);
    ADD_FAILURE() << "written";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("variable x is continuous"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_cfn(*p, out), std::invalid_argument);
}

}  // namespace
}  // namespace sightline::csp
