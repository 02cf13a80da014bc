// Brute force over every assignment of a small discrete problem: the reference the table
// and bnb tests compare against. Kept here, independent of any solver under test.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::testing {

struct BruteForceOptimum {
  bool feasible = false;                                  // some assignment breaks no hard one
  double cost = std::numeric_limits<double>::infinity();  // least soft cost of those
  std::uint64_t count = 0;  // assignments reaching it (|diff| <= 1e-9)
};

// Calls f(values) for every assignment of `problem` (every domain discrete).
template <class F>
void for_each_assignment(const csp::Problem& problem, F&& f) {
  const std::size_t n = problem.num_variables();
  std::vector<std::size_t> index(n, 0);
  std::vector<double> values(n);
  for (std::size_t v = 0; v < n; ++v) values[v] = problem.variable(v).domain.value_at(0);
  while (true) {
    f(values);
    std::size_t v = 0;
    for (; v < n; ++v) {
      const auto& d = problem.variable(v).domain;
      if (++index[v] < d.size()) {
        values[v] = d.value_at(index[v]);
        break;
      }
      index[v] = 0;
      values[v] = d.value_at(0);
    }
    if (v == n) return;
  }
}

inline BruteForceOptimum brute_force_optimum(const csp::Problem& problem) {
  BruteForceOptimum best;
  for_each_assignment(problem, [&](const std::vector<double>& values) {
    const csp::Score s = problem.score(values);
    if (!s.feasible()) return;
    if (!best.feasible || s.soft < best.cost - 1e-9) {
      best = {true, s.soft, 1};
    } else if (s.soft <= best.cost + 1e-9) {
      ++best.count;
    }
  });
  return best;
}

}  // namespace sightline::testing
