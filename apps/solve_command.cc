// `sightline solve FILE --solver NAME ...`: one problem file, one solver, the result.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/problem_loader.h"
#include "apps/report.h"
#include "apps/solve_options.h"

namespace sightline::apps {

void add_solve_command(CLI::App& app) {
  struct Args {
    std::string file;
    LoadOptions load;
    SolveOptions solve;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "solve", "solve a problem file (.yaml/.yml, .col with --colours, .wcsp/.wcsp.gz, .cfn/.cfn.gz)");
  command->add_option("file", args->file, "the problem file")->required();
  command
      ->add_option("--colours", args->load.colours, "number of colours, for a DIMACS graph (.col)")
      ->check(CLI::Range(1, 1 << 20));
  add_solve_options(*command, args->solve,
                    "write each variable's value (discrete: index from 0 in its domain) to "
                    "this file, '-' for standard output");
  command->callback([args] {
    const auto problem = load_problem(args->file, args->load);
    auto solver = make_solver(args->solve);
    const solvers::SolveContext context = make_context(args->solve);
    std::cout << "problem " << describe_problem(*problem) << '\n';
    const solvers::SolverResult result =
        solve_and_print(std::cout, *problem, *solver, context, args->file);
    if (!args->solve.solution_path.empty()) {
      write_solution(args->solve.solution_path, *problem, result.best, std::cout);
    }
  });
}

}  // namespace sightline::apps
