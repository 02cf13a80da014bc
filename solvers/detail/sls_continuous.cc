// Random-neighbourhood search with a shrinking radius: the continuous half of SlsSolver.
#include <algorithm>
#include <cmath>
#include <string>

#include "sightline/solvers/detail/random.h"
#include "sightline/solvers/detail/sls_engines.h"
#include "sightline/solvers/detail/start.h"

namespace sightline::solvers::detail {

namespace {

// Moves value `x` of a domain by a Gaussian step of standard deviation radius x width; a
// discrete domain moves along its value indices (width = number of values - 1).
double perturb(const csp::Domain& d, double x, double radius, Random& random) {
  if (d.is_continuous()) return d.clamp(x + random.gaussian() * radius * (d.upper() - d.lower()));
  const std::size_t size = d.size();
  if (size < 2) return x;
  const double index = static_cast<double>(*d.index_of(x));
  const double moved =
      std::round(index + random.gaussian() * radius * static_cast<double>(size - 1));
  const double clamped = std::min(std::max(moved, 0.0), static_cast<double>(size - 1));
  return d.value_at(static_cast<std::size_t>(clamped));
}

double uniform_in(const csp::Domain& d, Random& random) {
  if (d.is_continuous()) return d.clamp(d.lower() + random.uniform() * (d.upper() - d.lower()));
  return d.value_at(random.index(d.size()));
}

}  // namespace

void run_continuous_sls(const csp::Problem& problem, std::span<const double> start,
                        const SlsSolver::Options& options, std::uint64_t restart_cap,
                        std::uint64_t seed, Budget& budget,
                        SolverResult& result, std::vector<double>& current,
                        std::vector<double>& candidate) {
  Random random(seed);
  const std::size_t n = problem.num_variables();
  prepare_start(problem, start, current);
  candidate.resize(n);
  csp::Score here = problem.score(current);
  result.best = current;
  csp::Score best = here;
  budget.note_best(1, 0, &best);
  std::uint64_t evaluations = 1, iterations = 0, restarts_used = 0, failures = 0;
  double radius = options.initial_radius;
  result.stop = StopReason::kCompleted;
  result.message.clear();

  while (true) {
    if (options.stop_at_zero && is_zero(here)) {
      result.stop = StopReason::kTargetReached;
      break;
    }
    if (budget.exhausted(evaluations, iterations)) {
      result.stop = budget.reason();
      break;
    }
    ++iterations;
    for (std::size_t k = 0; k < n; ++k) {
      const csp::Domain& d = problem.domain(static_cast<csp::VariableId>(k));
      candidate[k] = perturb(d, current[k], radius, random);
    }
    const csp::Score there = problem.score(candidate);
    ++evaluations;
    if (there.better_than(here)) {
      current.swap(candidate);
      here = there;
      failures = 0;
      if (here.better_than(best)) {
        best = here;
        result.best = current;
        budget.note_best(evaluations, 0, &best);
      }
      continue;
    }
    if (++failures < static_cast<std::uint64_t>(options.patience)) continue;
    failures = 0;
    radius *= options.shrink;
    if (radius >= options.min_radius) continue;
    // The neighbourhood has collapsed onto a local optimum: restart from a random point.
    if (restart_cap != 0 && restarts_used >= restart_cap) {
      result.message = "radius collapsed after " + std::to_string(restarts_used) + " restarts";
      break;
    }
    if (budget.exhausted(evaluations, iterations)) {
      result.stop = budget.reason();
      break;
    }
    ++restarts_used;
    for (std::size_t k = 0; k < n; ++k) {
      current[k] = uniform_in(problem.domain(static_cast<csp::VariableId>(k)), random);
    }
    here = problem.score(current);
    ++evaluations;
    radius = options.initial_radius;
    if (here.better_than(best)) {
      best = here;
      result.best = current;
      budget.note_best(evaluations, 0, &best);
    }
  }
  result.evaluations = evaluations;
  result.iterations = iterations;
}

}  // namespace sightline::solvers::detail
