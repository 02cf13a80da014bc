// `sightline colour GRAPH --colours K --solver NAME ...`: colour a graph (DIMACS .col or a
// YAML graph) with K colours, then count conflicting edges independently of the CSP.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/report.h"
#include "apps/solve_options.h"
#include "apps/text_table.h"
#include "sightline/domains/colouring/colouring_problem.h"

namespace sightline::apps {

void add_colour_command(CLI::App& app) {
  struct Args {
    std::string file;
    int colours = 0;
    SolveOptions solve;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "colour", "colour a graph (.col DIMACS or .yaml) so that neighbours differ");
  command->add_option("graph", args->file, "the graph file")->required();
  command->add_option("--colours", args->colours, "number of colours")
      ->required()
      ->check(CLI::Range(1, 1 << 20));
  add_solve_options(*command, args->solve,
                    "write each vertex's colour (from 0), in vertex order, to this file, '-' "
                    "for standard output");
  command->callback([args] {
    const colouring::Graph graph = colouring::read_graph_file(args->file);
    const auto problem = colouring::build_colouring_problem(graph, args->colours);
    auto solver = make_solver(args->solve);
    const solvers::SolveContext context = make_context(args->solve);
    std::cout << "graph " << graph.name() << ": " << graph.num_vertices() << " vertices, "
              << graph.num_edges() << " edges, " << args->colours << " colours\n";
    const solvers::SolverResult result =
        solve_and_print(std::cout, *problem, *solver, context, args->file);
    const std::size_t conflicts = colouring::count_conflicts(graph, result.best);
    std::cout << "independent check: " << count_of(conflicts, "conflicting edge")
              << (conflicts == 0 ? " (a proper colouring)" : "") << '\n';
    if (!args->solve.solution_path.empty()) {
      write_solution(args->solve.solution_path, *problem, result.best, std::cout);
    }
    if (static_cast<double>(conflicts) != result.cost()) {
      throw RunFailed("the solver reports cost " + std::to_string(result.cost()) +
                      " but the independent check counts " + std::to_string(conflicts) +
                      " conflicting edges");
    }
  });
}

}  // namespace sightline::apps
