// The toulbar2 adapter, when the toulbar2 program is installed (skipped otherwise): on
// toulbar2's own instances it proves the same optimum as bnb (and the known one), with a
// solution that scores that cost here; it proves infeasibility; it keeps a time limit on a
// problem it cannot finish, returning its best; and it declares unsuitable what .wcsp cannot
// hold (costs of more than 6 decimal places; fractional ones go scaled and agree with bnb).
// Registration follows the binary's presence.
#include "sightline/solvers/toulbar2/toulbar2_solver.h"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <random>

#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/csp/kinds/builder.h"
#include "sightline/csp/kinds/table.h"
#include "sightline/domains/colouring/colouring_problem.h"
#include "sightline/solvers/registry.h"
#include "tests/solvers/stop_request.h"

namespace sightline::solvers {
namespace {

const std::string kDataDir = std::string(SIGHTLINE_SHARED_DIR) + "/data/wcsp/";

std::unique_ptr<Solver> toulbar2() {
  return std::make_unique<Toulbar2Solver>("toulbar2", Toulbar2Solver::Options{});
}

#define SKIP_WITHOUT_TOULBAR2() \
  if (!find_toulbar2()) GTEST_SKIP() << "toulbar2 is not installed"

TEST(Toulbar2Solver, IsRegisteredExactlyWhenItsProgramIsFound) {
  SolverRegistry registry;
  EXPECT_EQ(register_toulbar2_solver(registry), find_toulbar2().has_value());
  EXPECT_EQ(registry.contains("toulbar2"), find_toulbar2().has_value());
  EXPECT_FALSE(find_toulbar2("/nonexistent/toulbar2"));
}

class Toulbar2Instance : public ::testing::TestWithParam<std::string> {};

TEST_P(Toulbar2Instance, ProvesTheSameOptimumAsBnb) {
  SKIP_WITHOUT_TOULBAR2();
  const auto problem = csp::read_wcsp_file(kDataDir + GetParam() + ".wcsp");
  SolveContext context;
  context.limits.max_iterations = 2'000'000;  // bnb's nodes; only a guard against a hang
  const SolverResult exact = SolverRegistry::global().create("bnb")->solve(
      *problem, problem->default_assignment(), context);
  ASSERT_EQ(exact.stop, StopReason::kProvenOptimal);
  const SolverResult r = toulbar2()->solve(*problem, problem->default_assignment(), {});
  EXPECT_EQ(r.stop, StopReason::kProvenOptimal) << r.brief_report("toulbar2");
  EXPECT_TRUE(r.feasible()) << r.brief_report("toulbar2");
  EXPECT_EQ(r.cost(), exact.cost()) << r.brief_report("toulbar2");
  std::ifstream ub(kDataDir + GetParam() + ".ub");
  double known = -1;
  ub >> known;
  EXPECT_EQ(r.cost(), known);
  // Its own report agrees with the score here (a disagreement is added to the message).
  EXPECT_EQ(r.message, "toulbar2 proved optimality") << r.message;
  EXPECT_EQ(problem->score(r.best).soft, r.cost());
}

INSTANTIATE_TEST_SUITE_P(Toulbar2ValidationSet, Toulbar2Instance,
                         ::testing::Values("4queens", "base2", "example", "golomb4", "magic3",
                                           "oconnell", "sudoku", "warehouse", "zebra"));

TEST(Toulbar2Solver, ProvesAnInfeasibleProblemInfeasible) {
  SKIP_WITHOUT_TOULBAR2();
  // x != y and x == y, both hard.
  csp::Problem p("infeasible");
  const auto x = p.add_variable("x", csp::Domain::integer_range(0, 1));
  const auto y = p.add_variable("y", csp::Domain::integer_range(0, 1));
  p.add_constraint(std::make_unique<csp::Table>(
      std::vector<csp::VariableId>{x, y},
      std::vector<csp::Table::Entry>{{{0, 0}, 1}, {{1, 1}, 1}}, 0.0, 1.0, true));
  p.add_constraint(std::make_unique<csp::Table>(
      std::vector<csp::VariableId>{x, y},
      std::vector<csp::Table::Entry>{{{0, 1}, 1}, {{1, 0}, 1}}, 0.0, 1.0, true));
  const SolverResult r = toulbar2()->solve(p, p.default_assignment(), {});
  EXPECT_EQ(r.stop, StopReason::kCompleted);
  EXPECT_EQ(r.message, "toulbar2 proved infeasible");
  EXPECT_FALSE(r.feasible());
}

// A random Max-CSP toulbar2 cannot prove in a second: 60 variables of 8 values, 400 dense
// binary tables of costs 0..9.
std::unique_ptr<csp::Problem> hard_max_csp() {
  auto p = std::make_unique<csp::Problem>("random");
  std::mt19937 rng(1);
  for (int i = 0; i < 60; ++i) p->add_variable("v" + std::to_string(i), csp::Domain::integer_range(0, 7));
  std::uniform_int_distribution<int> var(0, 59), cost(0, 9);
  for (int k = 0; k < 400; ++k) {
    const int a = var(rng);
    int b = var(rng);
    while (b == a) b = var(rng);
    std::vector<csp::Table::Entry> entries;
    for (int i = 0; i < 8; ++i) {
      for (int j = 0; j < 8; ++j) entries.push_back({{double(i), double(j)}, double(cost(rng))});
    }
    p->add_constraint(std::make_unique<csp::Table>(
        std::vector<csp::VariableId>{csp::VariableId(a), csp::VariableId(b)}, entries, 0.0));
  }
  return p;
}

TEST(Toulbar2Solver, StopsAtTheTimeLimitWithItsBestSolution) {
  SKIP_WITHOUT_TOULBAR2();
  const auto p = hard_max_csp();
  SolveContext context;
  context.limits.time_limit_seconds = 1.0;
  const SolverResult r = toulbar2()->solve(*p, p->default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kTimeLimit) << r.brief_report("toulbar2");
  EXPECT_TRUE(r.feasible());
  EXPECT_GT(r.cost(), 0);
  EXPECT_EQ(p->score(r.best).soft, r.cost());
  EXPECT_LT(r.wall_seconds, 3.0);  // interrupted at 1 s, killed a second later at worst
  EXPECT_EQ(r.message.find("toulbar2 reports cost"), std::string::npos) << r.message;
}

// A stop request (Ctrl-C in the Python module) interrupts the program as the time limit does.
TEST(Toulbar2Solver, StopsWhenAskedToWithItsBestSolution) {
  SKIP_WITHOUT_TOULBAR2();
  const auto p = hard_max_csp();
  const SolverResult r = testing::solve_asked_to_stop(*toulbar2(), *p, std::chrono::milliseconds(500));
  EXPECT_EQ(r.stop, StopReason::kInterrupted) << r.brief_report("toulbar2");
  EXPECT_TRUE(r.feasible());
  EXPECT_LT(r.wall_seconds, 3.0);
}

TEST(Toulbar2Solver, DeclaresUnsuitableWhatDotWcspCannotHold) {
  csp::Problem continuous;
  continuous.add_variable("x", csp::Domain::real_interval(0, 1));
  EXPECT_NE(toulbar2()->unsuitable_reason(continuous).find("discrete"), std::string::npos);
  csp::Problem fractional;
  const auto x = fractional.add_variable("x", csp::Domain::integer_range(0, 1));
  fractional.add_constraint(std::make_unique<csp::Table>(
      std::vector<csp::VariableId>{x}, std::vector<csp::Table::Entry>{{{1}, 0.5}}, 0.0));
  EXPECT_EQ(toulbar2()->unsuitable_reason(fractional), "");  // scaled by 10
  // Seven decimal places: more than the scale holds exactly, said by the constraint's name.
  fractional.add_constraint(std::make_unique<csp::Table>(
      std::vector<csp::VariableId>{x}, std::vector<csp::Table::Entry>{{{0}, 0.1234567}}, 0.0));
  fractional.mutable_constraint(1).set_label("fine cost");
  const std::string why = toulbar2()->unsuitable_reason(fractional);
  EXPECT_NE(why.find("fine cost"), std::string::npos) << why;
  EXPECT_NE(why.find("6 decimal places"), std::string::npos) << why;
}

}  // namespace
}  // namespace sightline::solvers

namespace sightline::solvers {
namespace {

// toulbar2 on models made of any kinds (each written as a cost table, wcsp_writer.h): a
// 12-meeting timetable of not_equal, linear, abs_deviation and expression constraints, and
// the colouring problems of `compare`, each with the optimum bnb proves.
void expect_same_optimum_as_bnb(const csp::Problem& problem) {
  SolveContext context;
  context.limits.max_iterations = 5'000'000;
  const SolverResult exact = SolverRegistry::global().create("bnb")->solve(
      problem, problem.default_assignment(), context);
  ASSERT_EQ(exact.stop, StopReason::kProvenOptimal) << problem.name();
  const SolverResult r = toulbar2()->solve(problem, problem.default_assignment(), {});
  EXPECT_EQ(r.stop, StopReason::kProvenOptimal) << r.brief_report("toulbar2");
  EXPECT_NEAR(r.cost(), exact.cost(), 1e-9) << problem.name() << ": " << r.brief_report("toulbar2");
  EXPECT_EQ(problem.score(r.best).soft, r.cost()) << problem.name();
  // toulbar2's own cost (scaled back when the costs are fractional) agrees with the score.
  EXPECT_EQ(r.message, "toulbar2 proved optimality") << problem.name();
}

TEST(Toulbar2Solver, SolvesATimetableOfAnyKindsWithBnbsOptimum) {
  SKIP_WITHOUT_TOULBAR2();
  // 12 meetings in 4 slots of 3 rooms: m<i> = slot * 3 + room, 0..11. Meetings sharing a
  // person are in different slots (hard, an expression over integer division); meetings are
  // all in different slot-rooms (not_equal, hard); some want early slots (linear, soft);
  // some want a given room (abs_deviation of the room, soft, weight 2).
  csp::ProblemBuilder b("meetings");
  for (int i = 0; i < 12; ++i) b.integer("m" + std::to_string(i), 0, 11);
  for (int i = 0; i < 12; ++i) {
    for (int j = i + 1; j < 12; ++j) b.constrain("not_equal", {"m" + std::to_string(i), "m" + std::to_string(j)}, {}, 1, true);
  }
  const int shared[][2] = {{0, 1}, {1, 2}, {2, 3}, {4, 5}, {5, 6}, {0, 7}, {8, 9}, {9, 10}, {10, 11}, {3, 8}};
  for (const auto& p : shared) {
    const std::string a = "m" + std::to_string(p[0]), c = "m" + std::to_string(p[1]);
    b.constrain("expression", {a, c},
                csp::spec_from({{"formula", "floor(" + a + " / 3) == floor(" + c + " / 3)"}}), 1, true);
  }
  for (int i : {0, 4, 8}) {
    b.constrain("linear", {"m" + std::to_string(i)}, csp::spec_from({{"op", "<="}, {"rhs", 5}}), 1);
  }
  for (int i : {1, 5, 9, 11}) {
    b.constrain("abs_deviation", {"m" + std::to_string(i)}, csp::spec_from({{"target", 7}}), 2);
  }
  const auto problem = b.build();
  expect_same_optimum_as_bnb(*problem);
}

TEST(Toulbar2Solver, SolvesTheColouringProblemsOfCompareWithBnbsOptimum) {
  SKIP_WITHOUT_TOULBAR2();
  const std::string graphs = std::string(SIGHTLINE_SOURCE_DIR) + "/examples/graphs/";
  for (const auto& [file, colours] : std::vector<std::pair<std::string, int>>{
           {"australia.yaml", 3}, {"australia.yaml", 2}, {"queen5_5.col", 5}, {"myciel5.col", 6}}) {
    const auto problem = colouring::build_colouring_problem(colouring::read_graph_file(graphs + file), colours);
    expect_same_optimum_as_bnb(*problem);
  }
}

}  // namespace
}  // namespace sightline::solvers

namespace sightline::solvers {
namespace {

// Fractional weighted costs (.wcsp holds integers: the problem goes scaled by 10^d): the
// audit's abs_deviation of weight 1.5, costs in halves and in tenths.
TEST(Toulbar2Solver, SolvesFractionalCostsWithBnbsOptimum) {
  SKIP_WITHOUT_TOULBAR2();
  for (const double step : {0.5, 0.1}) {
    csp::ProblemBuilder b(step == 0.5 ? "halves" : "tenths");
    for (int i = 0; i < 6; ++i) b.integer("r" + std::to_string(i), 0, 4);
    for (int i = 0; i < 6; ++i) {
      const std::string a = "r" + std::to_string(i), c = "r" + std::to_string((i + 1) % 6);
      b.constrain("not_equal", {a, c}, {}, 3 * step);
      b.constrain("abs_deviation", {a}, csp::spec_from({{"target", (i * 7) % 5}}), (i + 1) * step);
    }
    b.constrain("linear", {"r0", "r3"}, csp::spec_from({{"op", ">="}, {"rhs", 6}}), 5 * step);
    b.constrain("equals", {"r5"}, csp::spec_from({{"value", 2}}), 1, true);
    const auto problem = b.build();
    SCOPED_TRACE(problem->name());
    expect_same_optimum_as_bnb(*problem);
  }
}

}  // namespace
}  // namespace sightline::solvers
