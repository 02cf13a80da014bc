#include "solvers/detail/group_placement.h"

#include <cmath>
#include <utility>

namespace sightline::solvers::detail {

bool can_place_group(const csp::IncrementalEvaluator& evaluator, const PermutationGroup& group) {
  for (csp::VariableId v : group.free) {
    if (!evaluator.can_retract(v)) return false;
  }
  return true;
}

PlacementReport place_group(csp::IncrementalEvaluator& evaluator, const PermutationGroup& group,
                            double attempts_per_variable, Random& random,
                            std::vector<double>& pool) {
  PlacementReport report;
  const std::size_t k = group.free.size();
  pool.resize(k);
  for (std::size_t i = 0; i < k; ++i) pool[i] = evaluator.values()[group.free[i]];
  evaluator.retract(group.free);
  // pool[0, placed) holds the values dealt out, in the placed variables' order; the rest
  // are the values still to deal.
  const auto attempts =
      static_cast<std::uint64_t>(std::ceil(attempts_per_variable * static_cast<double>(k)));
  std::size_t placed = 0;
  while (placed < k && report.draws < attempts) {
    const std::size_t m = placed + random.index(k - placed);
    const csp::VariableId v = group.free[placed];
    ++report.draws;
    if (!evaluator.place_is_free(v, pool[m])) continue;
    std::swap(pool[placed], pool[m]);
    evaluator.place(v, pool[placed]);
    ++placed;
  }
  report.placed = placed;
  report.left_over = k - placed;
  for (std::size_t i = placed; i < k; ++i) evaluator.place(group.free[i], pool[i]);
  return report;
}

}  // namespace sightline::solvers::detail
