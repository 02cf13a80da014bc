// WcspView: a discrete problem seen as a classic weighted CSP with integer costs: unary
// costs per (variable, value), one cost matrix per pair of variables sharing constraints, and
// a forbidden cost standing for every hard violation. It is what soft arc consistency
// (bnb_soft_arc.h) works on: projections and extensions move integer costs between these
// arrays exactly, with no round-off.
//
// Built when every constraint of arity 1 or 2 (any kind: its matrix is read through
// violation(), so tables, not_equal, ... all qualify) has integer weighted costs, every
// constraint of arity >= 3 is a table with integer weighted costs or an all_different with
// an integer weight, and the matrices fit the memory caps below. Otherwise
// `build_wcsp_view` says why and `bnb` falls back to forward checking (bnb_search.h).
// Constraints of arity >= 3 are listed, not projected (soundness before speed): the
// consistency checks a hard one by forward checking (min_violation) and projects any of
// them onto its last unfixed variable only.
//
// Costs: a soft constraint adds weight x violation; a hard one adds kForbidden where its
// violation is positive. Several constraints on the same pair (or variable) are summed into
// one matrix (or unary row). Sums saturate at kForbidden, and the soft costs of the whole
// problem must stay below kSoftCap, so a feasible assignment's cost is never mistaken for a
// forbidden one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::solvers::detail {

struct WcspView {
  static constexpr std::int64_t kForbidden = std::int64_t{1} << 60;
  static constexpr std::int64_t kSoftCap = std::int64_t{1} << 50;

  struct Edge {
    csp::VariableId x = 0, y = 0;    // x < y
    std::vector<std::int64_t> cost;  // cost[a * size(y) + b], value indices a of x, b of y
  };

  std::size_t num_variables() const { return offset.size() - 1; }
  std::uint32_t size(csp::VariableId v) const { return offset[v + 1] - offset[v]; }

  std::vector<std::uint32_t> offset;  // per variable into the slot arrays (n + 1)
  std::vector<double> values;         // per slot: the domain value
  std::vector<std::int64_t> unary;    // per slot
  std::vector<Edge> edges;
  std::vector<csp::ConstraintId> nary;  // constraints of arity >= 3
  const csp::Problem* problem = nullptr;
};

// Saturating sum of two costs in [0, kForbidden].
inline std::int64_t add_cost(std::int64_t a, std::int64_t b) {
  const std::int64_t s = a + b;
  return s >= WcspView::kForbidden ? WcspView::kForbidden : s;
}

// Fills `view` from `problem`; returns "" on success, otherwise why the problem is not a
// binary integer-cost WCSP (and `view` is left unspecified).
std::string build_wcsp_view(const csp::Problem& problem, WcspView& view);

}  // namespace sightline::solvers::detail
