#include "sightline/solvers/bnb.h"

#include "sightline/solvers/detail/bnb_search.h"
#include "sightline/solvers/detail/bnb_soft_search.h"
#include "sightline/solvers/detail/bnb_wcsp_view.h"

namespace sightline::solvers {

const OptionSchema<BranchAndBoundSolver::Options>& BranchAndBoundSolver::Options::schema() {
  static const OptionSchema<Options> s =
      OptionSchema<Options>()
          .boolean("count_optimal", &Options::count_optimal,
                   "count the optimal assignments (solutions_at_best); prunes only lb > ub")
          .boolean("use_start_bound", &Options::use_start_bound,
                   "start from the start assignment's cost as upper bound when it is feasible")
          .text("consistency", &Options::consistency,
                "soft arc consistency on integer-cost WCSPs: none, nc, ac, fdac, edac")
          .boolean("last_conflict", &Options::last_conflict,
                   "with soft arc consistency, branch again on the last failed variable");
  return s;
}

std::string BranchAndBoundSolver::Options::validate() const {
  if (consistency != "none" && consistency != "nc" && consistency != "ac" &&
      consistency != "fdac" && consistency != "edac") {
    return "consistency must be none, nc, ac, fdac or edac, got '" + consistency + "'";
  }
  return "";
}

BranchAndBoundSolver::BranchAndBoundSolver(std::string name, Options options)
    : name_(std::move(name)),
      options_(options),
      search_(std::make_unique<detail::BranchAndBoundSearch>()),
      view_(std::make_unique<detail::WcspView>()),
      soft_search_(std::make_unique<detail::SoftArcSearch>()) {}

BranchAndBoundSolver::~BranchAndBoundSolver() = default;

std::string BranchAndBoundSolver::unsuitable_reason(const csp::Problem& problem) const {
  if (!problem.all_discrete()) return "needs discrete domains (every variable)";
  return "";
}

void BranchAndBoundSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                      const SolveContext& context, SolverResult& result) {
  Budget budget(context, 1);  // a branch costs far more than reading the clock
  // The start may alias result.best; the search copies it before writing the result.
  const csp::Assignment start_copy(start.begin(), start.end());
  problem.check_assignment(start_copy);
  using Level = detail::SoftArcConsistency::Level;
  const std::string unsuited =
      options_.consistency == "none" ? "" : detail::build_wcsp_view(problem, *view_);
  if (options_.consistency != "none" && unsuited.empty()) {
    detail::SoftArcSearch::Settings settings;
    settings.level = options_.consistency == "nc"     ? Level::kNode
                     : options_.consistency == "ac"   ? Level::kArc
                     : options_.consistency == "fdac" ? Level::kDirectional
                                                      : Level::kExistential;
    settings.count_mode = options_.count_optimal;
    settings.use_start = options_.use_start_bound;
    settings.last_conflict = options_.last_conflict;
    soft_search_->run(problem, *view_, start_copy, settings, budget, result);
  } else {
    search_->run(problem, start_copy, options_.count_optimal, options_.use_start_bound, budget,
                 result);
    // Say why the consistency asked for was not used.
    if (!unsuited.empty()) result.message += "; forward checking only: " + unsuited;
  }
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
