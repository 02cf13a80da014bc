// TabuSolver (`tabu`): tabu search for weighted discrete problems, moves scored by exact
// weighted deltas.
//
// Local search for optimisation, not only satisfaction: every step moves one variable to
// another value, the best admissible move over the candidates, judged by its exact change
// of the (hard, soft) score. How hard and soft parts are weighed against each other when
// ranking moves is `hard_weight`: 0 ranks lexicographically as csp::Score does (hard
// first); w > 0 ranks by w x hard + soft; -1 (default) adapts w (strategic oscillation):
// it starts at the mean soft change of a move, doubles after a period of max(10, variables)
// moves spent wholly infeasible and halves after one spent wholly feasible, so the search
// may cross infeasible ground (a store sent to a closed warehouse, which then pays to open)
// instead of being walled in by hard constraints. The best assignment is always judged
// lexicographically: only a feasible one beats a feasible best.
// The change of every (variable, value) pair is kept in a table updated move by move
// (detail/move_table.h: a move of v only touches the rows of v's neighbours, through the
// constraints they share), so choosing the best move is a scan of the table, not a
// re-evaluation. Candidates are every variable when the table has at most
// `scan_all_below` entries, else the variables in a violated constraint (soft ones count).
//
// Compound moves (`compound_moves`, on by default): when moving v to a breaks a hard binary
// constraint with u (frequency assignment's duplex |f_v - f_u| = d, any hard table), the
// pair move "v = a, u = b" for every b of u allowed with a is a candidate as well, scored by
// the exact change of both (detail/compound_moves.h); without it, tied pairs can only move
// one half at a time across infeasible ground. Only tight pairs count (hard constraints
// allowing at most half the value pairs: loose ones seldom block a move, and their pair
// moves crowded out better ones on warehouse location); a perturbation (below) that breaks
// a tight pair repairs it with a random support. Problems without tight hard binary
// constraints search exactly as without the option.
//
// Tabu: after v leaves value a, moving v back to a is forbidden for a tenure drawn
// uniformly in [tenure_min, tenure_max] steps (auto: max(2, D / 6) and max(10, 0.7 D) for a
// mean domain size D: 2..10 up to 14 values, 7..31 at 44, where 2..10 let the search cycle
// among the few dozen values of a frequency-assignment pair), unless the move would beat the best score
// found (aspiration); a pair move is tabu when either of its values is, and after it both
// variables' old values are tabu. The best admissible move is taken even when it worsens the score
// (that is how tabu search leaves local minima); ties are broken at random.
//
// Stagnation: after `stall_moves` steps without a new best, the search perturbs the best
// assignment (iterated tabu search): `perturbation` x variables (at least 2, growing by one
// half each time in a row the perturbation brings nothing new, back to the start size after
// a new best) take random values, the tabu marks are cleared and the table is rebuilt from
// scratch (no round-off carried over).
//
// Anytime: with any limit set (time, iterations, evaluations) the search runs until it is
// spent, however many perturbations that takes, unless `restarts` caps them (>= 0); with no
// limit at all it stops after 10 perturbations in a row bring nothing new so that a bare call
// ends. It stops at once on a zero-cost feasible assignment when `stop_at_zero` (nothing can
// beat it: costs are >= 0). The message says when the best was found ("best found at
// 0.41 s, step 5123") and how many perturbations were made.
//
// Iterations count moves; evaluations count the table entries computed (a rebuild computes
// every (variable, value) entry; a move of v its neighbours' rows' entries).
// Deterministic for a given seed. Discrete domains only.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class TabuSolver : public Solver {
 public:
  struct Options {
    std::int64_t tenure_min = -1;  // shortest tabu tenure, steps (>= 0); -1 = auto
    std::int64_t tenure_max = -1;  // longest tabu tenure, steps (>= tenure_min); -1 = auto
    std::int64_t stall_moves = 0;  // steps without a new best before a perturbation;
                                   // 0 = auto (100 x variables, at least 2000)
    double perturbation = 0.1;     // fraction of the variables a perturbation changes, (0, 1]
    std::int64_t restarts = -1;    // cap on perturbations; -1 = none when a limit is set
    std::int64_t scan_all_below = 100000;  // scan every variable when the table is this small
    bool stop_at_zero = true;              // stop at a zero-cost feasible assignment
    double hard_weight = -1;               // moves ranked by hard_weight x hard + soft; 0 = hard
                                           // first (lexicographic); -1 = adaptive
    bool compound_moves = true;            // pair moves repairing hard binary constraints

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  TabuSolver(std::string name, Options options);
  std::string name() const override { return name_; }
  // Needs every domain discrete, and a move table that fits (sum of domain sizes <= 2^26).
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;
  const Options& options() const { return options_; }

 private:
  std::string name_;
  Options options_;
};

}  // namespace sightline::solvers
