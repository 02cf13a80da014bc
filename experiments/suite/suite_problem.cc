#include "sightline/experiments/suite/suite_problem.h"

#include <filesystem>

#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/domains/colouring/colouring_problem.h"
#include "sightline/domains/colouring/graph.h"
#include "sightline/domains/nqueens/nqueens.h"

namespace sightline::experiments {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

LoadedSuiteProblem load_suite_problem(const SuiteProblem& p) {
  LoadedSuiteProblem out;
  switch (p.kind) {
    case SuiteProblem::Kind::kNQueens:
      out.problem = nqueens::build_nqueens(p.queens);
      out.label = std::to_string(p.queens) + "-queens";
      out.count_broken = [](std::span<const double> rows) { return nqueens::attacking_pairs(rows); };
      out.broken_name = "attacking pairs";
      break;
    case SuiteProblem::Kind::kProblemFile: {
      if (ends_with(p.path, ".yaml") || ends_with(p.path, ".yml")) {
        csp::LoadedProblem loaded = csp::load_problem_file(p.path);
        out.problem = std::move(loaded.problem);
        out.value_labels = std::move(loaded.value_labels);
      } else if (ends_with(p.path, ".wcsp") || ends_with(p.path, ".wcsp.gz") ||
                 ends_with(p.path, ".wcsp.xz") || ends_with(p.path, ".wcsp.bz2")) {
        out.problem = csp::read_wcsp_file(p.path);
      } else {
        throw csp::InputError({p.path, 0, 0},
                              "expected a problem file ending in .yaml, .yml, .wcsp or .wcsp.gz");
      }
      out.label = out.problem->name().empty()
                      ? std::filesystem::path(p.path).stem().string()
                      : out.problem->name();
      break;
    }
    case SuiteProblem::Kind::kGraph: {
      auto graph = std::make_shared<colouring::Graph>(colouring::read_graph_file(p.path));
      out.problem = colouring::build_colouring_problem(*graph, p.colours);
      out.label = graph->name() + " (" + std::to_string(p.colours) + " colours)";
      out.count_broken = [graph](std::span<const double> c) {
        return colouring::count_conflicts(*graph, c);
      };
      out.broken_name = "conflicts";
      break;
    }
  }
  return out;
}

}  // namespace sightline::experiments
