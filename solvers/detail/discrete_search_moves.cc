// DiscreteSearch's moves: min-conflicts value steps, and swaps inside permutation groups
// (screened by the cheap half of the swap, or all tried with breakout weights on small
// groups). See discrete_search.h.
#include <algorithm>

#include "sightline/solvers/detail/discrete_search.h"

namespace sightline::solvers::detail {

bool DiscreteSearch::is_tabu(csp::VariableId v, double value) const {
  const Tabu& t = tabu_[v];
  return t.until > iterations_ && t.value == value;
}

void DiscreteSearch::note_change(csp::VariableId v, double old_value) {
  best_.log_change(v, old_value);
  tabu_[v] = {iterations_ + static_cast<std::uint64_t>(options_.tabu_tenure), old_value};
}

void DiscreteSearch::apply(csp::VariableId v, double value) {
  note_change(v, evaluator_->values()[v]);
  check_log();
  evaluator_->assign(v, value);
}

void DiscreteSearch::swap(csp::VariableId v, csp::VariableId j) {
  const double vi = evaluator_->values()[v], vj = evaluator_->values()[j];
  note_change(v, vi);
  note_change(j, vj);
  check_log();
  evaluator_->assign(v, vj);
  evaluator_->assign(j, vi);
}

bool DiscreteSearch::value_step(csp::VariableId v, bool greedy) {
  const csp::Domain& d = problem_.domain(v);
  const std::size_t size = d.size();
  if (size < 2) return false;
  const double current = evaluator_->values()[v];
  const auto samples =
      static_cast<std::size_t>(greedy ? options_.greedy_samples : options_.value_samples);
  const bool every_value = size <= samples;
  const std::size_t count = every_value ? size : samples;
  bool found = false;
  csp::Score best_delta;
  double best_value = current;
  std::size_t ties = 0;
  for (std::size_t t = 0; t < count; ++t) {
    const double value = d.value_at(every_value ? t : random_.index(size));
    if (value == current) continue;
    if (out_of_budget()) break;
    const csp::Score delta = evaluator_->delta(v, value);
    ++evaluations_;
    if (!improves(delta) && is_tabu(v, value)) continue;
    if (!found || delta.better_than(best_delta)) {
      found = true;
      best_delta = delta;
      best_value = value;
      ties = 1;
    } else if (!best_delta.better_than(delta) && random_.index(++ties) == 0) {
      best_value = value;  // reservoir sampling: each tied value equally likely
    }
  }
  if (found && (improves(best_delta) || (!greedy && !worsens(best_delta)))) {
    apply(v, best_value);
    return true;
  }
  // A local minimum for v: sometimes a random value instead (random walk).
  if (greedy || !random_.chance(options_.walk_probability) || out_of_budget()) return false;
  double value = d.value_at(random_.index(size - 1));
  if (value == current) value = d.value_at(size - 1);  // the one index not drawn
  ++evaluations_;
  apply(v, value);
  return true;
}

bool DiscreteSearch::greedy_swap(csp::VariableId v, std::size_t first) {
  const PermutationGroup& g = groups_[static_cast<std::size_t>(group_of_[v])];
  const std::size_t size = g.free_variables().size();
  if (first >= size) return false;
  const double vi = evaluator_->values()[v];
  std::size_t window = size - first;
  if (options_.greedy_window > 0) {
    window = std::min(window, static_cast<std::size_t>(options_.greedy_window));
  }
  bool screened = false;
  csp::Score best_half;
  for (std::int64_t t = 0; t < options_.greedy_samples; ++t) {
    const csp::VariableId j = g.free_variables()[first + random_.index(window)];
    if (out_of_budget()) return false;
    const double vj = evaluator_->values()[j];
    // Screen first with the cheap half of the swap (v's side only), and try for real only
    // a partner whose value is strictly better for v than every one tried before: v's
    // half is lowest exactly where v would be free of conflicts.
    const csp::Score half = evaluator_->delta(v, vj);
    ++evaluations_;
    if (screened && !half.better_than(best_half)) continue;
    best_half = half;
    screened = true;
    if (out_of_budget()) return false;
    evaluator_->assign(v, vj);
    evaluator_->assign(j, vi);
    ++evaluations_;
    if (evaluator_->involvement(v) <= 0) {
      note_change(v, vi);
      note_change(j, vj);
      check_log();
      return true;
    }
    evaluator_->assign(j, vj);  // rejected: revert
    evaluator_->assign(v, vi);
  }
  return false;
}

bool DiscreteSearch::swap_step(csp::VariableId v, csp::VariableId& partner) {
  const PermutationGroup& g = groups_[static_cast<std::size_t>(group_of_[v])];
  const std::size_t size = g.free_variables().size();
  if (size < 2) return false;
  if (size - 1 <= static_cast<std::size_t>(options_.swap_samples)) {
    return small_swap_step(v, g, partner);
  }
  const double vi = evaluator_->values()[v];
  std::size_t finalists = 0;
  csp::Score best_half;
  for (std::int64_t t = 0; t < options_.swap_samples; ++t) {
    const csp::VariableId candidate = g.free_variables()[random_.index(size)];
    if (candidate == v) continue;
    if (out_of_budget()) return false;
    const csp::Score half = evaluator_->delta(v, evaluator_->values()[candidate]);
    ++evaluations_;
    if (finalists == 0 || half.better_than(best_half)) {
      best_half = half;
      finalists_[0] = candidate;
      finalists = 1;
    } else if (!best_half.better_than(half) && finalists < kFinalists) {
      finalists_[finalists++] = candidate;
    }
  }
  csp::VariableId sideways = v;
  for (std::size_t f = 0; f < finalists; ++f) {
    std::swap(finalists_[f], finalists_[f + random_.index(finalists - f)]);
    const csp::VariableId j = finalists_[f];
    if (out_of_budget()) return false;
    const double vj = evaluator_->values()[j];
    const csp::Score before = evaluator_->score();
    evaluator_->assign(v, vj);
    evaluator_->assign(j, vi);
    ++evaluations_;
    const csp::Score delta = evaluator_->score() - before;
    evaluator_->assign(j, vj);  // undone here; redone below if chosen
    evaluator_->assign(v, vi);
    if (improves(delta)) {
      partner = j;
      swap(v, j);
      return true;
    }
    if (sideways == v && !worsens(delta) && !is_tabu(v, vj) && !is_tabu(j, vi)) sideways = j;
  }
  if (sideways != v) {
    partner = sideways;
    swap(v, sideways);
    return true;
  }
  // A local minimum for v: sometimes a random swap instead (random walk).
  if (!random_.chance(options_.walk_probability) || out_of_budget()) return false;
  partner = g.free_variables()[random_.index(size)];
  if (partner == v) return false;
  ++evaluations_;
  swap(v, partner);
  return true;
}

bool DiscreteSearch::small_swap_step(csp::VariableId v, const PermutationGroup& g,
                                     csp::VariableId& partner) {
  const double vi = evaluator_->values()[v];
  csp::VariableId chosen = v;
  csp::Score best;
  std::size_t ties = 0;
  for (csp::VariableId j : g.free_variables()) {
    if (j == v) continue;
    if (out_of_budget()) return false;
    const double vj = evaluator_->values()[j];
    breakout_.collect(*evaluator_, v, j);
    const csp::Score before = evaluator_->score();
    evaluator_->assign(v, vj);
    evaluator_->assign(j, vi);
    ++evaluations_;
    const csp::Score delta = evaluator_->score() - before;
    const csp::Score weighted{breakout_.weighted_hard_change(*evaluator_), delta.soft};
    evaluator_->assign(j, vj);
    evaluator_->assign(v, vi);
    if (!improves(delta) && (is_tabu(v, vj) || is_tabu(j, vi))) continue;
    if (chosen == v || weighted.better_than(best)) {
      chosen = j;
      best = weighted;
      ties = 1;
    } else if (!best.better_than(weighted) && random_.index(++ties) == 0) {
      chosen = j;
    }
  }
  if (chosen != v && !worsens(best)) {
    partner = chosen;
    swap(v, chosen);
    return true;
  }
  breakout_.bump(*evaluator_, v);
  if (!random_.chance(options_.walk_probability) || out_of_budget()) return false;
  partner = g.free_variables()[random_.index(g.free_variables().size())];
  if (partner == v) return false;
  ++evaluations_;
  swap(v, partner);
  return true;
}

}  // namespace sightline::solvers::detail
