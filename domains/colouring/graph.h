// Graph: an undirected simple graph with named vertices, the input of graph colouring.
//
// Readers (DIMACS .col, YAML) fill it; build_colouring_problem turns it into a weighted CSP.
// Edges are kept once each, as (smaller id, larger id), whatever order or repetition the
// input used: DIMACS files commonly list every edge in both directions, and it is the same
// graph. Self loops are refused, since no colouring could ever satisfy them.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace sightline::colouring {

using VertexId = std::uint32_t;

struct Edge {
  VertexId a;  // a < b
  VertexId b;
};

class Graph {
 public:
  explicit Graph(std::string name = "graph") : name_(std::move(name)) {}

  const std::string& name() const { return name_; }
  void set_name(std::string name) { name_ = std::move(name); }

  // Adds a vertex; throws std::invalid_argument on an empty or duplicate name.
  VertexId add_vertex(std::string name);
  // Adds the edge {a, b}. Returns false, adding nothing, when it is already there. Throws
  // std::invalid_argument for a self loop or a vertex id out of range.
  bool add_edge(VertexId a, VertexId b);

  std::size_t num_vertices() const { return names_.size(); }
  std::size_t num_edges() const { return edges_.size(); }
  const std::string& vertex_name(VertexId v) const { return names_[v]; }
  // The vertex of that name, or -1 when there is none.
  std::int64_t find_vertex(const std::string& name) const;
  const std::vector<Edge>& edges() const { return edges_; }
  bool has_edge(VertexId a, VertexId b) const;

 private:
  static std::uint64_t key(VertexId a, VertexId b) {
    return (static_cast<std::uint64_t>(a < b ? a : b) << 32) | (a < b ? b : a);
  }
  std::string name_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, VertexId> ids_;
  std::vector<Edge> edges_;
  std::unordered_set<std::uint64_t> edge_keys_;
};

// The number of edges whose two ends have the same colour; `colours[v]` is vertex v's colour.
// Independent of the CSP layer, so a solver's claim can be checked against it.
std::size_t count_conflicts(const Graph& graph, std::span<const double> colours);

}  // namespace sightline::colouring
