// The colouring problem: built as documented, its cost is the number of conflicting edges,
// and the solvers find the known chromatic numbers of small graphs.
#include "sightline/domains/colouring/colouring_problem.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "sightline/csp/input_error.h"
#include "sightline/solvers/registry.h"

namespace sightline::colouring {
namespace {

std::string example(const std::string& file) {
  return std::string(SIGHTLINE_SOURCE_DIR) + "/examples/graphs/" + file;
}

TEST(ColouringProblem, HasOneVariablePerVertexAndOneNotEqualPerEdge) {
  const Graph g = read_graph_file(example("australia.yaml"));
  const auto p = build_colouring_problem(g, 3);
  ASSERT_EQ(p->num_variables(), 7u);
  for (VertexId v = 0; v < g.num_vertices(); ++v) {
    EXPECT_EQ(p->variable(v).name, g.vertex_name(v));
    EXPECT_EQ(p->variable(v).domain.describe(), "int[0,2]");
  }
  ASSERT_EQ(p->num_constraints(), g.num_edges());
  for (csp::ConstraintId c = 0; c < p->num_constraints(); ++c) {
    const csp::Constraint& k = p->constraint(c);
    EXPECT_EQ(k.kind(), "not_equal");
    EXPECT_FALSE(k.is_hard());
    EXPECT_EQ(k.weight(), 1.0);
    ASSERT_EQ(k.scope().size(), 2u);
    EXPECT_EQ(k.scope()[0], g.edges()[c].a);
    EXPECT_EQ(k.scope()[1], g.edges()[c].b);
    EXPECT_EQ(k.label(), g.vertex_name(g.edges()[c].a) + " != " + g.vertex_name(g.edges()[c].b));
  }
}

TEST(ColouringProblem, CostIsTheIndependentCountOfConflictingEdges) {
  const Graph g = read_graph_file(example("myciel4.col"));
  const auto p = build_colouring_problem(g, 3);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> colour(0, 2);
  std::vector<double> c(g.num_vertices());
  for (int trial = 0; trial < 200; ++trial) {
    for (double& x : c) x = colour(rng);
    EXPECT_EQ(p->cost(c), static_cast<double>(count_conflicts(g, c)));
    EXPECT_TRUE(p->is_feasible(c));  // all soft: the k-1 problem keeps an optimum
  }
}

TEST(ColouringProblem, AHandMadeFiveColouringOfTheQueenGraphCostsNothing) {
  // colour(r, c) = (2r + c) mod 5: rows differ by c, columns by 2dr, diagonals by 3dr or dr,
  // never 0 mod 5. Vertex r*5+c is square (r, c).
  const Graph g = read_graph_file(example("queen5_5.col"));
  std::vector<double> colours(25);
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c) colours[r * 5 + c] = (2 * r + c) % 5;
  }
  EXPECT_EQ(count_conflicts(g, colours), 0u);
  EXPECT_EQ(build_colouring_problem(g, 5)->cost(colours), 0.0);
  colours[1] = colours[0];  // two squares of the first row now clash (and maybe more)
  EXPECT_GE(count_conflicts(g, colours), 1u);
}

TEST(ColouringProblem, RefusesZeroColoursAndUnknownFileTypes) {
  const Graph g = read_graph_file(example("australia.yaml"));
  EXPECT_THROW(build_colouring_problem(g, 0), std::invalid_argument);
  EXPECT_THROW(read_graph_file("graph.txt"), csp::InputError);
}

solvers::SolverResult solve(const csp::Problem& p, const std::string& solver) {
  solvers::SolveContext context;
  context.seed = 3;
  context.limits.time_limit_seconds = 20;  // a safety net only; the runs take milliseconds
  return solvers::SolverRegistry::global().create(solver)->solve(p, p.default_assignment(),
                                                                 context);
}

// Known answer: Australia has 18 proper 3-colourings (6 for the WA-NT-SA triangle, which
// force Q, NSW and V, times 3 for Tasmania) and none with 2 colours.
TEST(ColouringProblem, GridFindsAustraliasChromaticNumberAndCountsItsColourings) {
  const Graph g = read_graph_file(example("australia.yaml"));
  const auto three = solve(*build_colouring_problem(g, 3), "grid");
  EXPECT_EQ(three.cost(), 0.0);
  EXPECT_EQ(three.stop, solvers::StopReason::kProvenOptimal);
  EXPECT_EQ(three.solutions_at_best, 18u);
  EXPECT_EQ(count_conflicts(g, three.best), 0u);
  const auto two = solve(*build_colouring_problem(g, 2), "grid");
  EXPECT_GE(two.cost(), 1.0);
  EXPECT_EQ(two.stop, solvers::StopReason::kProvenOptimal);
}

// myciel3 (the Groetzsch graph) has chromatic number 4: grid proves 3 colours leave a
// conflict (3^11 assignments), sls finds a proper 4-colouring.
TEST(ColouringProblem, Myciel3NeedsFourColours) {
  const Graph g = read_graph_file(example("myciel3.col"));
  const auto three = solve(*build_colouring_problem(g, 3), "grid");
  EXPECT_EQ(three.stop, solvers::StopReason::kProvenOptimal);
  EXPECT_EQ(three.cost(), 1.0);
  EXPECT_EQ(count_conflicts(g, three.best), 1u);
  const auto four = solve(*build_colouring_problem(g, 4), "sls");
  EXPECT_EQ(four.cost(), 0.0);
  EXPECT_EQ(count_conflicts(g, four.best), 0u);
}

// Larger Mycielski graphs are beyond grid; sls reaches their chromatic numbers.
TEST(ColouringProblem, SlsColoursMyciel4AndMyciel5WithTheirChromaticNumbers) {
  for (const auto& [file, chi] : {std::pair{"myciel4.col", 5}, std::pair{"myciel5.col", 6}}) {
    const Graph g = read_graph_file(example(file));
    const auto r = solve(*build_colouring_problem(g, chi), "sls");
    EXPECT_EQ(r.cost(), 0.0) << file;
    EXPECT_EQ(count_conflicts(g, r.best), 0u) << file;
  }
}

}  // namespace
}  // namespace sightline::colouring
