#include "sightline/solvers/grid.h"

#include <cmath>
#include <sstream>

#include "sightline/csp/incremental_evaluator.h"

namespace sightline::solvers {

namespace {

// Slack of the pre-filter that sends a candidate to exact re-scoring: far above the drift of
// the incremental sums between two re-synchronisations, far below any meaningful difference.
bool maybe_not_worse(const csp::Score& candidate, const csp::Score& best) {
  const double hard_slack = 1e-9 * (1 + std::abs(best.hard));
  const double soft_slack = 1e-9 * (1 + std::abs(best.soft));
  if (candidate.hard > best.hard + hard_slack) return false;
  if (candidate.hard < best.hard - hard_slack) return true;
  return candidate.soft <= best.soft + soft_slack;
}

constexpr std::uint64_t kResynchronisePeriod = 1u << 16;

}  // namespace

const OptionSchema<GridSolver::Options>& GridSolver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.integer("points", &Options::points,
              "lattice points per continuous dimension, endpoints included (>= 1)", 1);
    s.integer("max_points", &Options::max_points,
              "largest number of assignments the grid agrees to enumerate (>= 1)", 1);
    return s;
  }();
  return schema;
}

std::string GridSolver::Options::validate() const {
  if (points < 1) return "points must be at least 1, got " + std::to_string(points);
  if (max_points < 1) return "max_points must be at least 1, got " + std::to_string(max_points);
  return "";
}

GridSolver::GridSolver(std::string name, Options options)
    : name_(std::move(name)), options_(options) {}

std::size_t GridSolver::axis_size(const csp::Problem& problem, csp::VariableId var) const {
  const csp::Domain& d = problem.domain(var);
  if (d.is_discrete()) return d.size();
  if (d.lower() == d.upper()) return 1;
  return static_cast<std::size_t>(options_.points);
}

double GridSolver::axis_value(const csp::Domain& domain, std::size_t size, std::size_t index) {
  if (domain.is_discrete()) return domain.value_at(index);
  if (size == 1) return domain.middle();
  if (index + 1 == size) return domain.upper();  // exactly the bound, no round-off
  const double t = static_cast<double>(index) / static_cast<double>(size - 1);
  return domain.lower() + (domain.upper() - domain.lower()) * t;
}

double GridSolver::lattice_size(const csp::Problem& problem) const {
  double total = 1;
  for (csp::VariableId v = 0; v < problem.num_variables(); ++v) {
    total *= static_cast<double>(axis_size(problem, v));
  }
  return total;
}

std::string GridSolver::unsuitable_reason(const csp::Problem& problem) const {
  const double size = lattice_size(problem);
  if (size <= static_cast<double>(options_.max_points)) return "";
  std::ostringstream out;
  out << "the grid has " << size << " points, above max_points = " << options_.max_points
      << " (raise max_points, or lower points for continuous dimensions)";
  return out.str();
}

void GridSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                            const SolveContext& context, SolverResult& result) {
  if (std::string why = unsuitable_reason(problem); !why.empty()) {
    throw GridTooLarge("grid on '" + problem.name() + "': " + why);
  }
  (void)start;
  Budget budget(context, 1024);
  const std::size_t n = problem.num_variables();
  sizes_.resize(n);
  digits_.assign(n, 0);
  std::uint64_t total = 1;
  for (csp::VariableId v = 0; v < n; ++v) {
    sizes_[v] = axis_size(problem, v);
    total *= sizes_[v];
  }

  // The first point: every variable at its first grid value.
  result.best.resize(n);
  for (csp::VariableId v = 0; v < n; ++v) {
    result.best[v] = axis_value(problem.domain(v), sizes_[v], 0);
  }
  csp::IncrementalEvaluator evaluator(problem, result.best);
  csp::Score best = problem.score(result.best);
  std::uint64_t at_best = 1;
  std::uint64_t visited = 1;
  budget.note_best(visited, 0, &best);  // the first point is the first best
  result.stop = StopReason::kCompleted;
  result.message.clear();

  while (visited < total) {
    if (budget.exhausted(visited, visited)) {
      result.stop = budget.reason();
      break;
    }
    // Advance the odometer: turn digit 0; on wrap-around reset it and carry to the next.
    for (csp::VariableId v = 0; v < n; ++v) {
      const bool wraps = ++digits_[v] == sizes_[v];
      if (wraps) digits_[v] = 0;
      evaluator.assign(v, axis_value(problem.domain(v), sizes_[v], digits_[v]));
      if (!wraps) break;
    }
    ++visited;
    if (visited % kResynchronisePeriod == 0) evaluator.resynchronise();
    if (!maybe_not_worse(evaluator.score(), best)) continue;
    const csp::Score exact = problem.score(evaluator.values());
    if (exact.better_than(best)) {
      best = exact;
      at_best = 1;
      result.best = evaluator.values();
      budget.note_best(visited, 0, &best);
    } else if (!best.better_than(exact)) {
      ++at_best;
    }
  }

  const bool finished = visited == total;
  if (finished) {
    result.stop = problem.all_discrete() ? StopReason::kProvenOptimal : StopReason::kCompleted;
  }
  result.solutions_at_best = finished ? at_best : 0;
  if (!finished) {
    result.message =
        "stopped after " + std::to_string(visited) + " of " + std::to_string(total) + " points";
  }
  result.evaluations = visited;
  result.iterations = visited;
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
