// DiscreteSearch: min-conflicts local search with permutation swaps, the discrete half of
// SlsSolver (solvers/sls.h says what it does and why; this is how).
//
// One object per solve. The search state is an IncrementalEvaluator plus what local search
// keeps around it: tabu marks, the list of variables believed to be in conflict, the best
// assignment seen (BestKeeper), breakout weights and the permutation groups. Its code is in
// two files: discrete_search.cc (runs, restarts, the conflict list and the two phases) and
// discrete_search_moves.cc (the moves: value steps and the swaps).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sightline/csp/incremental_evaluator.h"
#include "sightline/solvers/detail/best_keeper.h"
#include "sightline/solvers/detail/breakout_weights.h"
#include "sightline/solvers/detail/permutation_groups.h"
#include "sightline/solvers/detail/random.h"
#include "sightline/solvers/detail/zeroed_array.h"
#include "sightline/solvers/sls.h"

namespace sightline::solvers::detail {

// Incremental scores below this are checked from scratch as possible zero-cost assignments.
inline constexpr double kNearZero = 1e-9;

inline bool improves(const csp::Score& delta) { return delta.better_than(csp::Score{}); }
inline bool worsens(const csp::Score& delta) { return csp::Score{}.better_than(delta); }

class DiscreteSearch {
 public:
  // `restart_cap`: restarts allowed, 0 = until a limit stops the search.
  DiscreteSearch(const csp::Problem& problem, const SlsSolver::Options& options,
                 std::uint64_t restart_cap, std::uint64_t seed, Budget& budget);

  // Fills result.best, evaluations, iterations, stop and message. Returns the full
  // evaluation of result.best (evaluate_fully, with the breakdown when `keep_breakdown`)
  // when the search stopped on a zero-cost assignment, which it checks that way from
  // scratch, and nothing otherwise.
  std::optional<FullEvaluation> run(std::span<const double> start, SolverResult& result,
                                    bool keep_breakdown);

 private:
  // --- runs and restarts ---------------------------------------------------------------

  // Group variables whose values are not a permutation of the group's values, or whose pinned
  // variables are not at their values, are dealt the group's values anew (see deal_group).
  void make_groups_permutations(csp::Assignment& values);

  // True when the group's variables hold each of its values exactly once (marks each value's
  // index, found by binary search: O(k log k) without copying or sorting).
  bool is_permutation(const PermutationGroup& g, const csp::Assignment& values);

  // A fresh permutation for a group: pins at their values, the free values in order. Cheap
  // (sequential writes), and enough when constructive placement follows, which re-deals
  // them at random; begin_dealt_run shuffles the groups it will not take.
  void deal_group(const PermutationGroup& g, csp::Assignment& values);

  void shuffle_group(const PermutationGroup& g, csp::Assignment& values);

  // begin_run, after which the freshly dealt groups that placement will not re-deal (it is
  // off, or their constraints cannot retract) are shuffled, the evaluator rebuilt on them,
  // and their dealt_ mark cleared: the marks left are the groups placement will re-deal.
  void begin_dealt_run(csp::Assignment values);

  void randomise(csp::Assignment& values);

  void begin_run(csp::Assignment values);

  // Restarts from a random assignment, or ends the search when the restarts are used up.
  void restart_or_finish();

  bool out_of_budget();

  // Stops the search at a zero-cost feasible assignment (checked from scratch).
  bool check_target();

  // The current assignment, scored `score`, becomes the best; the budget notes when.
  void new_best(const csp::Score& score);

  // After an accepted move: keep the best, measure progress, look for the target.
  void after_move();

  // --- moves ---------------------------------------------------------------------------

  bool is_tabu(csp::VariableId v, double value) const;

  // `v` leaves `old_value`: remember it for the best keeper and for tabu. Call check_log()
  // once the whole move is noted.
  void note_change(csp::VariableId v, double old_value);
  void check_log() { best_.check_log(evaluator_->values()); }

  void apply(csp::VariableId v, double value);

  void swap(csp::VariableId v, csp::VariableId j);

  // Min-conflicts on one variable: the best candidate value, if it does not worsen the score.
  bool value_step(csp::VariableId v, bool greedy);

  // The greedy pass's swap, for groups that constructive placement does not take (a start
  // that already was a permutation, or constraints without partial assignments): the first
  // of up to `greedy_samples` partners, drawn from the `greedy_window` group positions after
  // `first` (nearby variables: their data is in cache), after which v is in no conflict at
  // all. The partner takes v's value and whatever conflicts come with it: its own turn,
  // later in the pass, deals with them. Unlike placement every variable counts here, so a
  // random partner frees v less often (about e^-2 of the time on N-queens, not 0.43).
  bool greedy_swap(csp::VariableId v, std::size_t first);

  // A swap of v with a partner of its permutation group. `swap_samples` random partners are
  // screened by the cheap half of the swap, delta(v -> partner's value), which reads only
  // v's side; the partners with the best half (up to kFinalists) are then tried for real,
  // both assigns, in random order: the first that improves the score is kept, else the
  // first sideways one that does not undo a recent move (tabu); the others are reverted.
  // Sets `partner` when it moves.
  bool swap_step(csp::VariableId v, csp::VariableId& partner);

  // swap_step for a group with at most swap_samples other free variables: every partner is
  // tried for real and the best is taken, judged with breakout weights (Morris 1993): the
  // hard part of a move's delta is sum_c w_c (violation after - violation before) over the
  // hard constraints it touches, w_c >= 1, the soft part is the plain soft delta. When no
  // partner lowers or keeps that weighted score (a local minimum for v), the weight of every
  // violated hard constraint around v grows by one: a constraint that stays violated at
  // local minima becomes expensive, and the search is pushed to satisfy it at the cost of
  // others instead of cycling. Tabu as in swap_step, except for moves that improve the true
  // score. The best keeper and restarts still follow the true score.
  bool small_swap_step(csp::VariableId v, const PermutationGroup& g, csp::VariableId& partner);

  // --- the conflict list -----------------------------------------------------------------

  void push(csp::VariableId v);

  // Adds every variable in conflict to the list. The list cannot follow conflicts a move
  // creates for third parties (the queen already on the row a queen moves to): nothing
  // generic names them. So besides refilling an empty list, rescan() also runs after every
  // `rescan_work_` evaluations, which is about twice the work of the scan itself, so it
  // costs at most a third of the search whatever the size of the problem.
  void rescan();

  // --- the two phases --------------------------------------------------------------------

  // One pass in variable order; each variable in conflict takes an improving move if one of
  // its sampled values (or swaps with later variables of its group) offers it.
  void greedy_pass();

  void main_loop();

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
  // Per variable, the value it last left and the step until which it may not go back:
  // side by side, as is_tabu reads both, and zero at each start without writing them (a
  // run may touch few variables; see ZeroedArray).
  struct Tabu {
    std::uint64_t until;
    double value;
  };
  ZeroedArray<Tabu> tabu_;
  static constexpr std::size_t kFinalists = 4;
  std::array<csp::VariableId, kFinalists> finalists_{};  // swap_step's best-screened partners
  std::vector<csp::VariableId> list_;                    // variables believed to be in conflict
  BreakoutWeights breakout_;                             // small groups' swaps
  std::vector<csp::ConstraintId> constant_;              // the groups' own all_differents
  std::vector<char> dealt_;   // per group: dealt in order this run, for placement to re-deal
  std::vector<char> seen_;    // is_permutation's marks
  std::vector<double> pool_;  // place_group's scratch
  ZeroedArray<char> listed_;  // per variable: in list_
  std::uint64_t last_rescan_ = 0, rescan_work_ = 0;  // in evaluations

  std::uint64_t evaluations_ = 0, iterations_ = 0;
  std::uint64_t stall_ = 0, stall_limit_ = 0, restarts_used_ = 0;
  const std::uint64_t restart_cap_;  // 0 = none
  bool stopped_ = false;
  bool keep_breakdown_ = false;  // in the target check's evaluation (see run)
  std::optional<FullEvaluation> target_;  // set by check_target when it stops the search
  StopReason stop_ = StopReason::kCompleted;
  std::string message_;
};

}  // namespace sightline::solvers::detail
