// YAML graphs: the Australia example, and mistakes reported at their line.
#include "sightline/domains/colouring/yaml_graph.h"

#include <gtest/gtest.h>

#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"

namespace sightline::colouring {
namespace {

Graph parse(const std::string& text) {
  return graph_from_spec(csp::parse_yaml(text, "graph.yaml"), "graph");
}

TEST(YamlGraph, ReadsTheAustraliaExample) {
  const Graph g =
      read_yaml_graph(std::string(SIGHTLINE_SOURCE_DIR) + "/examples/graphs/australia.yaml");
  EXPECT_EQ(g.name(), "australia");
  ASSERT_EQ(g.num_vertices(), 7u);
  EXPECT_EQ(g.num_edges(), 9u);
  const auto id = [&](const char* name) { return static_cast<VertexId>(g.find_vertex(name)); };
  EXPECT_TRUE(g.has_edge(id("WA"), id("NT")));
  EXPECT_TRUE(g.has_edge(id("V"), id("NSW")));
  EXPECT_FALSE(g.has_edge(id("WA"), id("Q")));
  for (const Edge& e : g.edges()) {  // Tasmania is an island
    EXPECT_NE(e.a, id("T"));
    EXPECT_NE(e.b, id("T"));
  }
}

TEST(YamlGraph, UsesTheDefaultNameAndMergesARepeatedEdge) {
  const Graph g = parse("vertices: [a, b]\nedges: [[a, b], [b, a]]\n");
  EXPECT_EQ(g.name(), "graph");
  EXPECT_EQ(g.num_edges(), 1u);
}

void expect_error(const std::string& text, int line, const std::string& part) {
  try {
    parse(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().file, "graph.yaml");
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(YamlGraph, RejectsAnUnknownKey) {
  expect_error("vertices: [a]\nedges: []\ncolors: 3\n", 3, "colors");
}
TEST(YamlGraph, RejectsAMissingEdgeList) { expect_error("vertices: [a]\n", 1, "edges"); }
TEST(YamlGraph, RejectsAVertexDeclaredTwice) {
  expect_error("vertices:\n  - a\n  - a\nedges: []\n", 3, "'a' is declared twice");
}
TEST(YamlGraph, RejectsAnEdgeToAnUnknownVertex) {
  expect_error("vertices: [a, b]\nedges:\n  - [a, b]\n  - [a, c]\n", 4, "unknown vertex 'c'");
}
TEST(YamlGraph, RejectsAnEdgeThatIsNotAPair) {
  expect_error("vertices: [a, b, c]\nedges:\n  - [a, b, c]\n", 3, "two vertex names");
}
TEST(YamlGraph, RejectsASelfLoop) {
  expect_error("vertices: [a, b]\nedges:\n  - [b, b]\n", 3, "self loop on vertex 'b'");
}

}  // namespace
}  // namespace sightline::colouring
