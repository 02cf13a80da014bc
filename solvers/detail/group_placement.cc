#include "sightline/solvers/detail/group_placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace sightline::solvers::detail {

bool can_place_group(const csp::IncrementalEvaluator& evaluator, const PermutationGroup& group) {
  for (csp::VariableId v : group.free_variables()) {
    if (!evaluator.can_retract(v)) return false;
  }
  return true;
}

PlacementReport place_group(csp::IncrementalEvaluator& evaluator, const PermutationGroup& group,
                            double attempts_per_variable, Random& random,
                            std::vector<double>& pool) {
  PlacementReport report;
  const auto free = group.free_variables();
  const std::size_t k = free.size();
  if (k == 0) return report;
  pool.resize(k);
  for (std::size_t i = 0; i < k; ++i) pool[i] = evaluator.values()[free[i]];
  evaluator.retract(free);
  // pool[0, placed) holds the values dealt out, in the placed variables' order; the rest
  // are the values still to deal.
  const auto attempts =
      static_cast<std::uint64_t>(std::ceil(attempts_per_variable * static_cast<double>(k)));
  std::size_t placed = 0;
  // Each draw reads the pool at a random place: on large groups a cache miss, which is most
  // of the cost. So the random bits are drawn kAhead draws before use, and the pool entry
  // they will pick is fetched then: it is placed' + scale(bits, k - placed') for the placed'
  // of that time, which lies within kAhead entries after the estimate made with today's
  // placed; both ends are fetched.
  constexpr std::size_t kAhead = 16;
  std::array<std::uint64_t, kAhead> ahead;
  const auto prefetch = [&](std::uint64_t bits) {
    const std::size_t estimate = placed + Random::scale(bits, k - placed);
    __builtin_prefetch(pool.data() + estimate);
    __builtin_prefetch(pool.data() + std::min(estimate + kAhead, k - 1));
  };
  for (auto& bits : ahead) {
    bits = random.bits();
    prefetch(bits);
  }
  while (placed < k && report.draws < attempts) {
    std::uint64_t& slot = ahead[report.draws % kAhead];
    const std::size_t m = placed + Random::scale(slot, k - placed);
    slot = random.bits();
    prefetch(slot);
    const csp::VariableId v = free[placed];
    ++report.draws;
    if (!evaluator.place_is_free(v, pool[m])) continue;
    std::swap(pool[placed], pool[m]);
    evaluator.place_free(v, pool[placed]);
    ++placed;
  }
  report.placed = placed;
  report.left_over = k - placed;
  for (std::size_t i = placed; i < k; ++i) evaluator.place(free[i], pool[i]);
  return report;
}

}  // namespace sightline::solvers::detail
