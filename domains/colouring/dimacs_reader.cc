#include "sightline/domains/colouring/dimacs_reader.h"

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "sightline/csp/input_error.h"

namespace sightline::colouring {
namespace {

// Far beyond any benchmark, and small enough that a typo in the p line cannot ask for
// gigabytes of vertex names before the first edge is read.
constexpr std::uint64_t kMaxVertices = 100'000'000;

struct Token {
  std::string_view text;
  int column;  // 1-based
};

// Splits a line on blanks, remembering where each token starts.
void tokenize(std::string_view line, std::vector<Token>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > begin) tokens.push_back({line.substr(begin, i - begin), static_cast<int>(begin) + 1});
  }
}

class Parser {
 public:
  explicit Parser(std::string origin) : origin_(std::move(origin)) {}

  Graph parse(std::istream& in) {
    Graph graph(std::filesystem::path(origin_).stem().string());
    std::string line;
    std::vector<Token> tokens;
    while (std::getline(in, line)) {
      ++line_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      tokenize(line, tokens);
      if (tokens.empty() || tokens[0].text == "c") continue;
      if (tokens[0].text == "p") {
        read_problem_line(tokens, graph);
      } else if (tokens[0].text == "e") {
        read_edge_line(tokens, graph);
      } else {
        fail(tokens[0].column, "expected a 'c' (comment), 'p' (problem) or 'e' (edge) line, got '" +
                                   std::string(tokens[0].text) + "'");
      }
    }
    if (in.bad()) fail(0, "read error");
    if (!seen_p_) {
      throw csp::InputError({origin_, 0, 0},
                            "no 'p edge VERTICES EDGES' line: this is not a DIMACS graph");
    }
    if (declared_edges_ != edge_lines_ && declared_edges_ != graph.num_edges()) {
      throw csp::InputError({origin_, p_line_, 0},
                            "the p line declares " + std::to_string(declared_edges_) +
                                " edges but the file has " + std::to_string(edge_lines_) +
                                " 'e' lines (" + std::to_string(graph.num_edges()) +
                                " distinct edges)");
    }
    return graph;
  }

 private:
  [[noreturn]] void fail(int column, const std::string& message) const {
    throw csp::InputError({origin_, line_, column}, message);
  }

  std::uint64_t read_count(const Token& token, const char* what) const {
    std::uint64_t value = 0;
    const char* end = token.text.data() + token.text.size();
    const auto [ptr, ec] = std::from_chars(token.text.data(), end, value);
    if (ec != std::errc() || ptr != end) {
      fail(token.column, std::string("expected ") + what + " (a non-negative integer), got '" +
                             std::string(token.text) + "'");
    }
    return value;
  }

  void read_problem_line(const std::vector<Token>& tokens, Graph& graph) {
    if (seen_p_) {
      fail(1, "a second 'p' line (the first is on line " + std::to_string(p_line_) + ")");
    }
    if (tokens.size() != 4 || (tokens[1].text != "edge" && tokens[1].text != "col")) {
      fail(1, "expected 'p edge VERTICES EDGES'");
    }
    const std::uint64_t vertices = read_count(tokens[2], "the number of vertices");
    if (vertices == 0 || vertices > kMaxVertices) {
      fail(tokens[2].column, "the number of vertices must be in [1, " +
                                 std::to_string(kMaxVertices) + "], got " +
                                 std::string(tokens[2].text));
    }
    declared_edges_ = read_count(tokens[3], "the number of edges");
    for (std::uint64_t v = 1; v <= vertices; ++v) graph.add_vertex("v" + std::to_string(v));
    seen_p_ = true;
    p_line_ = line_;
  }

  void read_edge_line(const std::vector<Token>& tokens, Graph& graph) {
    if (!seen_p_) fail(1, "an edge before the 'p edge VERTICES EDGES' line");
    if (tokens.size() != 3) fail(1, "expected 'e U V' (two vertex numbers)");
    const std::uint64_t n = graph.num_vertices();
    VertexId ends[2];
    for (int i = 0; i < 2; ++i) {
      const Token& t = tokens[1 + i];
      const std::uint64_t v = read_count(t, "a vertex number");
      if (v < 1 || v > n) {
        fail(t.column, "vertex " + std::string(t.text) + " is out of range: the p line declares " +
                           std::to_string(n) + " vertices, numbered from 1");
      }
      ends[i] = static_cast<VertexId>(v - 1);
    }
    if (ends[0] == ends[1]) {
      fail(tokens[2].column,
           "self loop on vertex " + std::string(tokens[1].text) + ": no colouring can satisfy it");
    }
    graph.add_edge(ends[0], ends[1]);
    ++edge_lines_;
  }

  std::string origin_;
  int line_ = 0;
  bool seen_p_ = false;
  int p_line_ = 0;
  std::uint64_t declared_edges_ = 0;
  std::uint64_t edge_lines_ = 0;
};

}  // namespace

Graph parse_dimacs_graph(std::istream& in, const std::string& origin) {
  return Parser(origin).parse(in);
}

Graph read_dimacs_graph(const std::string& path) {
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path))
    throw csp::InputError({path, 0, 0}, "cannot open the graph file");
  return parse_dimacs_graph(in, path);
}

}  // namespace sightline::colouring
