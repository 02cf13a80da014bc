#include "sightline/domains/colouring/graph.h"

#include <stdexcept>

namespace sightline::colouring {

VertexId Graph::add_vertex(std::string name) {
  if (name.empty()) throw std::invalid_argument("a vertex needs a name");
  if (ids_.count(name)) throw std::invalid_argument("vertex '" + name + "' is declared twice");
  const auto id = static_cast<VertexId>(names_.size());
  ids_.emplace(name, id);
  names_.push_back(std::move(name));
  return id;
}

bool Graph::add_edge(VertexId a, VertexId b) {
  if (a >= names_.size() || b >= names_.size()) {
    throw std::invalid_argument("edge names a vertex beyond the " + std::to_string(names_.size()) +
                                " of the graph");
  }
  if (a == b) {
    throw std::invalid_argument("self loop on vertex '" + names_[a] +
                                "': no colouring can give a vertex a colour other than its own");
  }
  if (!edge_keys_.insert(key(a, b)).second) return false;
  edges_.push_back(a < b ? Edge{a, b} : Edge{b, a});
  return true;
}

std::int64_t Graph::find_vertex(const std::string& name) const {
  const auto it = ids_.find(name);
  return it == ids_.end() ? -1 : static_cast<std::int64_t>(it->second);
}

bool Graph::has_edge(VertexId a, VertexId b) const { return edge_keys_.count(key(a, b)) != 0; }

std::size_t count_conflicts(const Graph& graph, std::span<const double> colours) {
  if (colours.size() != graph.num_vertices()) {
    throw std::invalid_argument("a colouring of " + std::to_string(graph.num_vertices()) +
                                " vertices needs as many colours, got " +
                                std::to_string(colours.size()));
  }
  std::size_t conflicts = 0;
  for (const Edge& e : graph.edges()) conflicts += colours[e.a] == colours[e.b] ? 1 : 0;
  return conflicts;
}

}  // namespace sightline::colouring
