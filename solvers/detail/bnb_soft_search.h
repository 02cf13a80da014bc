// SoftArcSearch: `bnb` on a problem that is a binary integer-cost WCSP (bnb_wcsp_view.h),
// with soft arc consistency (bnb_soft_arc.h) maintained at every node.
//
// Depth-first with binary branching as toulbar2 does: at a node, the variable x with the
// smallest alive count / weighted degree (dom/wdeg: the weights of its pairs with other
// unfixed variables; a pair's weight grows by one each time a move on it ended in a failed
// propagation) and its value a of least unary cost (EDAC keeps a zero-cost, fully supported
// one) give two children, x = a and then x != a, each propagated before it is explored.
// Optional last-conflict: a variable whose assignment failed is chosen again next.
// A node fails when propagation empties a domain or c0 reaches top (the incumbent's cost,
// plus one when counting optimal solutions so that every optimum is visited); a leaf is a
// state where every domain holds one value, or where the variables left unfixed are
// isolated (every cost function on them has its other variables fixed: each takes its
// cheapest value there, without branching, unless counting), scored with Problem::score.
// Undo is the consistency's trail.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/solvers/detail/bnb_soft_arc.h"
#include "sightline/solvers/detail/bnb_wcsp_view.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers::detail {

class SoftArcSearch {
 public:
  struct Settings {
    SoftArcConsistency::Level level = SoftArcConsistency::Level::kExistential;
    bool count_mode = false;
    bool use_start = true;
    bool last_conflict = false;
  };
  // `view` must have been built from `problem` by build_wcsp_view. Fills result.best,
  // iterations (nodes: branches tried), evaluations, solutions_at_best, stop and message.
  void run(const csp::Problem& problem, const WcspView& view, std::span<const double> start,
           const Settings& settings, Budget& budget, SolverResult& result);

 private:
  void search();
  void leaf();
  std::uint32_t only_value(csp::VariableId v) const;
  csp::VariableId select_variable() const;
  void failed();
  std::int64_t top() const;

  const csp::Problem* problem_ = nullptr;
  const WcspView* view_ = nullptr;
  Settings settings_;
  Budget* budget_ = nullptr;
  SoftArcConsistency state_;
  std::vector<std::uint64_t> weight_;  // per edge of the view
  csp::Assignment values_;
  csp::Assignment best_;
  bool have_incumbent_ = false;
  std::int64_t ub_ = 0;
  std::uint64_t optimal_count_ = 0;
  std::uint64_t nodes_ = 0;
  std::uint64_t full_evaluations_ = 0;
  bool stopped_ = false;
  static constexpr csp::VariableId kNone = ~csp::VariableId{0};
  csp::VariableId conflict_ = kNone;  // last-conflict variable
};

}  // namespace sightline::solvers::detail
