// Writing .wcsp: every instance read, written and read back scores every assignment tried
// the same (feasibility and soft cost); problems built in C++ keep their weighted costs;
// what .wcsp cannot express is refused by name.
#include "sightline/csp/files/wcsp_writer.h"

#include <gtest/gtest.h>

#include "sightline/csp/kinds/builder.h"

#include <random>
#include <sstream>

#include "tests/csp/brute_force.h"
#include "sightline/csp/files/cfn_reader.h"
#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/files/table_writers.h"
#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/csp/kinds/all_different.h"
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
  }
}

struct KindCase {
  std::string kind;
  std::vector<std::string> scope;
  Spec params;
  double weight;
  bool hard;
};

// A constraint of each built-in kind over small finite domains (integer weighted costs).
std::vector<KindCase> kind_cases() {
  return {
      {"not_equal", {"a", "b"}, Spec(), 3, false},
      {"not_equal", {"a", "c"}, Spec(), 1, true},
      {"linear", {"a", "b", "c"}, spec_from({{"coefficients", std::vector<double>{1, 2, -1}}, {"op", "<="}, {"rhs", 2}}), 2, false},
      {"linear", {"a", "c"}, spec_from({{"op", "=="}, {"rhs", 3}}), 1, true},
      {"abs_deviation", {"b"}, spec_from({{"target", 1}}), 1, false},
      {"expression", {"a", "b"}, spec_from({{"formula", "abs(a - 2*b)"}}), 1, false},
      {"all_different", {"a", "b", "c"}, spec_from({{"offsets", std::vector<double>{0, 1, 2}}}), 4, false},
      {"all_different", {"a", "b", "d"}, Spec(), 1, false},  // d's domain differs: a table
      {"in", {"d"}, spec_from({{"values", std::vector<double>{0, 5}}}), 2, false},
  };
}

// Writes a problem holding each case with `write`, reads it back with `read`, and compares
// the scores of random assignments: soft costs equal, feasibility equal. `by_index`: the
// format's values are domain indices (.wcsp, .cfn), else the values themselves.
template <class Write, class Read>
void check_round_trip(const std::vector<KindCase>& cases, Write write, Read read, bool by_index) {
  std::mt19937_64 rng(11);
  for (const KindCase& k : cases) {
    ProblemBuilder b("kind-" + k.kind);
    b.integer("a", 0, 3);
    b.integer("b", -1, 2);
    b.integer("c", 0, 4);
    b.values("d", {0, 2, 5});
    b.constrain(k.kind, k.scope, k.params.is_map() ? k.params : Spec::map({}), k.weight, k.hard);
    const std::unique_ptr<Problem> original = b.build();
    std::stringstream text;
    write(*original, text);
    const std::unique_ptr<Problem> back = read(text.str());
    ASSERT_EQ(back->num_variables(), original->num_variables()) << k.kind;
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<double> values(4), written(4);
      for (VariableId v = 0; v < 4; ++v) {
        const Domain& d = original->domain(v);
        const std::size_t i = std::uniform_int_distribution<std::size_t>(0, d.size() - 1)(rng);
        values[v] = d.value_at(i);
        written[v] = by_index ? back->domain(v).value_at(i) : values[v];
      }
      const Score want = original->score(values);
      const Score got = back->score(written);
      EXPECT_EQ(want.feasible(), got.feasible()) << k.kind << " trial " << trial;
      if (want.feasible()) {
        EXPECT_NEAR(want.soft, got.soft, 1e-9) << k.kind << " trial " << trial;
      }
    }
  }
}

// Every built-in kind over finite domains goes to .wcsp as a cost table: read back, the
// problem scores every assignment as the kind itself does (soft: the weighted cost; hard:
// feasibility), on random assignments of small random problems.
TEST(WcspWriter, EveryKindIsWrittenAsATableThatScoresAsTheKind) {
  check_round_trip(kind_cases(), [](const Problem& p, std::ostream& out) { write_wcsp(p, out); },
                   [](const std::string& text) {
                     std::istringstream in(text);
                     return parse_wcsp(in, "kind.wcsp");
                   },
                   true);
}

// The same through .cfn and through this project's problem file (sightline convert --to
// cfn|yaml), with a kind of fractional costs besides (stretch: .wcsp has integer costs only).
TEST(TableWriters, EveryKindGoesToCfnAndToAProblemFileAndScoresAsTheKind) {
  std::vector<KindCase> cases = kind_cases();
  cases.push_back({"stretch", {"a", "b", "c"}, spec_from({{"min", 2}}), 1.5, false});
  check_round_trip(cases, [](const Problem& p, std::ostream& out) { write_cfn(p, out); },
                   [](const std::string& text) { return parse_cfn(text, "kind.cfn"); }, true);
  check_round_trip(cases, [](const Problem& p, std::ostream& out) { write_problem_yaml(p, out); },
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
