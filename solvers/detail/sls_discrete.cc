// Min-conflicts local search with permutation swaps: the discrete half of SlsSolver.
#include <algorithm>
#include <array>
#include <memory>
#include <string>

#include "csp/incremental_evaluator.h"
#include "solvers/detail/best_keeper.h"
#include "solvers/detail/permutation_groups.h"
#include "solvers/detail/random.h"
#include "solvers/detail/sls_engines.h"
#include "solvers/detail/start.h"

namespace sightline::solvers::detail {

namespace {

// Incremental scores below this are checked from scratch as possible zero-cost assignments.
constexpr double kNearZero = 1e-9;

bool improves(const csp::Score& delta) { return delta.better_than(csp::Score{}); }
bool worsens(const csp::Score& delta) { return csp::Score{}.better_than(delta); }

class DiscreteSearch {
 public:
  DiscreteSearch(const csp::Problem& problem, const SlsSolver::Options& options, std::uint64_t seed,
                 Budget& budget)
      : problem_(problem),
        options_(options),
        budget_(budget),
        random_(seed),
        n_(problem.num_variables()) {
    if (options.permutation_moves) groups_ = find_permutation_groups(problem);
    group_of_.assign(n_, -1);
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      for (csp::VariableId v : groups_[g].variables) group_of_[v] = static_cast<int>(g);
      for (const auto& pin : groups_[g].pinned) group_of_[pin.first] = kPinned;
    }
    std::size_t incidences = 0;
    for (csp::VariableId v = 0; v < n_; ++v) incidences += problem.incidences(v).size();
    rescan_work_ = std::max<std::uint64_t>(64, 2 * incidences);
    stall_limit_ = options.stall_moves > 0 ? static_cast<std::uint64_t>(options.stall_moves)
                                           : 10 * static_cast<std::uint64_t>(n_) + 1000;
  }

  void run(std::span<const double> start, SolverResult& result) {
    csp::Assignment values;
    prepare_start(problem_, start, values);
    make_groups_permutations(values);
    begin_run(std::move(values));
    best_.reset(evaluator_->values(), evaluator_->score(), std::max<std::size_t>(1024, n_));
    if (!check_target() && options_.greedy_start) greedy_pass();
    main_loop();
    best_.materialise(evaluator_->values());
    result.best = best_.best();
    result.evaluations = evaluations_;
    result.iterations = iterations_;
    result.stop = stop_;
    result.message = message_;
  }

 private:
  // --- runs and restarts ---------------------------------------------------------------

  // Group variables whose values are not a permutation of the group's values, or whose pinned
  // variables are not at their values, get a random permutation that respects the pins.
  void make_groups_permutations(csp::Assignment& values) {
    std::vector<double> seen;
    for (const PermutationGroup& g : groups_) {
      seen.clear();
      for (csp::VariableId v : g.variables) seen.push_back(values[v]);
      std::sort(seen.begin(), seen.end());
      const bool pins_hold = std::all_of(g.pinned.begin(), g.pinned.end(),
                                         [&](const auto& p) { return values[p.first] == p.second; });
      if (seen != g.values || !pins_hold) shuffle_group(g, values);
    }
  }

  void shuffle_group(const PermutationGroup& g, csp::Assignment& values) {
    for (const auto& [v, value] : g.pinned) values[v] = value;
    const std::size_t k = g.free.size();
    if (k == 0) return;
    for (std::size_t i = 0; i < k; ++i) values[g.free[i]] = g.free_values[i];
    for (std::size_t i = k - 1; i > 0; --i) {  // Fisher-Yates
      std::swap(values[g.free[i]], values[g.free[random_.index(i + 1)]]);
    }
  }

  void randomise(csp::Assignment& values) {
    for (csp::VariableId v = 0; v < n_; ++v) {
      if (group_of_[v] != kNoGroup) continue;
      const csp::Domain& d = problem_.variable(v).domain;
      values[v] = d.value_at(random_.index(d.size()));
    }
    for (const PermutationGroup& g : groups_) shuffle_group(g, values);
  }

  void begin_run(csp::Assignment values) {
    evaluator_ = std::make_unique<csp::IncrementalEvaluator>(problem_, std::move(values));
    ++evaluations_;
    run_best_ = evaluator_->score();
    stall_ = 0;
    tabu_until_.assign(n_, 0);
    tabu_value_.assign(n_, 0.0);
    list_.clear();
    listed_.assign(n_, 0);
    weights_.assign(problem_.num_constraints(), 1.0);
    stamps_.assign(problem_.num_constraints(), 0);
    stamp_ = 0;
  }

  // Restarts from a random assignment, or ends the search when the restarts are used up.
  void restart_or_finish() {
    if (restarts_used_ >= static_cast<std::uint64_t>(options_.restarts)) {
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
    begin_run(std::move(values));
    if (evaluator_->score().better_than(best_.score())) best_.improved(evaluator_->score());
    if (!check_target() && options_.greedy_start) greedy_pass();
  }

  bool out_of_budget() {
    if (stopped_) return true;
    if (!budget_.exhausted(evaluations_, iterations_)) return false;
    stopped_ = true;
    stop_ = budget_.reason();
    return true;
  }

  // Stops the search at a zero-cost feasible assignment (checked from scratch).
  bool check_target() {
    if (!options_.stop_at_zero) return false;
    const csp::Score s = evaluator_->score();
    if (s.hard > kNearZero || s.soft > kNearZero) return false;
    const csp::Score exact = problem_.score(evaluator_->values());
    if (!is_zero(exact)) {
      evaluator_->resynchronise();  // the incremental sums had drifted: start them afresh
      return false;
    }
    if (exact.better_than(best_.score())) best_.improved(exact);
    stopped_ = true;
    stop_ = StopReason::kTargetReached;
    return true;
  }

  // After an accepted move: keep the best, measure progress, look for the target.
  void after_move() {
    const csp::Score s = evaluator_->score();
    if (s.better_than(best_.score())) best_.improved(s);
    if (s.better_than(run_best_)) {
      run_best_ = s;
      stall_ = 0;
    } else {
      ++stall_;
    }
    check_target();
  }

  // --- moves ---------------------------------------------------------------------------

  bool is_tabu(csp::VariableId v, double value) const {
    return tabu_until_[v] > iterations_ && tabu_value_[v] == value;
  }

  // `v` leaves `old_value`: remember it for the best keeper and for tabu. Call check_log()
  // once the whole move is noted.
  void note_change(csp::VariableId v, double old_value) {
    best_.log_change(v, old_value);
    tabu_value_[v] = old_value;
    tabu_until_[v] = iterations_ + static_cast<std::uint64_t>(options_.tabu_tenure);
  }
  void check_log() { best_.check_log(evaluator_->values()); }

  void apply(csp::VariableId v, double value) {
    note_change(v, evaluator_->values()[v]);
    check_log();
    evaluator_->assign(v, value);
  }

  void swap(csp::VariableId v, csp::VariableId j) {
    const double vi = evaluator_->values()[v], vj = evaluator_->values()[j];
    note_change(v, vi);
    note_change(j, vj);
    check_log();
    evaluator_->assign(v, vj);
    evaluator_->assign(j, vi);
  }

  // Min-conflicts on one variable: the best candidate value, if it does not worsen the score.
  bool value_step(csp::VariableId v, bool greedy) {
    const csp::Domain& d = problem_.variable(v).domain;
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

  // The greedy pass's swap: the first of up to `greedy_samples` partners, drawn from the
  // `greedy_window` group positions after `first` (nearby variables: their data is in cache),
  // after which v is in no conflict at all. The partner takes v's
  // value and whatever conflicts come with it: its own turn, later in the pass, deals with
  // them. This is Sosic & Gu's placement stated generically (v is "placed" when it is
  // conflict-free), except that their partial check ignores the queens not yet placed,
  // which a generic evaluator cannot do: here every variable counts, so a random partner
  // frees v less often (about e^-2 of the time on N-queens instead of 0.43 on average).
  bool greedy_swap(csp::VariableId v, std::size_t first) {
    const PermutationGroup& g = groups_[static_cast<std::size_t>(group_of_[v])];
    const std::size_t size = g.free.size();
    if (first >= size) return false;
    const double vi = evaluator_->values()[v];
    std::size_t window = size - first;
    if (options_.greedy_window > 0) {
      window = std::min(window, static_cast<std::size_t>(options_.greedy_window));
    }
    bool screened = false;
    csp::Score best_half;
    for (std::int64_t t = 0; t < options_.greedy_samples; ++t) {
      const csp::VariableId j = g.free[first + random_.index(window)];
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

  // A swap of v with a partner of its permutation group. `swap_samples` random partners are
  // screened by the cheap half of the swap, delta(v -> partner's value), which reads only
  // v's side; the partners with the best half (up to kFinalists) are then tried for real,
  // both assigns, in random order: the first that improves the score is kept, else the
  // first sideways one that does not undo a recent move (tabu); the others are reverted.
  // Sets `partner` when it moves.
  bool swap_step(csp::VariableId v, csp::VariableId& partner) {
    const PermutationGroup& g = groups_[static_cast<std::size_t>(group_of_[v])];
    const std::size_t size = g.free.size();
    if (size < 2) return false;
    if (size - 1 <= static_cast<std::size_t>(options_.swap_samples)) {
      return small_swap_step(v, g, partner);
    }
    const double vi = evaluator_->values()[v];
    std::size_t finalists = 0;
    csp::Score best_half;
    for (std::int64_t t = 0; t < options_.swap_samples; ++t) {
      const csp::VariableId candidate = g.free[random_.index(size)];
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
    partner = g.free[random_.index(size)];
    if (partner == v) return false;
    ++evaluations_;
    swap(v, partner);
    return true;
  }

  // swap_step for a group with at most swap_samples other free variables: every partner is
  // tried for real and the best is taken, judged with breakout weights (Morris 1993): the
  // hard part of a move's delta is sum_c w_c (violation after - violation before) over the
  // hard constraints it touches, w_c >= 1, the soft part is the plain soft delta. When no
  // partner lowers or keeps that weighted score (a local minimum for v), the weight of every
  // violated hard constraint around v grows by one: a constraint that stays violated at
  // local minima becomes expensive, and the search is pushed to satisfy it at the cost of
  // others instead of cycling. Tabu as in swap_step, except for moves that improve the true
  // score. The best keeper and restarts still follow the true score.
  bool small_swap_step(csp::VariableId v, const PermutationGroup& g, csp::VariableId& partner) {
    const double vi = evaluator_->values()[v];
    csp::VariableId chosen = v;
    csp::Score best;
    std::size_t ties = 0;
    for (csp::VariableId j : g.free) {
      if (j == v) continue;
      if (out_of_budget()) return false;
      const double vj = evaluator_->values()[j];
      collect_touched(v, j);
      const csp::Score before = evaluator_->score();
      evaluator_->assign(v, vj);
      evaluator_->assign(j, vi);
      ++evaluations_;
      const csp::Score delta = evaluator_->score() - before;
      const csp::Score weighted{weighted_hard_change(), delta.soft};
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
    for (const auto& incidence : problem_.incidences(v)) {
      const csp::ConstraintId c = incidence.constraint;
      if (problem_.constraint(c).is_hard() && evaluator_->violation(c) > 0) weights_[c] += 1;
    }
    if (!random_.chance(options_.walk_probability) || out_of_budget()) return false;
    partner = g.free[random_.index(g.free.size())];
    if (partner == v) return false;
    ++evaluations_;
    swap(v, partner);
    return true;
  }

  // The hard constraints around v and j, each once, with their violations now.
  void collect_touched(csp::VariableId v, csp::VariableId j) {
    ++stamp_;
    touched_.clear();
    for (csp::VariableId x : {v, j}) {
      for (const auto& incidence : problem_.incidences(x)) {
        const csp::ConstraintId c = incidence.constraint;
        if (stamps_[c] == stamp_ || !problem_.constraint(c).is_hard()) continue;
        stamps_[c] = stamp_;
        touched_.push_back({c, evaluator_->violation(c)});
      }
    }
  }
  double weighted_hard_change() const {
    double change = 0;
    for (const auto& [c, before] : touched_) change += weights_[c] * (evaluator_->violation(c) - before);
    return change;
  }

  // --- the conflict list -----------------------------------------------------------------

  void push(csp::VariableId v) {
    if (listed_[v]) return;
    listed_[v] = 1;
    list_.push_back(v);
  }

  // Adds every variable in conflict to the list. The list cannot follow conflicts a move
  // creates for third parties (the queen already on the row a queen moves to): nothing
  // generic names them. So besides refilling an empty list, rescan() also runs after every
  // `rescan_work_` evaluations, which is about twice the work of the scan itself, so it
  // costs at most a third of the search whatever the size of the problem.
  void rescan() {
    for (csp::VariableId v = 0; v < n_; ++v) {
      if (group_of_[v] != kPinned && evaluator_->involvement(v) > 0) push(v);
    }
    last_rescan_ = evaluations_;
  }

  // --- the two phases --------------------------------------------------------------------

  // One pass in variable order; each variable in conflict takes an improving move if one of
  // its sampled values (or swaps with later variables of its group) offers it.
  void greedy_pass() {
    for (csp::VariableId v = 0; v < n_ && !out_of_budget(); ++v) {
      if (group_of_[v] != kNoGroup || evaluator_->involvement(v) <= 0) continue;
      ++iterations_;
      if (value_step(v, true)) after_move();
    }
    for (const PermutationGroup& g : groups_) {
      for (std::size_t k = 0; k + 1 < g.free.size() && !out_of_budget(); ++k) {
        const csp::VariableId v = g.free[k];
        if (evaluator_->involvement(v) <= 0) continue;
        ++iterations_;
        if (greedy_swap(v, k + 1)) after_move();
      }
    }
  }

  void main_loop() {
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

  const csp::Problem& problem_;
  const SlsSolver::Options& options_;
  Budget& budget_;
  Random random_;
  const std::size_t n_;

  std::vector<PermutationGroup> groups_;
  static constexpr int kNoGroup = -1, kPinned = -2;
  std::vector<int> group_of_;  // group index per variable, kNoGroup, or kPinned (never moves)

  std::unique_ptr<csp::IncrementalEvaluator> evaluator_;
  BestKeeper best_;
  csp::Score run_best_;
  std::vector<std::uint64_t> tabu_until_;  // step until which tabu_value_ is forbidden
  std::vector<double> tabu_value_;         // the value the variable last left
  static constexpr std::size_t kFinalists = 4;
  std::array<csp::VariableId, kFinalists> finalists_{};  // swap_step's best-screened partners
  std::vector<csp::VariableId> list_;                    // variables believed to be in conflict
  std::vector<double> weights_;                          // breakout weights (small groups)
  std::vector<std::uint32_t> stamps_;                    // collect_touched's marks
  std::uint32_t stamp_ = 0;
  std::vector<std::pair<csp::ConstraintId, double>> touched_;  // constraint, violation before
  std::vector<char> listed_;
  std::uint64_t last_rescan_ = 0, rescan_work_ = 0;  // in evaluations

  std::uint64_t evaluations_ = 0, iterations_ = 0;
  std::uint64_t stall_ = 0, stall_limit_ = 0, restarts_used_ = 0;
  bool stopped_ = false;
  StopReason stop_ = StopReason::kCompleted;
  std::string message_;
};

}  // namespace

void run_discrete_sls(const csp::Problem& problem, std::span<const double> start,
                      const SlsSolver::Options& options, std::uint64_t seed, Budget& budget,
                      SolverResult& result) {
  DiscreteSearch search(problem, options, seed, budget);
  search.run(start, result);
}

}  // namespace sightline::solvers::detail
