// BranchAndBoundSearch: the state and steps of one `bnb` search (solvers/bnb.h describes
// the method: bounds, pruning, orderings). Kept apart from the solver class so the solver
// file is the interface and options, and this pair the algorithm.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers::detail {

// Flat arrays indexed by slot = offset[v] + value index hold per-(variable, value) data.
class BranchAndBoundSearch {
 public:
  // Searches `problem` from `start` (the initial upper bound when `use_start` and it is
  // feasible) and fills result.best, iterations, evaluations, solutions_at_best (when
  // counting), stop and message.
  void run(const csp::Problem& problem, std::span<const double> start, bool count_mode,
           bool use_start, Budget& budget, SolverResult& result);

 private:
  struct Undo {
    enum Kind : std::uint8_t { kAssign, kCount, kAlive, kRow, kContribution, kMin, kDegree };
    Kind kind;
    std::uint32_t a;  // variable, constraint or slot
    std::uint32_t b;  // variable (kAlive), buffer start (kRow, kContribution)
    double old;       // previous value (kAssign, kMin) or target (kContribution)
  };
  // The sums making up the lower bound; saved and restored whole around each child.
  struct Sums {
    double assigned_cost = 0;  // g
    double future_min = 0;     // sum over future variables of min alive (ic + dac)
  };

  void setup(const csp::Problem& problem, std::span<const double> start);
  bool initial_propagation();
  void search(std::size_t depth);
  void leaf();
  csp::VariableId select_variable() const;
  bool assign(csp::VariableId u, std::uint32_t index);
  void project(csp::ConstraintId c, csp::VariableId w);
  bool check_hard_partial(csp::ConstraintId c);
  void retarget(csp::ConstraintId c);
  void compute_contribution(csp::ConstraintId c, csp::VariableId target);
  void fill_bound_row(csp::VariableId u);
  void kill(csp::VariableId v, std::uint32_t index);
  void touch(csp::VariableId v);
  bool refresh_touched();
  void undo_to(std::size_t mark);
  // Propagation can run long on one node: forward checking a hard constraint over k
  // variables of d values makes k d checks, each O(k) for a global one (an all_different
  // over 1,000 queens: 10^6 checks of 1,000 keys at the root). So propagation also asks the
  // budget, every kPropagationStride constraint checks; when it is spent, stopped_ is set
  // and the node fails, which unwinds the search as a stop between branches does.
  bool propagation_stopped();
  static constexpr std::uint64_t kPropagationStride = 256;
  double lower_bound() const { return sums_.assigned_cost + sums_.future_min; }
  bool prunes(double bound) const {
    if (!have_incumbent_) return false;
    const double tol = 1e-9 * std::max(1.0, std::abs(ub_));
    return count_mode_ ? bound > ub_ + tol : bound >= ub_ - tol;
  }

  const csp::Problem* problem_ = nullptr;
  std::size_t n_ = 0;
  bool count_mode_ = false;
  Budget* budget_ = nullptr;

  std::vector<std::uint32_t> offset_;   // per variable, into the slot arrays (n + 1)
  std::vector<double> domain_values_;   // per slot
  std::vector<double> values_;          // current assignment (unassigned: meaningless)
  std::vector<std::uint8_t> assigned_;  // per variable
  std::vector<std::uint8_t> alive_;     // per slot
  std::vector<std::uint32_t> alive_count_;
  std::vector<double> ic_soft_, ic_hard_;     // per slot
  std::vector<double> min_soft_;              // per variable: min of ic_soft_ over alive values
  std::vector<std::uint32_t> unassigned_in_;  // per constraint
  // Soft constraints with >= 2 unassigned variables lend a bound to one of them, their
  // target: contribution_[contribution_offset_[c] + a] <= cost of c if target = a.
  static constexpr csp::VariableId kNoTarget = ~csp::VariableId{0};
  std::vector<csp::VariableId> target_;
  std::vector<std::uint32_t> contribution_offset_;  // per constraint (m + 1)
  std::vector<double> contribution_;
  std::vector<double> bound_row_;      // scratch: ic + dac of one variable
  std::vector<std::uint32_t> degree_;  // per variable: constraints shared with others
  Sums sums_;

  std::vector<Undo> trail_;
  std::vector<double> row_buffer_;
  std::vector<csp::VariableId> touched_;
  std::vector<std::uint64_t> touched_stamp_;
  std::uint64_t stamp_ = 0;
  // Value orders of the open nodes: (ic + dac, value index).
  std::vector<std::pair<double, std::uint32_t>> order_stack_;

  bool have_incumbent_ = false;
  double ub_ = std::numeric_limits<double>::infinity();
  csp::Assignment best_;
  std::uint64_t optimal_count_ = 0;
  std::uint64_t nodes_ = 0;
  std::uint64_t evaluations_ = 0;       // single-constraint checks (propagation included)
  // Whole candidates scored (the start and every leaf): the "evaluations" every solver
  // reports and every evaluation limit counts, one candidate = one.
  std::uint64_t full_evaluations_ = 0;
  bool stopped_ = false;
  std::uint64_t next_budget_check_ = 0;  // evaluations_ at which propagation asks again
};

}  // namespace sightline::solvers::detail
