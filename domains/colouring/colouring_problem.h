// Graph colouring as a weighted CSP: give each vertex one of k colours so that the ends of
// every edge differ, or, when k colours are not enough, with as few conflicting edges as
// possible.
//
// One variable per vertex (same name, domain int[0, k-1]) and one soft NotEqual of weight 1
// per edge, so an assignment's cost is exactly its number of conflicting edges and a cost of
// 0 is a proper k-colouring. Soft rather than hard so that "k-1 colours" problems still have
// a meaningful optimum (the fewest conflicts) that every solver can be compared on.
#pragma once

#include <memory>

#include "sightline/csp/problem.h"
#include "sightline/domains/colouring/graph.h"

namespace sightline::colouring {

// Throws std::invalid_argument when colours < 1.
std::unique_ptr<csp::Problem> build_colouring_problem(const Graph& graph, int colours);

// Reads a graph by extension: .col (DIMACS) or .yaml / .yml; anything else is an InputError.
Graph read_graph_file(const std::string& path);

}  // namespace sightline::colouring
