#include "sightline/solvers/detail/discrete_search.h"

#include <algorithm>
#include <string>
#include <utility>

#include "sightline/solvers/detail/group_placement.h"
#include "sightline/solvers/detail/sls_engines.h"
#include "sightline/solvers/detail/start.h"

namespace sightline::solvers::detail {

DiscreteSearch::DiscreteSearch(const csp::Problem& problem, const SlsSolver::Options& options,
                               std::uint64_t restart_cap, std::uint64_t seed, Budget& budget)
    : problem_(problem),
      options_(options),
      budget_(budget),
      random_(seed),
      n_(problem.num_variables()),
      restart_cap_(restart_cap) {
  if (options.permutation_moves) groups_ = find_permutation_groups(problem);
  group_of_.assign(n_, -1);
  dealt_.assign(groups_.size(), 0);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    // Every move on a group's variables is a swap inside the group, so its all_different
    // stays satisfied and the evaluator need not follow it.
    constant_.push_back(groups_[g].constraint);
    for (csp::VariableId v : groups_[g].variables) group_of_[v] = static_cast<int>(g);
    for (const auto& pin : groups_[g].pinned) group_of_[pin.first] = kPinned;
  }
  std::size_t incidences = 0;
  for (csp::VariableId v = 0; v < n_; ++v) incidences += problem.incidences(v).size();
  rescan_work_ = std::max<std::uint64_t>(64, 2 * incidences);
  stall_limit_ = options.stall_moves > 0 ? static_cast<std::uint64_t>(options.stall_moves)
                                         : 10 * static_cast<std::uint64_t>(n_) + 1000;
}

std::optional<FullEvaluation> DiscreteSearch::run(std::span<const double> start,
                                                  SolverResult& result, bool keep_breakdown) {
  keep_breakdown_ = keep_breakdown;
  csp::Assignment values;
  prepare_start(problem_, start, values);
  make_groups_permutations(values);
  begin_dealt_run(std::move(values));
  best_.reset(evaluator_->values(), evaluator_->score(), std::max<std::size_t>(1024, n_));
  const csp::Score first = evaluator_->score();
  budget_.note_best(evaluations_, 0, &first);
  if (!check_target() && options_.greedy_start) greedy_pass();
  main_loop();
  best_.materialise(evaluator_->values());
  result.best = best_.take_best();  // the search is over: no copy
  result.evaluations = evaluations_;
  result.iterations = iterations_;
  result.stop = stop_;
  result.message = message_;
  return std::move(target_);
}

void DiscreteSearch::make_groups_permutations(csp::Assignment& values) {
  for (std::size_t i = 0; i < groups_.size(); ++i) {
    const PermutationGroup& g = groups_[i];
    const bool pins_hold = std::all_of(g.pinned.begin(), g.pinned.end(),
                                       [&](const auto& p) { return values[p.first] == p.second; });
    if (!pins_hold || !is_permutation(g, values)) {
      deal_group(g, values);
      dealt_[i] = 1;
    }
  }
}

bool DiscreteSearch::is_permutation(const PermutationGroup& g, const csp::Assignment& values) {
  seen_.assign(g.values.size(), 0);
  for (csp::VariableId v : g.variables) {
    const auto it = std::lower_bound(g.values.begin(), g.values.end(), values[v]);
    if (it == g.values.end() || *it != values[v]) return false;
    char& mark = seen_[static_cast<std::size_t>(it - g.values.begin())];
    if (mark) return false;
    mark = 1;
  }
  return true;
}

void DiscreteSearch::deal_group(const PermutationGroup& g, csp::Assignment& values) {
  for (const auto& [v, value] : g.pinned) values[v] = value;
  const auto free = g.free_variables();
  const auto free_values = g.free_values();
  for (std::size_t i = 0; i < free.size(); ++i) values[free[i]] = free_values[i];
}

void DiscreteSearch::shuffle_group(const PermutationGroup& g, csp::Assignment& values) {
  const auto free = g.free_variables();
  for (std::size_t i = free.size(); i > 1; --i) {  // Fisher-Yates
    std::swap(values[free[i - 1]], values[free[random_.index(i)]]);
  }
}

void DiscreteSearch::begin_dealt_run(csp::Assignment values) {
  begin_run(std::move(values));
  const bool placement_on = options_.greedy_start && options_.placement_attempts > 0;
  bool shuffled = false;
  csp::Assignment copy;
  for (std::size_t i = 0; i < groups_.size(); ++i) {
    if (!dealt_[i] || (placement_on && can_place_group(*evaluator_, groups_[i]))) continue;
    if (!shuffled) copy = evaluator_->values();
    shuffle_group(groups_[i], copy);
    dealt_[i] = 0;  // dealt at random now: nothing left for placement to do
    shuffled = true;
  }
  if (shuffled) begin_run(std::move(copy));
}

void DiscreteSearch::randomise(csp::Assignment& values) {
  for (csp::VariableId v = 0; v < n_; ++v) {
    if (group_of_[v] != kNoGroup) continue;
    const csp::Domain& d = problem_.domain(v);
    values[v] = d.value_at(random_.index(d.size()));
  }
  for (const PermutationGroup& g : groups_) deal_group(g, values);
  std::fill(dealt_.begin(), dealt_.end(), 1);
}

void DiscreteSearch::begin_run(csp::Assignment values) {
  // The old evaluator goes first: at a million variables each holds tens of MB of counts,
  // and two alive at once would double the search's peak memory.
  evaluator_.reset();
  evaluator_ = std::make_unique<csp::IncrementalEvaluator>(problem_, std::move(values), constant_);
  ++evaluations_;
  run_best_ = evaluator_->score();
  stall_ = 0;
  tabu_.reset(n_);
  list_.clear();
  listed_.reset(n_);
  breakout_.reset(problem_.num_constraints());
}

void DiscreteSearch::restart_or_finish() {
  if (restart_cap_ != 0 && restarts_used_ >= restart_cap_) {
    stopped_ = true;
    stop_ = StopReason::kCompleted;
    message_ = "no zero-cost assignment after " + std::to_string(restarts_used_) + " restarts";
    return;
  }
  if (out_of_budget()) return;  // a restart costs one evaluation
  ++restarts_used_;
  best_.materialise(evaluator_->values());
  csp::Assignment values = evaluator_->values();
  randomise(values);
  begin_dealt_run(std::move(values));
  if (evaluator_->score().better_than(best_.score())) new_best(evaluator_->score());
  if (!check_target() && options_.greedy_start) greedy_pass();
}

bool DiscreteSearch::out_of_budget() {
  if (stopped_) return true;
  if (!budget_.exhausted(evaluations_, iterations_)) return false;
  stopped_ = true;
  stop_ = budget_.reason();
  return true;
}

bool DiscreteSearch::check_target() {
  if (!options_.stop_at_zero) return false;
  const csp::Score s = evaluator_->score();
  if (s.hard > kNearZero || s.soft > kNearZero) return false;
  FullEvaluation exact = evaluate_fully(problem_, evaluator_->values(), keep_breakdown_);
  if (!is_zero(exact.score)) {
    evaluator_->resynchronise();  // the incremental sums had drifted: start them afresh
    return false;
  }
  // The current assignment becomes the best even when an earlier one scored as well: the
  // search ends on it, and target_ its evaluation from scratch just now, which the result
  // takes as its score and breakdown (finish_result) instead of evaluating it again.
  new_best(exact.score);
  target_ = std::move(exact);
  stopped_ = true;
  stop_ = StopReason::kTargetReached;
  return true;
}

void DiscreteSearch::new_best(const csp::Score& score) {
  best_.improved(score);
  // Improvements come in bursts (every few moves while a run descends): a clock reading
  // 256 evaluations old is close enough, and spares the clock on 10^5 improvements a second.
  budget_.note_best(evaluations_, 256, &score);
}

void DiscreteSearch::after_move() {
  const csp::Score s = evaluator_->score();
  if (s.better_than(best_.score())) new_best(s);
  if (s.better_than(run_best_)) {
    run_best_ = s;
    stall_ = 0;
  } else {
    ++stall_;
  }
  check_target();
}

void DiscreteSearch::push(csp::VariableId v) {
  if (listed_[v]) return;
  listed_[v] = 1;
  list_.push_back(v);
}

void DiscreteSearch::rescan() {
  for (csp::VariableId v = 0; v < n_; ++v) {
    if (group_of_[v] != kPinned && evaluator_->involvement(v) > 0) push(v);
  }
  last_rescan_ = evaluations_;
}

void DiscreteSearch::greedy_pass() {
  for (csp::VariableId v = 0; v < n_ && !out_of_budget(); ++v) {
    if (group_of_[v] != kNoGroup || evaluator_->involvement(v) <= 0) continue;
    ++iterations_;
    if (value_step(v, true)) after_move();
  }
  for (std::size_t i = 0; i < groups_.size(); ++i) {
    const PermutationGroup& g = groups_[i];
    if (dealt_[i]) {
      dealt_[i] = 0;
      if (out_of_budget()) return;
      best_.materialise(evaluator_->values());  // placement's changes are not logged
      const PlacementReport placement =
          place_group(*evaluator_, g, options_.placement_attempts, random_, pool_);
      evaluations_ += placement.draws;
      const auto free = g.free_variables();
      iterations_ += free.size();
      // Placed variables added no cost, so every conflict left involves a left-over one:
      // they start the conflict list without a scan (the usual scans follow if it empties).
      for (std::size_t k = placement.placed; k < free.size(); ++k) {
        if (evaluator_->involvement(free[k]) > 0) push(free[k]);
      }
      if (evaluator_->score().better_than(best_.score())) new_best(evaluator_->score());
      check_target();
      continue;
    }
    const auto free = g.free_variables();
    for (std::size_t k = 0; k + 1 < free.size() && !out_of_budget(); ++k) {
      const csp::VariableId v = free[k];
      if (evaluator_->involvement(v) <= 0) continue;
      ++iterations_;
      if (greedy_swap(v, k + 1)) after_move();
    }
  }
}

void DiscreteSearch::main_loop() {
  while (!out_of_budget()) {
    if (list_.empty() || evaluations_ - last_rescan_ >= rescan_work_) {
      rescan();
      if (list_.empty()) {  // nothing in conflict: the target, or a dead end
        if (!check_target()) restart_or_finish();
        continue;
      }
    }
    const std::size_t k = random_.index(list_.size());
    const csp::VariableId v = list_[k];
    if (evaluator_->involvement(v) <= 0) {  // no longer in conflict: drop it
      listed_[v] = 0;
      list_[k] = list_.back();
      list_.pop_back();
      continue;
    }
    ++iterations_;
    csp::VariableId partner = v;
    const bool moved = group_of_[v] >= 0 ? swap_step(v, partner) : value_step(v, false);
    if (moved) {
      if (partner != v && evaluator_->involvement(partner) > 0) push(partner);
      after_move();
    } else {
      ++stall_;
    }
    if (!stopped_ && stall_ >= stall_limit_) restart_or_finish();
  }
}

std::optional<FullEvaluation> run_discrete_sls(const csp::Problem& problem,
                                               std::span<const double> start,
                                               const SlsSolver::Options& options,
                                               std::uint64_t restart_cap, std::uint64_t seed,
                                               Budget& budget, SolverResult& result,
                                               bool keep_breakdown) {
  DiscreteSearch search(problem, options, restart_cap, seed, budget);
  return search.run(start, result, keep_breakdown);
}

}  // namespace sightline::solvers::detail
