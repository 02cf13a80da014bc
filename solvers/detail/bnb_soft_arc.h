// SoftArcConsistency: the cost state of a weighted CSP (bnb_wcsp_view.h) under search, kept
// soft arc consistent with equivalence-preserving cost moves, every change trailed so that
// backtracking restores the exact state. `bnb` reads its lower bound c0 and its unary costs.
//
// State: c0 (a cost every completion pays), unary costs C_i(a), binary costs
// C_ij(a, b) = M_ij(a, b) - dx_ij(a) - dy_ij(b) (the matrix of the view, never written,
// minus what was projected out of row a onto x, or extended from y's b into column b, as
// toulbar2 does: a move costs O(d) trailed cells, not O(d^2)), alive flags and domain sizes.
// Every move keeps the cost of each complete assignment of the current domains exactly
// (feasible ones; forbidden ones stay >= kForbidden), so c0 never exceeds the optimum of
// the subproblem. "top" is the pruning threshold: the incumbent's cost (plus one when every
// optimum must be visited); a value with c0 + C_i(a) >= top is removed, and a state with
// c0 >= top fails. Hard violations cost kForbidden >= top, so they prune as in classic WCSP
// with k = top.
//
// Levels (Larrosa & Schiex 2004 "Solving weighted CSP by maintaining arc consistency";
// de Givry, Heras, Zytnicki & Larrosa 2005 "Existential arc consistency: getting closer to
// full arc consistency in weighted CSPs"), each including the ones before:
//  - kNode (NC*): c0 + C_i(a) < top for every alive value, and some alive value of every
//    variable has C_i(a) = 0 (min projected into c0). Pairs with a singleton side are
//    projected onto the other side (forward checking).
//  - kArc (AC*): every alive a of x has a simple support b on each C_xy: C_xy(a, b) = 0
//    (row minima projected onto C_x).
//  - kDirectional (FDAC*): for x < y every alive a of x has a full support b in y:
//    C_xy(a, b) + C_y(b) = 0 (unary costs of y extended into C_xy, then projected onto x,
//    moving costs toward lower ids).
//  - kExistential (EDAC*): and every variable x has an alive a with C_x(a) = 0 that is fully
//    supported on every pair at once; where none is, full supports are sought toward x on
//    all its pairs, which raises c0 by the least sum (the violation of existential AC).
// Constraints of arity >= 3 (tables and all_differents with integer costs) are not
// projected while two or more of their variables are unfixed: a hard one is then forward
// checked (a value goes when min_violation with it is positive), and any of them is moved
// whole onto its last unfixed variable's unary costs (or into c0) once the others are fixed.
// Each EAC step raises c0 by at least 1 (integer costs) and FDAC* terminates, so
// propagation ends; a cap on the steps of one call also bounds it (stopping early keeps
// the bound valid, only weaker).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "sightline/solvers/detail/bnb_wcsp_view.h"

namespace sightline::solvers::detail {

class SoftArcConsistency {
 public:
  enum class Level { kNode, kArc, kDirectional, kExistential };
  static constexpr std::int64_t kForbidden = WcspView::kForbidden;

  // Copies what it needs from `view` (which must outlive this object: its matrices are read).
  void load(const WcspView& view, Level level);
  Level level() const { return level_; }

  // The pruning threshold (kForbidden when there is no incumbent). Lowering it is always
  // valid; the next propagate() prunes with it. Raising it does not bring back values
  // already removed (the state then holds only for costs below the old top).
  void set_top(std::int64_t top) { top_ = top; }
  std::int64_t top() const { return top_; }

  // Value changes; each is recorded for the next propagate(). False when a domain empties.
  bool assign(csp::VariableId v, std::uint32_t a);
  bool remove(csp::VariableId v, std::uint32_t a);
  // Enforces the level; false when a domain empties or c0 >= top (the state is then
  // partial and must be undone), or when `stop` (if set) said so: a limit must hold inside
  // one long propagation too (a root over large domains); stopped() then tells.
  bool propagate();
  void set_stop_check(std::function<bool()> stop) { stop_ = std::move(stop); }
  bool stopped() const { return stopped_; }

  std::size_t mark() const { return trail_.size(); }
  void undo(std::size_t mark);

  std::int64_t lower_bound() const { return c0_; }
  // What the soft constraints of arity >= 3 not yet projected must still cost at least
  // (min_violation over their fixed part), as of the last successful propagate(): c0 plus
  // it bounds every completion too, and propagate() fails when that reaches top.
  std::int64_t nary_lower_bound() const { return nary_bound_; }
  std::size_t num_variables() const { return size_.size(); }
  std::uint32_t domain_size(csp::VariableId v) const { return view_->size(v); }
  std::uint32_t alive_count(csp::VariableId v) const {
    return static_cast<std::uint32_t>(size_[v]);
  }
  bool alive(csp::VariableId v, std::uint32_t a) const { return alive_[view_->offset[v] + a] != 0; }
  std::int64_t unary(csp::VariableId v, std::uint32_t a) const {
    return unary_[view_->offset[v] + a];
  }
  // C_v(a) + sum over v's pairs of min over b (C(a, b) + C_w(b)): what a costs with its
  // neighbours' best answers; 0 for EDAC's existential support (value ordering).
  std::int64_t support_cost(csp::VariableId v, std::uint32_t a) const;
  std::size_t num_edges() const { return view_->edges.size(); }
  std::int64_t binary(std::size_t e, std::uint32_t a, std::uint32_t b) const;
  // The edges of v (ids into the view) and the pair variable on each.
  struct Neighbour {
    std::uint32_t edge;
    csp::VariableId other;
    bool is_x;  // v is the edge's x
  };
  const std::vector<Neighbour>& neighbours(csp::VariableId v) const { return neighbours_[v]; }
  // How many constraints of arity >= 3 on v are not yet projected.
  std::size_t open_nary(csp::VariableId v) const;
  // The edge whose move last changed the state (for dom/wdeg after a failure), or -1.
  std::int64_t last_edge() const { return last_edge_; }
  // Every trailed cell, for tests comparing a state before and after undo.
  std::vector<std::int64_t> snapshot() const;

 private:
  // Queue steps (and n-ary forward checks) between two asks of the stop check.
  static constexpr std::uint64_t kStopStride = 64;
  void set(std::int64_t& cell, std::int64_t value) {
    trail_.push_back({&cell, cell});
    cell = value;
  }
  std::int64_t& delta(std::uint32_t e, bool x_side, std::uint32_t a) {
    return deltas_[(x_side ? delta_x_[e] : delta_y_[e]) + a];
  }
  std::int64_t cost(std::uint32_t e, std::uint32_t a, std::uint32_t b) const {
    const WcspView::Edge& edge = view_->edges[e];
    const std::int64_t m = edge.cost[std::size_t{a} * view_->size(edge.y) + b];
    if (m >= kForbidden) return kForbidden;
    return m - deltas_[delta_x_[e] + a] - deltas_[delta_y_[e] + b];
  }
  // The costs of pair e seen from one side s (x when onto_x): at(a, b) = C(s = a, o = b),
  // with the addresses hoisted out of the loops that scan rows.
  struct SidedPair {
    const std::int64_t* matrix;
    std::size_t row_stride, column_stride;
    const std::int64_t* delta_s;
    const std::int64_t* delta_o;
    std::int64_t at(std::uint32_t a, std::uint32_t b) const {
      const std::int64_t m = matrix[a * row_stride + b * column_stride];
      return m >= kForbidden ? kForbidden : m - delta_s[a] - delta_o[b];
    }
  };
  SidedPair sided(std::uint32_t e, bool onto_x) const {
    const WcspView::Edge& edge = view_->edges[e];
    const std::size_t dy = view_->size(edge.y);
    const std::int64_t* dx = deltas_.data() + delta_x_[e];
    const std::int64_t* dyv = deltas_.data() + delta_y_[e];
    return onto_x ? SidedPair{edge.cost.data(), dy, 1, dx, dyv}
                  : SidedPair{edge.cost.data(), 1, dy, dyv, dx};
  }
  // Moves the cheapest cost of each alive value row onto that side (AC*'s projection);
  // returns true when something moved.
  // The alive values of v, in order, into `out` (stops once size_[v] are found).
  void list_alive(csp::VariableId v, std::vector<std::uint32_t>& out) const;
  bool project_simple(std::uint32_t e, bool onto_x);
  // Full supports toward `onto_x`'s side (extension from the other side, then projection).
  bool project_full(std::uint32_t e, bool onto_x);
  // AC* on one side of a pair: item = 2 e (onto x) or 2 e + 1 (onto y).
  void revise_side(std::uint32_t item);
  void revise_existential(csp::VariableId v);
  void revise_nary(std::uint32_t k);
  std::int64_t nary_cost(const csp::Constraint& con) const;
  std::int64_t open_nary_bound();
  bool node_consistency(csp::VariableId v);
  bool prune(csp::VariableId v);
  void unary_increased(csp::VariableId v);
  void edge_changed(std::uint32_t e, bool onto_x);
  void value_removed(csp::VariableId v);
  void push_ac(std::uint32_t e, bool onto_x);
  void push_dac(std::uint32_t e);
  bool dac_before(std::uint32_t e, std::uint32_t f) const;  // heap order: f's y is higher
  void push_eac(csp::VariableId v);
  void push_nc(csp::VariableId v);
  void clear_queues();

  const WcspView* view_ = nullptr;
  Level level_ = Level::kExistential;
  std::int64_t top_ = kForbidden;
  std::int64_t checked_top_ = 0;  // the top every alive value was last checked with (trailed)
  std::int64_t c0_ = 0;
  std::vector<std::int64_t> unary_, alive_, size_;
  std::vector<std::int64_t> deltas_;
  std::vector<std::uint32_t> delta_x_, delta_y_;  // per edge, into deltas_
  // Last simple support found per (edge, side, value), laid out as deltas_: a hint, not
  // trailed (checked before use: alive and of zero cost), so AC* rescans a row only when
  // its support has gone.
  std::vector<std::uint32_t> support_;
  // The same for full supports (toward x when x < y, or toward an EAC variable).
  std::vector<std::uint32_t> full_support_;
  std::vector<std::vector<Neighbour>> neighbours_;
  struct Change {
    std::int64_t* cell;
    std::int64_t old;
  };
  std::vector<Change> trail_;
  // Work queues with membership flags (not trailed: emptied on failure).
  std::vector<std::uint32_t> ac_queue_, dac_queue_;  // AC items (see revise_side); edges (a heap)
  std::vector<csp::VariableId> eac_queue_, nc_queue_;
  std::vector<std::uint32_t> nary_queue_;
  std::vector<std::uint8_t> in_ac_, in_dac_, in_eac_, in_nc_, in_nary_;
  // Constraints of arity >= 3: per variable, its entries of view.nary; per entry, 1 once
  // projected (trailed); scratch values and assigned flags for violation/min_violation.
  std::vector<std::vector<std::uint32_t>> nary_of_;
  std::vector<std::int64_t> nary_done_;
  std::int64_t nary_bound_ = 0;  // see nary_lower_bound()
  std::vector<double> values_;
  std::vector<std::uint8_t> assigned_;
  bool failed_ = false;
  bool prune_all_ = false;  // c0 rose: every domain to be pruned when the queues are empty
  bool stopped_ = false;
  std::uint64_t checks_ = 0;  // n-ary forward checks, for the stop check
  std::function<bool()> stop_;
  std::int64_t last_edge_ = -1;
  std::vector<std::int64_t> scratch_alpha_;
  std::vector<std::uint32_t> scratch_alive_;  // alive values of a pair's other side
};

}  // namespace sightline::solvers::detail
