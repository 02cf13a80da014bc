#include "solvers/bnb.h"

#include "solvers/detail/bnb_search.h"

namespace sightline::solvers {

const OptionSchema<BranchAndBoundSolver::Options>& BranchAndBoundSolver::Options::schema() {
  static const OptionSchema<Options> s =
      OptionSchema<Options>()
          .boolean("count_optimal", &Options::count_optimal,
                   "count the optimal assignments (solutions_at_best); prunes only lb > ub")
          .boolean("use_start_bound", &Options::use_start_bound,
                   "start from the start assignment's cost as upper bound when it is feasible");
  return s;
}

std::string BranchAndBoundSolver::Options::validate() const { return ""; }

BranchAndBoundSolver::BranchAndBoundSolver(std::string name, Options options)
    : name_(std::move(name)),
      options_(options),
      search_(std::make_unique<detail::BranchAndBoundSearch>()) {}

BranchAndBoundSolver::~BranchAndBoundSolver() = default;

std::string BranchAndBoundSolver::unsuitable_reason(const csp::Problem& problem) const {
  if (!problem.all_discrete()) return "needs discrete domains (every variable)";
  return "";
}

void BranchAndBoundSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                      const SolveContext& context, SolverResult& result) {
  Budget budget(context.limits, 1);  // a branch costs far more than reading the clock
  // The start may alias result.best; the search copies it before writing the result.
  const csp::Assignment start_copy(start.begin(), start.end());
  problem.check_assignment(start_copy);
  search_->run(problem, start_copy, options_.count_optimal, options_.use_start_bound, budget,
               result);
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
