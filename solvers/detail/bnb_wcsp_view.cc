#include "sightline/solvers/detail/bnb_wcsp_view.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>


namespace sightline::solvers::detail {

namespace {

bool integral(double cost) {
  return std::isfinite(cost) && cost >= 0 && cost == std::floor(cost) &&
         cost < static_cast<double>(WcspView::kSoftCap);
}

// An n-ary constraint the consistency can carry: its weighted costs are all integers.
// Returns its largest weighted cost (0 for a hard one), or -1 when it cannot be carried.
double nary_largest_cost(const csp::Constraint& con) {
  if (const csp::TableCosts* table = con.table_costs()) {
    if (con.is_hard()) return 0;
    double largest = con.weight() * table->default_cost();
    if (!integral(largest)) return -1;
    for (std::size_t i = 0; i < table->num_tuples(); ++i) {
      const double c = con.weight() * table->tuple_cost(i);
      if (!integral(c)) return -1;
      largest = std::max(largest, c);
    }
    return largest;
  }
  if (con.distinctness()) {
    if (con.is_hard()) return 0;
    // Violation: a count of repeated variables or of equal pairs, at most k^2.
    const double k = static_cast<double>(con.scope().size());
    return integral(con.weight()) ? con.weight() * k * k : -1;
  }
  return -1;
}

std::pair<csp::VariableId, csp::VariableId> ordered(csp::VariableId a, csp::VariableId b) {
  return a < b ? std::pair{a, b} : std::pair{b, a};
}

// Per-matrix and total caps on cost entries, so a huge domain product falls back instead of
// allocating gigabytes.
constexpr std::uint64_t kMaxEdgeEntries = std::uint64_t{1} << 22;
constexpr std::uint64_t kMaxTotalEntries = std::uint64_t{1} << 24;

}  // namespace

std::string build_wcsp_view(const csp::Problem& problem, WcspView& view) {
  if (!problem.all_discrete()) return "a domain is not discrete";
  const std::size_t n = problem.num_variables();
  view.offset.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) {
    view.offset[v + 1] =
        view.offset[v] + static_cast<std::uint32_t>(problem.domain(v).size());
  }
  view.values.resize(view.offset[n]);
  for (std::size_t v = 0; v < n; ++v) {
    const csp::Domain& d = problem.domain(v);
    for (std::size_t i = 0; i < d.size(); ++i) view.values[view.offset[v] + i] = d.value_at(i);
  }
  view.unary.assign(view.offset[n], 0);
  view.edges.clear();
  view.nary.clear();
  view.problem = &problem;

  // Checks first (cheap), so a problem that falls back allocates no matrix.
  std::map<std::pair<csp::VariableId, csp::VariableId>, std::size_t> edge_of;
  std::uint64_t entries = 0;
  for (csp::ConstraintId c = 0; c < problem.num_constraints(); ++c) {
    const auto scope = problem.constraint(c).scope();
    if (scope.size() > 2) {
      if (nary_largest_cost(problem.constraint(c)) < 0) {
        return "a constraint of arity " + std::to_string(scope.size()) +
               " is neither a table nor an all_different with integer costs";
      }
      view.nary.push_back(c);
    }
    if (scope.size() == 2) {
      const auto key = ordered(scope[0], scope[1]);
      if (edge_of.emplace(key, edge_of.size()).second) {
        const std::uint64_t e = std::uint64_t{view.size(key.first)} * view.size(key.second);
        if (e > kMaxEdgeEntries) return "a cost matrix would be too large";
        entries += e;
      }
    }
  }
  if (entries > kMaxTotalEntries) return "the cost matrices would be too large";
  view.edges.resize(edge_of.size());
  for (const auto& [key, e] : edge_of) {
    view.edges[e].x = key.first;
    view.edges[e].y = key.second;
    view.edges[e].cost.assign(std::size_t{view.size(key.first)} * view.size(key.second), 0);
  }

  csp::Assignment values = problem.default_assignment();
  double soft_total = 0;  // sum over soft constraints of their largest cost
  // The weighted cost of constraint c at the current `values`, or -1 when not an integer.
  auto cost_here = [&](const csp::Constraint& con, double& largest) -> std::int64_t {
    const double violation = con.violation(values);
    if (con.is_hard()) return violation > 0 ? WcspView::kForbidden : 0;
    const double cost = con.weight() * violation;
    if (!std::isfinite(cost) || cost < 0 || cost != std::floor(cost) ||
        cost >= static_cast<double>(WcspView::kSoftCap)) {
      return -1;
    }
    largest = std::max(largest, cost);
    return static_cast<std::int64_t>(cost);
  };
  for (csp::ConstraintId c = 0; c < problem.num_constraints(); ++c) {
    const csp::Constraint& con = problem.constraint(c);
    const auto scope = con.scope();
    double largest = 0;
    if (scope.size() > 2) {
      largest = nary_largest_cost(con);
    } else if (scope.size() == 1) {
      const csp::VariableId v = scope[0];
      for (std::uint32_t a = 0; a < view.size(v); ++a) {
        values[v] = view.values[view.offset[v] + a];
        const std::int64_t cost = cost_here(con, largest);
        if (cost < 0) return "a weighted cost is not a non-negative integer";
        std::int64_t& cell = view.unary[view.offset[v] + a];
        cell = add_cost(cell, cost);
      }
    } else {
      WcspView::Edge& edge = view.edges[edge_of.at(ordered(scope[0], scope[1]))];
      const std::uint32_t dy = view.size(edge.y);
      for (std::uint32_t a = 0; a < view.size(edge.x); ++a) {
        values[edge.x] = view.values[view.offset[edge.x] + a];
        for (std::uint32_t b = 0; b < dy; ++b) {
          values[edge.y] = view.values[view.offset[edge.y] + b];
          const std::int64_t cost = cost_here(con, largest);
          if (cost < 0) return "a weighted cost is not a non-negative integer";
          std::int64_t& cell = edge.cost[std::size_t{a} * dy + b];
          cell = add_cost(cell, cost);
        }
      }
    }
    soft_total += largest;
    if (soft_total >= static_cast<double>(WcspView::kSoftCap))
      return "the soft costs are too large";
  }
  return "";
}

}  // namespace sightline::solvers::detail
