// The part of SoftArcConsistency (bnb_soft_arc.h) that carries constraints of arity >= 3:
// forward checking of the hard ones while two or more of their variables are unfixed, and
// the projection of any of them onto its last unfixed variable (or into c0). Kept apart
// from the pair consistency, which never looks at these constraints.
#include <cmath>

#include "sightline/solvers/detail/bnb_soft_arc.h"

namespace sightline::solvers::detail {

std::size_t SoftArcConsistency::open_nary(csp::VariableId v) const {
  std::size_t open = 0;
  for (std::uint32_t i : nary_of_[v]) open += nary_done_[i] == 0;
  return open;
}

// The weighted cost of an n-ary constraint at values_ (integral: checked by the view).
std::int64_t SoftArcConsistency::nary_cost(const csp::Constraint& con) const {
  const double violation = con.violation(values_);
  if (con.is_hard()) return violation > 0 ? kForbidden : 0;
  return static_cast<std::int64_t>(std::llround(con.weight() * violation));
}

void SoftArcConsistency::revise_nary(std::uint32_t k) {
  if (nary_done_[k]) return;
  const csp::Constraint& con = view_->problem->constraint(view_->nary[k]);
  const auto scope = con.scope();
  std::size_t unfixed = 0;
  csp::VariableId last = 0;
  for (csp::VariableId u : scope) {
    const std::uint32_t ub = view_->offset[u];
    if (size_[u] == 1) {
      for (std::uint32_t a = 0; a < view_->size(u); ++a) {
        if (alive_[ub + a]) values_[u] = view_->values[ub + a];
      }
      assigned_[u] = 1;
    } else {
      ++unfixed;
      last = u;
    }
  }
  if (unfixed == 0) {  // the whole constraint into c0
    set(nary_done_[k], 1);
    set(c0_, add_cost(c0_, nary_cost(con)));
    if (c0_ >= top_) failed_ = true;
    for (csp::VariableId w = 0; w < size_.size() && !failed_; ++w) prune(w);
  } else if (unfixed == 1) {  // onto the last variable's unary costs
    set(nary_done_[k], 1);
    const std::uint32_t lb = view_->offset[last];
    for (std::uint32_t b = 0; b < view_->size(last); ++b) {
      if (!alive_[lb + b]) continue;
      values_[last] = view_->values[lb + b];
      const std::int64_t c = nary_cost(con);
      if (c > 0) set(unary_[lb + b], add_cost(unary_[lb + b], c));
    }
    unary_increased(last);
  } else if (con.is_hard()) {  // forward checking
    if (con.min_violation(values_, assigned_) > 0) failed_ = true;
    for (std::size_t p = 0; p < scope.size() && !failed_; ++p) {
      const csp::VariableId u = scope[p];
      if (assigned_[u]) continue;
      const std::uint32_t ub = view_->offset[u];
      assigned_[u] = 1;
      for (std::uint32_t b = 0; b < view_->size(u) && !failed_; ++b) {
        if (!alive_[ub + b]) continue;
        // One wide constraint can take long (800 queens: 640,000 checks of 800 values):
        // the stop check is asked here too.
        if (++checks_ % kStopStride == 0 && stop_ && stop_()) {
          stopped_ = failed_ = true;
          break;
        }
        values_[u] = view_->values[ub + b];
        if (con.min_violation(values_, assigned_) > 0) remove(u, b);
      }
      assigned_[u] = 0;
    }
  }
  for (csp::VariableId u : scope) assigned_[u] = 0;
}

// The soft n-ary constraints still open hold costs no move has touched, so what each
// must still cost at least (min_violation over the fixed part; floor keeps it a bound) adds
// to c0 as a bound of every completion. Hard ones add nothing: forward checking has them.
std::int64_t SoftArcConsistency::open_nary_bound() {
  nary_bound_ = 0;
  for (std::uint32_t k = 0; k < nary_done_.size(); ++k) {
    const csp::Constraint& con = view_->problem->constraint(view_->nary[k]);
    if (nary_done_[k] || con.is_hard()) continue;
    for (csp::VariableId u : con.scope()) {
      if (size_[u] != 1) continue;
      const std::uint32_t ub = view_->offset[u];
      for (std::uint32_t a = 0; a < view_->size(u); ++a) {
        if (alive_[ub + a]) values_[u] = view_->values[ub + a];
      }
      assigned_[u] = 1;
    }
    const double least = std::floor(con.weight() * con.min_violation(values_, assigned_));
    for (csp::VariableId u : con.scope()) assigned_[u] = 0;
    if (least > 0) nary_bound_ = add_cost(nary_bound_, static_cast<std::int64_t>(least));
  }
  return nary_bound_;
}

}  // namespace sightline::solvers::detail
