// Breakout weights (Morris 1993) for local search on hard constraints.
//
// Every hard constraint carries a weight w_c >= 1, all 1 at the start of a run. A move is
// judged by the weighted change of the hard constraints it touches,
//   sum_c w_c (violation after - violation before),
// instead of the plain change. When a variable is at a local minimum (no move lowers or keeps
// that weighted score), the weight of every violated hard constraint around it grows by one:
// a constraint that stays violated at local minima becomes expensive, and the search is
// pushed to satisfy it at the cost of others instead of cycling among the same few states.
// The true score still decides what is best; the weights only steer.
//
// Usage for a move touching variables v and j: collect(v, j) before the move, make the move
// on the evaluator, read weighted_hard_change(), undo or keep it.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sightline/csp/incremental_evaluator.h"

namespace sightline::solvers::detail {

class BreakoutWeights {
 public:
  // All weights back to 1.
  void reset(std::size_t num_constraints) {
    weights_.assign(num_constraints, 1.0);
    stamps_.assign(num_constraints, 0);
    stamp_ = 0;
  }

  // Notes the hard constraints around v and j, each once, with their violations now.
  void collect(const csp::IncrementalEvaluator& evaluator, csp::VariableId v, csp::VariableId j) {
    const csp::Problem& problem = evaluator.problem();
    ++stamp_;
    touched_.clear();
    for (csp::VariableId x : {v, j}) {
      for (const auto& incidence : problem.incidences(x)) {
        const csp::ConstraintId c = incidence.constraint;
        if (stamps_[c] == stamp_ || !problem.constraint(c).is_hard()) continue;
        stamps_[c] = stamp_;
        touched_.push_back({c, evaluator.violation(c)});
      }
    }
  }

  // The weighted change of the collected constraints since collect().
  double weighted_hard_change(const csp::IncrementalEvaluator& evaluator) const {
    double change = 0;
    for (const auto& [c, before] : touched_) {
      change += weights_[c] * (evaluator.violation(c) - before);
    }
    return change;
  }

  // `v` is at a local minimum: every violated hard constraint around it weighs one more.
  void bump(const csp::IncrementalEvaluator& evaluator, csp::VariableId v) {
    const csp::Problem& problem = evaluator.problem();
    for (const auto& incidence : problem.incidences(v)) {
      const csp::ConstraintId c = incidence.constraint;
      if (problem.constraint(c).is_hard() && evaluator.violation(c) > 0) weights_[c] += 1;
    }
  }

 private:
  std::vector<double> weights_;
  std::vector<std::uint32_t> stamps_;  // collect()'s marks
  std::uint32_t stamp_ = 0;
  std::vector<std::pair<csp::ConstraintId, double>> touched_;  // constraint, violation before
};

}  // namespace sightline::solvers::detail
