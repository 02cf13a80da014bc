// Writing .wcsp: every instance read, written and read back scores every assignment tried
// the same (feasibility and soft cost); problems built in C++ keep their weighted costs;
// what .wcsp cannot express is refused by name.
#include "sightline/csp/files/wcsp_writer.h"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "tests/csp/brute_force.h"
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
  Problem p;
  p.add_variable("x", Domain::integer_range(0, 1));
  p.add_variable("y", Domain::integer_range(0, 1));
  p.add_constraint(std::make_unique<NotEqual>(0, 1));
  std::ostringstream out;
  try {
    write_wcsp(p, out);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not_equal"), std::string::npos) << e.what();
  }
  Problem q;
  q.add_variable("x", Domain::integer_range(0, 1));
  q.add_constraint(std::make_unique<Table>(std::vector<VariableId>{0},
                                           std::vector<Table::Entry>{{{0}, 0.5}}, 0));
  EXPECT_THROW(write_wcsp(q, out), std::invalid_argument);
  Problem r;
  r.add_variable("x", Domain::real_interval(0, 1));
  EXPECT_THROW(write_wcsp(r, out), std::invalid_argument);
  // salldiff compares indices: value 1 of {0, 1} and value 1 of {1, 2} have different ones.
  Problem s;
  s.add_variable("x", Domain::integer_range(0, 1));
  s.add_variable("y", Domain::integer_range(1, 2));
  s.add_constraint(std::make_unique<AllDifferent>(std::vector<VariableId>{0, 1}));
  EXPECT_THROW(write_wcsp(s, out), std::invalid_argument);
}

}  // namespace
}  // namespace sightline::csp
