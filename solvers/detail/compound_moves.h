// CompoundMoves: two-variable "ejection" moves for local search on problems with hard binary
// constraints, scored by the exact weighted change of both variables together.
//
// Why: when hard binary constraints tie pairs of variables (frequency assignment's duplex
// constraints |f_i - f_j| = d, or any hard table with few supports per value), every
// one-variable move of a tied variable breaks a hard constraint, so a one-variable local
// search can only move such a pair by crossing infeasible ground, one half at a time. The
// standard remedy is the compound move: when moving x to a breaks a hard binary constraint
// with y, y moves at the same time to a value b consistent with a (a support of a). Scored
// exactly, the search then chooses among "x = a, y = its best repair" as among any move.
//
// How: for every pair {x, y} that a hard binary constraint ties (scope exactly {x, y}), the
// pair's binary constraints (hard and soft) are tabulated once into a cost matrix
// M[a][b] (weight x violation, hard and soft apart), with the allowed matrix (every hard
// binary constraint of the pair satisfied) and, per value of either side, its supports on
// the other side. With MoveTable's one-variable changes (rows hold the cost of x's
// constraints with y at its current value y0, and of y's with x at x0), the exact change of
// the pair move (x: x0 -> a, y: y0 -> b) is
//     change_x(a) + change_y(b) + [M(a,b) - M(a,y0) - M(x0,b) + M(x0,y0)]
//                               + the same correction for every wider constraint on both
// (the bracket corrects the constraints counted with the other variable at its old value;
// wider constraints on both x and y are re-evaluated with violation()).
// A pair move is offered only when x = a breaks the pair (y0 is not allowed with a): other
// moves of x are one-variable moves already. Pairs whose matrices would exceed
// `max_entries` in total are left out (their moves stay one-variable; memory is bounded).
// Only tight pairs are kept: those whose hard constraints allow at most `max_density` (half)
// of the value pairs. A loose hard constraint (warehouse location's "a store's warehouse is
// open": every pair allowed but one) seldom blocks a one-variable move, and its pair moves
// (close a warehouse, move one of its stores) crowd the choice without helping: on the
// held-out warehouse instances tabu with them ended 5-12% above the optimum it reached
// without them. Duplex constraints allow one or two of ~40 values per value.
// Discrete domains only; the matrices are static (they do not depend on the assignment).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/solvers/detail/move_table.h"

namespace sightline::solvers::detail {

class CompoundMoves {
 public:
  // Tabulates every pair tied by a hard binary constraint, up to `max_entries` matrix
  // entries in total (pairs beyond it are skipped, in constraint order).
  // Only pairs whose hard binary constraints allow at most `max_density` of the value
  // pairs are kept (see above).
  explicit CompoundMoves(const csp::Problem& problem,
                         std::size_t max_entries = std::size_t{1} << 21,
                         double max_density = 0.5);

  // One pair as seen from one of its variables ("self"): the partner and where to look.
  struct Link {
    std::uint32_t pair;
    bool self_is_first;  // self is the pair's row variable
  };
  std::span<const Link> links(csp::VariableId var) const {
    return {links_.data() + link_start_[var], links_.data() + link_start_[var + 1]};
  }
  csp::VariableId partner(const Link& link) const {
    return link.self_is_first ? pairs_[link.pair].second : pairs_[link.pair].first;
  }
  // Whether self = a and partner = b satisfy every hard binary constraint of the pair.
  bool allowed(const Link& link, std::uint32_t a, std::uint32_t b) const;
  // The partner's values allowed with self = a (value indices).
  std::span<const std::uint32_t> supports(const Link& link, std::uint32_t a) const;
  // Self's values not allowed with partner = b: the moves of self that break the pair when
  // the partner is at b (so a search visits only those, not every value of every link).
  std::span<const std::uint32_t> conflicts(const Link& link, std::uint32_t b) const;
  // Exact score change of self: -> a together with partner: -> b, from the table's state.
  // `scratch` must equal table.values() on entry; it is restored on exit.
  csp::Score change(const MoveTable& table, csp::VariableId self, const Link& link,
                    std::uint32_t a, std::uint32_t b, csp::Assignment& scratch) const;
  // Number of tight pairs, those with links (0: no hard binary constraint that qualifies).
  std::size_t num_pairs() const { return tight_pairs_; }
  // Whether some wider constraint reads both variables of `link`'s pair (its change then
  // calls violation(); else a pair move costs a few table reads).
  bool has_wider(const Link& link) const {
    return wider_start_[link.pair + 1] > wider_start_[link.pair];
  }

 private:
  struct Pair {
    csp::VariableId first, second;
    std::uint32_t rows, cols;    // domain sizes of first and second
    std::size_t matrix;          // offset of M / allowed, row-major (first's index, second's)
    std::size_t row_supports;    // offset into support_start_: rows + 1 entries (first = a)
    std::size_t col_supports;    // offset into support_start_: cols + 1 entries (second = b)
    std::size_t row_conflicts;   // offset into support_start_: per second's value b, the
                                 // first's values not allowed with it (cols + 1 entries)
    std::size_t col_conflicts;   // per first's value a, the second's values (rows + 1)
  };
  csp::Score pair_cost(const Pair& p, std::uint32_t a, std::uint32_t b) const {
    return cost_[p.matrix + std::size_t{a} * p.cols + b];
  }

  const csp::Problem& problem_;
  std::vector<Pair> pairs_;
  std::vector<csp::Score> cost_;   // M per pair: the pair's binary constraints, weighted
  std::vector<char> allowed_;      // per pair: every hard binary constraint satisfied
  std::vector<std::uint32_t> support_start_;  // CSR into supports_
  std::vector<std::uint32_t> supports_;
  std::vector<std::uint32_t> wider_start_;    // per pair: CSR into wider_ (pairs + 1)
  std::vector<csp::ConstraintId> wider_;      // constraints of arity >= 3 on both
  std::vector<std::uint32_t> link_start_;     // per variable: CSR into links_ (n + 1)
  std::vector<Link> links_;
  std::size_t tight_pairs_ = 0;
};

}  // namespace sightline::solvers::detail
