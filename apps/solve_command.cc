// `sightline solve FILE --solver NAME ...`: one problem file, one solver, the result.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/problem_loader.h"
#include "apps/report.h"
#include "apps/solve_options.h"

#include <sstream>

namespace sightline::apps {

void add_solve_command(CLI::App& app) {
  struct Args {
    std::string file;
    LoadOptions load;
    SolveOptions solve;
    std::string format = "text";
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
  command->add_option("--format", args->format,
                      "text (the default) or json: one object with the result and the "
                      "assignment by variable name (labels where the file gives them)")
      ->check(CLI::IsMember({"text", "json"}));
  command->callback([args] {
    const csp::LoadedProblem model = load_model(args->file, args->load);
    const csp::Problem& problem = *model.problem;
    auto solver = make_solver(args->solve);
    const solvers::SolveContext context = make_context(args->solve);
    if (args->format == "json") {
      const solvers::SolverResult result = solve_quietly(problem, *solver, context);
      std::cout << result_json(model, args->solve.solver, result) << '\n';
      if (!args->solve.solution_path.empty() && args->solve.solution_path != "-") {
        std::ostringstream ignored;
        write_solution(args->solve.solution_path, problem, result.best, ignored);
      }
      return;
    }
    std::cout << "problem " << describe_problem(problem) << '\n';
    const solvers::SolverResult result =
        solve_and_print(std::cout, problem, *solver, context, args->file);
    if (!args->solve.solution_path.empty()) {
      write_solution(args->solve.solution_path, problem, result.best, std::cout);
    }
  });
}

}  // namespace sightline::apps
