#include "sightline/domains/colouring/colouring_problem.h"

#include <filesystem>
#include <stdexcept>

#include "sightline/csp/input_error.h"
#include "sightline/csp/kinds/not_equal.h"
#include "sightline/domains/colouring/dimacs_reader.h"
#include "sightline/domains/colouring/yaml_graph.h"

namespace sightline::colouring {

std::unique_ptr<csp::Problem> build_colouring_problem(const Graph& graph, int colours) {
  if (colours < 1) {
    throw std::invalid_argument("a colouring needs at least one colour, got " +
                                std::to_string(colours));
  }
  auto problem =
      std::make_unique<csp::Problem>(graph.name() + " (" + std::to_string(colours) + " colours)");
  const csp::Domain palette = csp::Domain::integer_range(0, colours - 1);
  for (VertexId v = 0; v < graph.num_vertices(); ++v) {
    problem->add_variable(graph.vertex_name(v), palette);
  }
  for (const Edge& e : graph.edges()) {
    auto edge = std::make_unique<csp::NotEqual>(e.a, e.b);
    edge->set_label(graph.vertex_name(e.a) + " != " + graph.vertex_name(e.b));
    problem->add_constraint(std::move(edge));
  }
  return problem;
}

Graph read_graph_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".col") return read_dimacs_graph(path);
  if (ext == ".yaml" || ext == ".yml") return read_yaml_graph(path);
  throw csp::InputError({path, 0, 0},
                        "unknown graph file type '" + ext +
                            "' (expected .col for DIMACS or .yaml/.yml for a YAML graph)");
}

}  // namespace sightline::colouring
