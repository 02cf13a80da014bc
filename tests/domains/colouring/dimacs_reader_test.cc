// DIMACS .col reading: the accepted forms, and every malformed line reported at its line.
#include "sightline/domains/colouring/dimacs_reader.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "sightline/csp/input_error.h"

namespace sightline::colouring {
namespace {

Graph parse(const std::string& text) {
  std::istringstream in(text);
  return parse_dimacs_graph(in, "test.col");
}

// Parses text that must fail; returns the error so its location and message can be checked.
csp::InputError parse_error(const std::string& text) {
  try {
    parse(text);
  } catch (const csp::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return csp::InputError({}, "none");
}

TEST(DimacsReader, ReadsCommentsProblemLineAndEdges) {
  const Graph g = parse("c a triangle and a pendant\n\np edge 4 4\ne 1 2\ne 2 3\ne 3 1\ne 3 4\n");
  EXPECT_EQ(g.name(), "test");
  ASSERT_EQ(g.num_vertices(), 4u);
  EXPECT_EQ(g.vertex_name(0), "v1");
  EXPECT_EQ(g.vertex_name(3), "v4");
  ASSERT_EQ(g.num_edges(), 4u);
  EXPECT_TRUE(g.has_edge(0, 1));
  EXPECT_TRUE(g.has_edge(2, 0));
  EXPECT_TRUE(g.has_edge(3, 2));
  EXPECT_FALSE(g.has_edge(0, 3));
  // Edges are stored with the smaller end first whatever order the file used.
  EXPECT_EQ(g.edges()[2].a, 0u);
  EXPECT_EQ(g.edges()[2].b, 2u);
}

TEST(DimacsReader, AcceptsWindowsLineEndsTabsAndTheColVariant) {
  const Graph g = parse("p col 3 2\r\ne\t1  2\r\ne 2 3\r\n");
  EXPECT_EQ(g.num_vertices(), 3u);
  EXPECT_EQ(g.num_edges(), 2u);
}

TEST(DimacsReader, KeepsAnEdgeListedInBothDirectionsOnce) {
  // The DIMACS queen graphs count both directions in the p line...
  const Graph both = parse("p edge 3 4\ne 1 2\ne 2 1\ne 2 3\ne 3 2\n");
  EXPECT_EQ(both.num_edges(), 2u);
  // ...others count distinct edges; both conventions are accepted.
  const Graph distinct = parse("p edge 3 2\ne 1 2\ne 2 1\ne 2 3\n");
  EXPECT_EQ(distinct.num_edges(), 2u);
}

TEST(DimacsReader, AcceptsAGraphWithoutEdges) {
  const Graph g = parse("p edge 5 0\n");
  EXPECT_EQ(g.num_vertices(), 5u);
  EXPECT_EQ(g.num_edges(), 0u);
}

struct BadInput {
  const char* text;
  int line;
  int column;
  const char* message_part;
};

class DimacsReaderErrors : public testing::TestWithParam<BadInput> {};

TEST_P(DimacsReaderErrors, NameTheLineColumnAndWhatWasExpected) {
  const BadInput& bad = GetParam();
  const csp::InputError e = parse_error(bad.text);
  EXPECT_EQ(e.where().file, "test.col");
  EXPECT_EQ(e.where().line, bad.line) << e.what();
  EXPECT_EQ(e.where().column, bad.column) << e.what();
  EXPECT_NE(std::string(e.what()).find(bad.message_part), std::string::npos) << e.what();
}

INSTANTIATE_TEST_SUITE_P(
    EveryKindOfMistake, DimacsReaderErrors,
    testing::Values(
        BadInput{"", 0, 0, "no 'p edge VERTICES EDGES' line"},
        BadInput{"c only a comment\n", 0, 0, "no 'p edge"},
        BadInput{"c x\ne 1 2\np edge 2 1\n", 2, 1, "an edge before the 'p edge"},
        BadInput{"p edge 2 1\np edge 2 1\ne 1 2\n", 2, 1,
                 "a second 'p' line (the first is on line 1)"},
        BadInput{"p edge 2\n", 1, 1, "expected 'p edge VERTICES EDGES'"},
        BadInput{"p graph 2 1\n", 1, 1, "expected 'p edge VERTICES EDGES'"},
        BadInput{"p edge two 1\n", 1, 8, "expected the number of vertices"},
        BadInput{"p edge -3 1\n", 1, 8, "expected the number of vertices"},
        BadInput{"p edge 0 0\n", 1, 8, "must be in [1, "},
        BadInput{"p edge 999999999999 0\n", 1, 8, "must be in [1, "},
        BadInput{"p edge 3 1.5\n", 1, 10, "expected the number of edges"},
        BadInput{"p edge 3 1\ne 1\n", 2, 1, "expected 'e U V'"},
        BadInput{"p edge 3 1\ne 1 2 3\n", 2, 1, "expected 'e U V'"},
        BadInput{"p edge 3 1\ne 1 x\n", 2, 5, "expected a vertex number"},
        BadInput{"p edge 3 1\ne 0 2\n", 2, 3, "vertex 0 is out of range: the p line declares 3"},
        BadInput{"p edge 3 1\ne 1 4\n", 2, 5, "vertex 4 is out of range"},
        BadInput{"p edge 3 1\ne 2 2\n", 2, 5, "self loop on vertex 2"},
        BadInput{"p edge 3 1\nn 1 5\n", 2, 1,
                 "expected a 'c' (comment), 'p' (problem) or 'e' (edge)"},
        BadInput{"c\n\np edge 3 5\ne 1 2\ne 2 3\n", 3, 0, "declares 5 edges but the file has 2"}));

TEST(DimacsReader, ReportsAMissingFileByName) {
  try {
    read_dimacs_graph("/nonexistent/graph.col");
    FAIL() << "no error";
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().file, "/nonexistent/graph.col");
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
  }
}

// The shipped benchmarks have the sizes of the DIMACS originals (examples/graphs/README.md).
TEST(DimacsReader, ReadsTheShippedBenchmarksWithTheirKnownSizes) {
  struct Known {
    const char* file;
    std::size_t vertices, edges;
  };
  for (const Known& k :
       {Known{"myciel3", 11, 20}, Known{"myciel4", 23, 71}, Known{"myciel5", 47, 236},
        Known{"queen5_5", 25, 160}, Known{"queen6_6", 36, 290}, Known{"queen8_8", 64, 728}}) {
    const Graph g = read_dimacs_graph(std::string(SIGHTLINE_SOURCE_DIR) + "/examples/graphs/" +
                                      k.file + ".col");
    EXPECT_EQ(g.name(), k.file);
    EXPECT_EQ(g.num_vertices(), k.vertices) << k.file;
    EXPECT_EQ(g.num_edges(), k.edges) << k.file;
  }
}

}  // namespace
}  // namespace sightline::colouring
