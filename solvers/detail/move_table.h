// MoveTable: the exact score change of every one-variable move of a discrete problem, kept
// up to date move after move: the "incremental best-move bookkeeping" of tabu search for
// weighted CSPs (as in Galinier & Hao's tabu for graph colouring and toulbar2-style local
// search, with the delta of every (variable, value) pair at hand).
//
// row(v)[a] = the (hard, soft) cost of the constraints on v if v took its a-th value, the
// other variables as they are; the score change of that move is row(v)[a] - row(v)[current].
// A row depends on the other variables only, so moving v leaves v's own row as it is: the
// move changes the rows of the variables that share a constraint with v, and only through
// those constraints. So a move of v, for each constraint c on v and each other variable u of
// c, takes c's part out of u's row before the change and puts the new part back after it:
//     row(u)[b] += w_c (cost_c(u = b) after - cost_c(u = b) before)
// which costs (arity - 1) x |D(u)| constraint deltas per constraint, not a rebuild of rows
// (|D(u)| x every constraint of u). Each delta comes from the constraint's IncrementalState
// (O(1) for a table), or from violation() with the variable changed when the kind offers
// none. Hard and soft parts are kept apart (csp::Score), so moves compare lexicographically
// as csp::Score does, or by any weighting of the two.
//
// With real-valued costs the updates add round-off; rebuild() recomputes everything from
// scratch (the search calls it at each restart). It also keeps, per variable, how many of
// its constraints are violated, and the list of variables with at least one (the
// "conflicting" variables a large problem's search looks at).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::solvers::detail {

class MoveTable {
 public:
  explicit MoveTable(const csp::Problem& problem);

  // Scores `values` (each in its domain) from scratch and fills every row.
  void rebuild(std::span<const double> values);
  // Moves `var` to its value index `index` and updates the rows.
  void move(csp::VariableId var, std::uint32_t index);

  const csp::Score& score() const { return total_; }
  const csp::Assignment& values() const { return values_; }
  std::uint32_t index_of(csp::VariableId var) const { return index_[var]; }
  std::size_t domain_size(csp::VariableId var) const { return offset_[var + 1] - offset_[var]; }
  // The cost of var's constraints for every value of `var`, by value index (see above).
  std::span<const csp::Score> row(csp::VariableId var) const {
    return {rows_.data() + offset_[var], rows_.data() + offset_[var + 1]};
  }
  double value_at(csp::VariableId var, std::uint32_t index) const {
    return domain_values_[offset_[var] + index];
  }
  // Index of (var, value index) in a flat array over every variable's values.
  std::size_t slot(csp::VariableId var, std::uint32_t index) const { return offset_[var] + index; }
  // Variables in at least one violated constraint, in no particular order.
  std::span<const csp::VariableId> conflicting() const { return conflicting_; }
  // The score change if `var` took its value `index`.
  csp::Score change(csp::VariableId var, std::uint32_t index) const {
    return rows_[offset_[var] + index] - rows_[offset_[var] + index_[var]];
  }
  // Row entries a rebuild, or a move of `var`, (re)computes: what the search counts as
  // evaluations, known before the work so that limits can be kept exactly.
  std::uint64_t rebuild_work() const { return offset_.back(); }
  std::uint64_t move_work(csp::VariableId var) const { return move_work_[var]; }
  // Sum of the domain sizes (the table's size).
  std::size_t entries() const { return offset_.back(); }

 private:
  // Violation change of constraint c if the variable at `position` took `value`.
  double constraint_delta(csp::ConstraintId c, std::uint32_t position, double value);
  // Adds sign x (c's part of the row) to the row of every scope variable but `mover`.
  void add_neighbour_parts(csp::ConstraintId c, csp::VariableId mover, double sign);
  void fill_row(csp::VariableId var);
  void set_violation(csp::ConstraintId c, double violation);

  const csp::Problem& problem_;
  std::vector<std::uint32_t> offset_;  // per variable, into rows_ / domain_values_ (n + 1)
  std::vector<double> domain_values_;
  std::vector<csp::Score> rows_;
  std::vector<std::uint64_t> move_work_;
  csp::Assignment values_;
  std::vector<std::uint32_t> index_;
  std::vector<std::unique_ptr<csp::IncrementalState>> states_;  // nullptr: re-evaluate
  std::vector<double> violations_;
  std::vector<double> violations_scratch_;  // move(): each constraint's change
  std::vector<double> weights_;
  std::vector<char> hard_;
  std::vector<std::uint32_t> violated_on_;    // per variable: its violated constraints
  std::vector<std::uint32_t> conflict_slot_;  // per variable: place in conflicting_, or ~0
  std::vector<csp::VariableId> conflicting_;
  csp::Score total_;
};

}  // namespace sightline::solvers::detail
