#include "sightline/solvers/sliding_octree.h"

#include <algorithm>
#include <stdexcept>

#include "sightline/solvers/detail/start.h"

namespace sightline::solvers {

const OptionSchema<SlidingOctreeSolver::Options>& SlidingOctreeSolver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.integer("passes", &Options::passes, "number of passes (>= 1)", 1);
    s.real("initial_size", &Options::initial_size,
           "initial edge length as a fraction of each domain's width (> 0)");
    s.real("initial_size_absolute", &Options::initial_size_absolute,
           "if > 0, initial edge length in the variables' units, overriding initial_size");
    s.real("scale", &Options::scale, "edge length multiplier per pass, in [0.5, 1)");
    s.real("slide", &Options::slide,
           "fraction of the way from the centre to the best the box slides, in (0, 1]");
    return s;
  }();
  return schema;
}

std::string SlidingOctreeSolver::Options::validate() const {
  if (passes < 1) return "passes must be at least 1, got " + std::to_string(passes);
  if (!(initial_size > 0)) {
    return "initial_size must be > 0 (a fraction of the domain width), got " +
           detail::format_real(initial_size);
  }
  if (initial_size_absolute < 0) {
    return "initial_size_absolute must be >= 0 (0 = use initial_size), got " +
           detail::format_real(initial_size_absolute);
  }
  // Below 1/2 the next box would not even cover the best child's region.
  if (!(scale >= 0.5 && scale < 1)) {
    return "scale must be in [0.5, 1) so the next box covers the best child, got " +
           detail::format_real(scale);
  }
  if (!(slide > 0 && slide <= 1)) {
    return "slide must be in (0, 1], got " + detail::format_real(slide);
  }
  return "";
}

SlidingOctreeSolver::SlidingOctreeSolver(std::string name, Options options)
    : name_(std::move(name)), options_(options) {}

std::string SlidingOctreeSolver::unsuitable_reason(const csp::Problem& problem) const {
  if (!problem.all_continuous()) return "needs continuous (real interval) domains only";
  if (problem.num_variables() > kMaxDimensions) {
    return "2^d children per pass: d = " + std::to_string(problem.num_variables()) +
           " variables is above the limit of " + std::to_string(kMaxDimensions);
  }
  return "";
}

void SlidingOctreeSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                     const SolveContext& context, SolverResult& result) {
  if (std::string why = unsuitable_reason(problem); !why.empty()) {
    throw std::invalid_argument("sliding-octree on '" + problem.name() + "': " + why);
  }
  Budget budget(context, 1);
  const std::size_t d = problem.num_variables();
  detail::prepare_start(problem, start, centre_);
  size_.resize(d);
  for (std::size_t k = 0; k < d; ++k) {
    const csp::Domain& domain = problem.domain(static_cast<csp::VariableId>(k));
    size_[k] = options_.initial_size_absolute > 0
                   ? options_.initial_size_absolute
                   : options_.initial_size * (domain.upper() - domain.lower());
  }
  result.best = centre_;
  csp::Score best = problem.score(result.best);
  std::uint64_t evaluations = 1;
  std::uint64_t passes = 0;
  result.stop = StopReason::kCompleted;
  result.message.clear();
  candidate_.resize(d);
  const std::uint64_t children = std::uint64_t{1} << d;

  bool stopped = false;
  for (; passes < static_cast<std::uint64_t>(options_.passes) && !stopped; ++passes) {
    if (budget.exhausted(evaluations, passes)) break;
    // Child c's centre: bit k of c says which half of dimension k it is in.
    for (std::uint64_t c = 0; c < children; ++c) {
      if (budget.exhausted(evaluations, passes)) {
        stopped = true;
        break;
      }
      for (std::size_t k = 0; k < d; ++k) {
        const double quarter = 0.25 * size_[k];
        const double x = centre_[k] + (((c >> k) & 1) ? quarter : -quarter);
        candidate_[k] = problem.domain(static_cast<csp::VariableId>(k)).clamp(x);
      }
      const csp::Score s = problem.score(candidate_);
      ++evaluations;
      if (s.better_than(best)) {
        best = s;
        result.best = candidate_;
      }
    }
    if (stopped) break;
    for (std::size_t k = 0; k < d; ++k) {
      size_[k] *= options_.scale;
      const double moved = centre_[k] + (result.best[k] - centre_[k]) * options_.slide;
      centre_[k] = problem.domain(static_cast<csp::VariableId>(k)).clamp(moved);
    }
  }
  if (passes < static_cast<std::uint64_t>(options_.passes)) result.stop = budget.reason();
  result.evaluations = evaluations;
  result.iterations = passes;
  result.solutions_at_best = 0;
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
