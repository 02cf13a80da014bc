// `sightline nqueens N --solver NAME ...`: N queens on an N x N board, solved, then checked
// by counting attacking pairs independently of the constraints the solver saw.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/report.h"
#include "apps/solve_options.h"
#include "apps/text_table.h"
#include "sightline/domains/nqueens/nqueens.h"

namespace sightline::apps {

void add_nqueens_command(CLI::App& app) {
  struct Args {
    std::size_t n = 8;
    SolveOptions solve;
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand("nqueens", "place N non-attacking queens");
  command->add_option("n", args->n, "board size (number of queens)")
      ->required()
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}));
  add_solve_options(*command, args->solve,
                    "write the row (from 0) of each column's queen, in column order, to this "
                    "file, '-' for standard output");
  command->callback([args] {
    const auto problem = nqueens::build_nqueens(args->n);
    auto solver = make_solver(args->solve);
    const solvers::SolveContext context = make_context(args->solve);
    std::cout << "problem " << describe_problem(*problem) << '\n';
    const solvers::SolverResult result =
        solve_and_print(std::cout, *problem, *solver, context, problem->name());
    const std::size_t attacks = nqueens::attacking_pairs(result.best);
    std::cout << "independent check: " << count_of(attacks, "attacking pair")
              << (attacks == 0 ? " (a solution)" : "") << '\n';
    if (!args->solve.solution_path.empty()) {
      write_solution(args->solve.solution_path, *problem, result.best, std::cout);
    }
    if ((attacks == 0) != result.feasible()) {
      throw RunFailed("the solver reports " +
                      std::string(result.feasible() ? "a feasible" : "an infeasible") +
                      " placement but the independent check counts " + std::to_string(attacks) +
                      " attacking pairs");
    }
  });
}

}  // namespace sightline::apps
