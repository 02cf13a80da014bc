// Reading a graph written by hand in YAML, for small maps such as Australia's:
//
//   name: australia              # optional; default: the file's name without extension
//   vertices: [WA, NT, SA, Q, NSW, V, T]
//   edges:
//     - [WA, NT]
//     - [WA, SA]
//
// Goes through csp/files/yaml_spec.h, so every error names the file, line and column:
// an unknown key, a repeated vertex, an edge that is not a pair of declared vertices, a
// self loop. A repeated edge is the same edge and is kept once.
#pragma once

#include <string>

#include "sightline/csp/spec.h"
#include "sightline/domains/colouring/graph.h"

namespace sightline::colouring {

Graph read_yaml_graph(const std::string& path);
// Builds the graph from an already parsed document; `default_name` is used when it has no
// `name` field.
Graph graph_from_spec(const csp::Spec& document, const std::string& default_name);

}  // namespace sightline::colouring
