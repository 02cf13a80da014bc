// Reading graphs in the DIMACS colouring format (.col), the standard benchmark format.
//
//   c any comment
//   p edge VERTICES EDGES      (also "p col ..."; exactly one, before any edge)
//   e U V                      (1-based vertex numbers, one edge per line)
//
// Vertices are named "v1" .. "vN". An edge listed twice (as many files do, once per
// direction) is one edge; the p line may count either the `e` lines or the distinct edges,
// anything else is an error. Every malformed line is a csp::InputError naming the file, the
// line and the column, and what was expected: a missing or repeated p line, a non-integer,
// a vertex out of range, a self loop (which no colouring can satisfy).
#pragma once

#include <istream>
#include <string>

#include "sightline/domains/colouring/graph.h"

namespace sightline::colouring {

// Reads a .col file; an unreadable file is an InputError naming it.
Graph read_dimacs_graph(const std::string& path);
// Parses DIMACS text from a stream; `origin` names it in errors and becomes the graph's name
// (without directories or extension).
Graph parse_dimacs_graph(std::istream& in, const std::string& origin);

}  // namespace sightline::colouring
