#include "sightline/solvers/detail/tabu_search.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "sightline/solvers/detail/compound_moves.h"
#include "sightline/solvers/detail/move_table.h"
#include "sightline/solvers/detail/random.h"
#include "sightline/solvers/detail/start.h"

namespace sightline::solvers::detail {

namespace {

// Without any limit, the search ends after this many perturbations in a row that bring no
// new best (a bare call must end; with a limit the search uses all of it instead).
constexpr std::uint64_t kUnlimitedFruitlessPerturbations = 10;

class TabuSearch {
 public:
  TabuSearch(const csp::Problem& problem, const TabuSolver::Options& options, std::uint64_t seed,
             bool unlimited, Budget& budget)
      : problem_(problem),
        options_(options),
        unlimited_(unlimited),
        budget_(budget),
        random_(seed),
        table_(problem),
        n_(problem.num_variables()) {
    // Tenure bounds (tabu.h): automatic ones follow the mean domain size.
    double mean_domain = 0;
    for (csp::VariableId v = 0; v < n_; ++v) {
      mean_domain += static_cast<double>(problem.domain(v).size());
    }
    mean_domain /= static_cast<double>(std::max<std::size_t>(1, n_));
    const auto auto_min = std::max<std::int64_t>(2, std::llround(mean_domain / 6));
    const auto auto_max = std::max<std::int64_t>(10, std::llround(0.7 * mean_domain));
    tenure_min_ = options.tenure_min >= 0
                      ? options.tenure_min
                      : (options.tenure_max >= 0 ? std::min(auto_min, options.tenure_max) : auto_min);
    tenure_max_ = options.tenure_max >= 0 ? options.tenure_max : std::max(auto_max, tenure_min_);
    if (options.compound_moves) {
      compound_.emplace(problem);
      if (compound_->num_pairs() == 0) compound_.reset();
    }
  }

  void run(std::span<const double> start, SolverResult& result) {
    prepare_start(problem_, start, best_);
    const std::uint64_t stall_limit =
        options_.stall_moves > 0
            ? static_cast<std::uint64_t>(options_.stall_moves)
            : std::max<std::uint64_t>(2000, 100 * static_cast<std::uint64_t>(n_));
    const std::size_t base_strength = std::max<std::size_t>(
        2, static_cast<std::size_t>(options_.perturbation * static_cast<double>(n_)));
    std::size_t strength = base_strength;
    if (n_ > 0 && rebuild(best_)) {
      best_score_ = table_.score();
      // The start is the first best (time to best 0 when nothing improves on it).
      best_seconds_ = budget_.elapsed_seconds();
      budget_.record_best(evaluations_, best_seconds_, &best_score_);
      tabu_until_.assign(table_.entries(), 0);
      start_penalty();
      scan_all_ = table_.entries() <= static_cast<std::uint64_t>(options_.scan_all_below);
      std::uint64_t fruitless = 0;  // perturbations in a row without a new best
      while (!stopped_) {
        const std::uint64_t last_best = best_step_;
        const std::uint64_t run_start = iterations_;
        while (!stopped_ && iterations_ - std::max(run_start, best_step_) < stall_limit) {
          step();
        }
        if (stopped_) break;
        fruitless = best_step_ > last_best ? 0 : fruitless + 1;
        strength = fruitless == 0 ? base_strength : std::min(n_, strength + strength / 2 + 1);
        if ((options_.restarts >= 0 &&
             perturbations_ >= static_cast<std::uint64_t>(options_.restarts)) ||
            (unlimited_ && options_.restarts < 0 &&
             fruitless >= kUnlimitedFruitlessPerturbations)) {
          stop_ = StopReason::kCompleted;
          break;
        }
        perturb(strength);
      }
    } else if (n_ == 0) {
      best_score_ = problem_.score(best_);
    }
    result.best = best_;
    result.evaluations = evaluations_;
    result.iterations = iterations_;
    result.stop = stop_;
    char text[160];
    std::snprintf(text, sizeof text, "best found at %.3f s, step %llu; %llu perturbations",
                  best_seconds_, static_cast<unsigned long long>(best_step_),
                  static_cast<unsigned long long>(perturbations_));
    result.message = text;
  }

 private:
  // Rebuilds the table on `values` if the budget allows it (else stops).
  bool rebuild(const csp::Assignment& values) {
    if (budget_.exhausted(evaluations_ + table_.rebuild_work(), iterations_)) {
      stop_ = budget_.reason();
      stopped_ = true;
      return false;
    }
    evaluations_ += table_.rebuild_work();
    table_.rebuild(values);
    scratch_ = table_.values();
    return true;
  }

  // Move order: lexicographic (csp::Score) when hard_weight is 0, else by the penalty
  // hard_weight x hard + soft.
  bool prefer(const csp::Score& a, const csp::Score& b) const {
    if (penalty_ <= 0) return a.better_than(b);
    const double pa = penalty_ * a.hard + a.soft;
    const double pb = penalty_ * b.hard + b.soft;
    return pa < pb - 1e-12 * (1 + std::abs(pb));
  }

  // The penalty weight: fixed (hard_weight > 0), none (0), or adaptive (< 0), starting at
  // the mean soft change of a move (hard violations then count like a typical move).
  void start_penalty() {
    penalty_ = options_.hard_weight;
    if (penalty_ >= 0) return;
    double sum = 0;
    std::size_t count = 0;
    for (csp::VariableId v = 0; v < n_; ++v) {
      const auto row = table_.row(v);
      const double here = row[table_.index_of(v)].soft;
      for (const csp::Score& cost : row) {
        if (cost.soft != here) {
          sum += std::abs(cost.soft - here);
          ++count;
        }
      }
    }
    penalty_ = count ? sum / static_cast<double>(count) : 1.0;
  }

  // Strategic oscillation: over each period of max(10, variables) moves, a search that was
  // never feasible doubles the penalty (feasibility matters more), one that was always
  // feasible halves it (it may cross infeasible ground to reach other feasible regions).
  void oscillate() {
    (table_.score().feasible() ? feasible_steps_ : infeasible_steps_) += 1;
    if (feasible_steps_ + infeasible_steps_ < std::max<std::size_t>(10, n_)) return;
    if (feasible_steps_ == 0) {
      penalty_ *= 2;
    } else if (infeasible_steps_ == 0) {
      penalty_ = std::max(penalty_ / 2, 1e-9);
    }
    feasible_steps_ = infeasible_steps_ = 0;
  }

  // Offers one candidate move (`partner` = kNone for a one-variable move) to the choice:
  // kept if admissible and preferred, ties broken uniformly at random (reservoir sampling
  // over `ties`).
  void offer(const csp::Score& change, csp::VariableId v, std::uint32_t a, csp::VariableId partner,
             std::uint32_t b, csp::Score& chosen, std::size_t& ties) {
    if (chosen_var_ == kNone || prefer(change, chosen)) {
      chosen = change;
      ties = 1;
    } else if (prefer(chosen, change) || random_.index(++ties) != 0) {
      return;
    }
    chosen_var_ = v;
    chosen_index_ = a;
    chosen_partner_ = partner;
    chosen_partner_index_ = b;
  }

  bool is_tabu(csp::VariableId v, std::uint32_t a) const {
    return tabu_until_[table_.slot(v, a)] > iterations_;
  }

  // Offers every admissible move of v: its one-variable moves (v's row), and, where moving
  // v breaks a hard binary constraint with a partner, the pair moves that repair it
  // (compound_moves.h). A move is admissible when none of its (variable, value) is tabu, or
  // when it would beat the best score found (aspiration).
  void consider_row(csp::VariableId v, const csp::Score& current, csp::Score& chosen,
                    std::size_t& ties) {
    const auto row = table_.row(v);
    const std::uint32_t here = table_.index_of(v);
    const csp::Score at_here = row[here];
    for (std::uint32_t a = 0; a < row.size(); ++a) {
      if (a == here) continue;
      const csp::Score change = row[a] - at_here;
      if (is_tabu(v, a) && !(current + change).better_than(best_score_)) continue;
      offer(change, v, a, kNone, 0, chosen, ties);
    }
    if (!compound_) return;
    for (const CompoundMoves::Link& link : compound_->links(v)) {
      const csp::VariableId partner = compound_->partner(link);
      const std::uint32_t there = table_.index_of(partner);
      for (std::uint32_t a : compound_->conflicts(link, there)) {
        if (a == here) continue;
        for (std::uint32_t b : compound_->supports(link, a)) {
          const csp::Score change = compound_->change(table_, v, link, a, b, scratch_);
          if ((is_tabu(v, a) || is_tabu(partner, b)) &&
              !(current + change).better_than(best_score_)) {
            continue;
          }
          offer(change, v, a, partner, b, chosen, ties);
        }
      }
    }
  }

  void step() {
    const csp::Score current = table_.score();
    if (options_.stop_at_zero && is_zero(current) && is_zero(problem_.score(table_.values()))) {
      stop_ = StopReason::kTargetReached;
      stopped_ = true;
      return;
    }
    chosen_var_ = kNone;
    chosen_partner_ = kNone;
    csp::Score chosen;
    std::size_t ties = 0;
    if (scan_all_) {
      for (csp::VariableId v = 0; v < n_; ++v) consider_row(v, current, chosen, ties);
    } else {
      for (csp::VariableId v : table_.conflicting()) consider_row(v, current, chosen, ties);
    }
    if (chosen_var_ == kNone) {  // every move is tabu (or no candidate): a random one
      chosen_var_ = static_cast<csp::VariableId>(random_.index(n_));
      chosen_index_ = static_cast<std::uint32_t>(random_.index(table_.domain_size(chosen_var_)));
    }
    const bool pair = chosen_partner_ != kNone;
    const std::uint64_t work =
        table_.move_work(chosen_var_) + (pair ? table_.move_work(chosen_partner_) : 0);
    if (budget_.exhausted(evaluations_ + work, iterations_)) {
      stop_ = budget_.reason();
      stopped_ = true;
      return;
    }
    const std::uint32_t left = table_.index_of(chosen_var_);
    if (left == chosen_index_) {  // a random pick that stays put: a wasted step
      ++iterations_;
      return;
    }
    const std::uint32_t partner_left = pair ? table_.index_of(chosen_partner_) : 0;
    evaluations_ += work;
    table_.move(chosen_var_, chosen_index_);
    scratch_[chosen_var_] = table_.value_at(chosen_var_, chosen_index_);
    if (pair) {
      table_.move(chosen_partner_, chosen_partner_index_);
      scratch_[chosen_partner_] = table_.value_at(chosen_partner_, chosen_partner_index_);
    }
    ++iterations_;
    if (options_.hard_weight < 0) oscillate();
    tabu_until_[table_.slot(chosen_var_, left)] = iterations_ + draw_tenure();
    if (pair) tabu_until_[table_.slot(chosen_partner_, partner_left)] = iterations_ + draw_tenure();
    if (table_.score().better_than(best_score_)) {
      best_score_ = table_.score();
      best_ = table_.values();
      best_step_ = iterations_;
      best_seconds_ = budget_.elapsed_seconds();
      budget_.record_best(evaluations_, best_seconds_, &best_score_);
    }
  }

  std::uint64_t draw_tenure() {
    return static_cast<std::uint64_t>(
        tenure_min_ + static_cast<std::int64_t>(
                          random_.index(static_cast<std::size_t>(tenure_max_ - tenure_min_ + 1))));
  }

  // From the best assignment, `strength` distinct random variables take random values.
  void perturb(std::size_t strength) {
    ++perturbations_;
    csp::Assignment values = best_;
    order_.resize(n_);
    for (csp::VariableId v = 0; v < n_; ++v) order_[v] = v;
    for (std::size_t k = 0; k < strength && k < n_; ++k) {
      std::swap(order_[k], order_[k + random_.index(n_ - k)]);
      const csp::VariableId v = order_[k];
      const csp::Domain& d = problem_.domain(v);
      const auto a = static_cast<std::uint32_t>(random_.index(d.size()));
      values[v] = d.value_at(a);
      if (!compound_) continue;
      // A tight pair broken by the new value is repaired at once (a random support of it):
      // a perturbation that broke pairs would mostly be undone by the first moves.
      for (const CompoundMoves::Link& link : compound_->links(v)) {
        const csp::VariableId u = compound_->partner(link);
        const csp::Domain& du = problem_.domain(u);
        const auto b = static_cast<std::uint32_t>(*du.index_of(values[u]));
        if (compound_->allowed(link, a, b)) continue;
        const auto supports = compound_->supports(link, a);
        if (!supports.empty()) values[u] = du.value_at(supports[random_.index(supports.size())]);
      }
    }
    if (!rebuild(values)) return;
    std::fill(tabu_until_.begin(), tabu_until_.end(), 0);
    if (table_.score().better_than(best_score_)) {
      best_score_ = table_.score();
      best_ = table_.values();
      best_step_ = iterations_;
      best_seconds_ = budget_.elapsed_seconds();
      budget_.record_best(evaluations_, best_seconds_, &best_score_);
    }
  }

  static constexpr csp::VariableId kNone = ~csp::VariableId{0};
  const csp::Problem& problem_;
  const TabuSolver::Options& options_;
  const bool unlimited_;
  Budget& budget_;
  Random random_;
  MoveTable table_;
  const std::size_t n_;
  std::int64_t tenure_min_ = 2, tenure_max_ = 10;
  std::optional<CompoundMoves> compound_;  // none: one-variable moves only
  csp::Assignment scratch_;                // table_.values(), for CompoundMoves::change
  std::vector<std::uint64_t> tabu_until_;  // per (variable, value): step until which it is tabu
  std::vector<csp::VariableId> order_;
  bool scan_all_ = true;
  double penalty_ = 0;  // weight of hard violations in move ranking; 0 = lexicographic
  std::uint64_t feasible_steps_ = 0, infeasible_steps_ = 0;
  csp::VariableId chosen_var_ = kNone;
  std::uint32_t chosen_index_ = 0;
  csp::VariableId chosen_partner_ = kNone;  // kNone: a one-variable move
  std::uint32_t chosen_partner_index_ = 0;
  csp::Assignment best_;
  csp::Score best_score_;
  std::uint64_t best_step_ = 0;
  double best_seconds_ = 0;
  std::uint64_t evaluations_ = 0, iterations_ = 0, perturbations_ = 0;
  bool stopped_ = false;
  StopReason stop_ = StopReason::kCompleted;
};

}  // namespace

void run_tabu_search(const csp::Problem& problem, std::span<const double> start,
                     const TabuSolver::Options& options, std::uint64_t seed, bool unlimited,
                     Budget& budget, SolverResult& result) {
  TabuSearch search(problem, options, seed, unlimited, budget);
  search.run(start, result);
}

}  // namespace sightline::solvers::detail
