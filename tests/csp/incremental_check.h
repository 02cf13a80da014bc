// Test helpers shared by the csp tests: random assignments and the check that an
// IncrementalEvaluator's deltas and running score agree with full re-evaluation.
//
// Every constraint kind with an IncrementalState must pass check_incremental_matches_full on
// problems built from it: that is the contract local search relies on.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sightline/csp/incremental_evaluator.h"
#include "sightline/csp/problem.h"

namespace sightline::csp::testing {

// A uniformly random member of the domain.
inline double random_value(const Domain& d, std::mt19937& rng) {
  if (d.is_continuous()) return std::uniform_real_distribution<double>(d.lower(), d.upper())(rng);
  return d.value_at(std::uniform_int_distribution<std::size_t>(0, d.size() - 1)(rng));
}

inline Assignment random_assignment(const Problem& p, std::mt19937& rng) {
  Assignment a(p.num_variables());
  for (VariableId v = 0; v < p.num_variables(); ++v) a[v] = random_value(p.variable(v).domain, rng);
  return a;
}

// `moves` random one-variable changes: each delta is compared with the difference of two full
// Problem::score calls; about two thirds are then assigned, after which the evaluator's
// running score must equal Problem::score of its assignment. Tolerances are relative.
inline void check_incremental_matches_full(const Problem& p, std::uint32_t seed, int moves) {
  std::mt19937 rng(seed);
  IncrementalEvaluator evaluator(p, random_assignment(p, rng));
  std::uniform_int_distribution<VariableId> pick(0, static_cast<VariableId>(p.num_variables() - 1));
  auto close = [](double a, double b) { return std::abs(a - b) <= 1e-9 * (1 + std::abs(b)); };
  for (int step = 0; step < moves; ++step) {
    const VariableId var = pick(rng);
    const double value = random_value(p.variable(var).domain, rng);
    Assignment after = evaluator.values();
    after[var] = value;
    const Score expected = p.score(after) - p.score(evaluator.values());
    const Score got = evaluator.delta(var, value);
    ASSERT_TRUE(close(got.hard, expected.hard) && close(got.soft, expected.soft))
        << "step " << step << ": delta (" << got.hard << ", " << got.soft << ") but full "
        << "re-evaluation says (" << expected.hard << ", " << expected.soft << ")";
    if (step % 3 != 2) {
      evaluator.assign(var, value);
      const Score full = p.score(evaluator.values());
      ASSERT_TRUE(close(evaluator.score().hard, full.hard) &&
                  close(evaluator.score().soft, full.soft))
          << "step " << step << ": running score (" << evaluator.score().hard << ", "
          << evaluator.score().soft << ") but Problem::score (" << full.hard << ", " << full.soft
          << ")";
    }
  }
}

}  // namespace sightline::csp::testing
