#include "sightline/domains/colouring/yaml_graph.h"

#include <filesystem>

#include "sightline/csp/files/yaml_spec.h"

namespace sightline::colouring {

Graph graph_from_spec(const csp::Spec& document, const std::string& default_name) {
  if (!document.is_map()) document.fail("expected a graph: a map with 'vertices' and 'edges'");
  document.check_keys({"name", "description", "vertices", "edges"});
  Graph graph(document.string_or("name", default_name));

  for (const csp::Spec& v : document.at("vertices").items("a list of vertex names")) {
    const std::string& name = v.as_string("a vertex name");
    if (name.empty()) v.fail("a vertex needs a non-empty name");
    if (graph.find_vertex(name) >= 0) v.fail("vertex '" + name + "' is declared twice");
    graph.add_vertex(name);
  }

  for (const csp::Spec& e : document.at("edges").items("a list of edges [a, b]")) {
    const auto& ends = e.items("an edge [a, b]");
    if (ends.size() != 2) e.fail("expected an edge [a, b] of two vertex names, got " + e.preview());
    VertexId ids[2];
    for (int i = 0; i < 2; ++i) {
      const std::string& name = ends[i].as_string("a vertex name");
      const std::int64_t id = graph.find_vertex(name);
      if (id < 0) ends[i].fail("unknown vertex '" + name + "' (declare it under 'vertices')");
      ids[i] = static_cast<VertexId>(id);
    }
    if (ids[0] == ids[1]) {
      e.fail("self loop on vertex '" + graph.vertex_name(ids[0]) +
             "': no colouring can satisfy it");
    }
    graph.add_edge(ids[0], ids[1]);
  }
  return graph;
}

Graph read_yaml_graph(const std::string& path) {
  return graph_from_spec(csp::read_yaml_file(path), std::filesystem::path(path).stem().string());
}

}  // namespace sightline::colouring
