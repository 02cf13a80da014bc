#include "solvers/detail/permutation_groups.h"

#include <algorithm>

#include "csp/kinds/all_different.h"

namespace sightline::solvers::detail {

namespace {

bool same_values(const csp::Domain& a, const csp::Domain& b) {
  if (a.size() != b.size() || a.lower() != b.lower() || a.upper() != b.upper()) return false;
  if (a.kind() == csp::DomainKind::kIntegerRange && b.kind() == csp::DomainKind::kIntegerRange) {
    return true;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.value_at(i) != b.value_at(i)) return false;
  }
  return true;
}

// The values hard unary constraints allow `v` among `values`; empty when `v` has no hard
// unary constraint (pin() only looks for a single allowed value).
std::vector<double> allowed_values(const csp::Problem& problem, csp::VariableId v,
                                   const std::vector<double>& values, csp::Assignment& scratch) {
  std::vector<double> allowed;
  const auto incidences = problem.incidences(v);
  const bool has_unary = std::any_of(incidences.begin(), incidences.end(), [&](const auto& i) {
    const csp::Constraint& c = problem.constraint(i.constraint);
    return c.is_hard() && c.scope().size() == 1;
  });
  if (!has_unary) return allowed;  // cheap answer for the usual case; pin() needs size 1 only
  if (scratch.empty()) scratch = problem.default_assignment();  // first time it is needed
  const double kept = scratch[v];
  for (double value : values) {
    scratch[v] = value;
    bool ok = true;
    for (const auto& incidence : problem.incidences(v)) {
      const csp::Constraint& c = problem.constraint(incidence.constraint);
      if (c.is_hard() && c.scope().size() == 1 && c.violation(scratch) > 0) {
        ok = false;
        break;
      }
    }
    if (ok) allowed.push_back(value);
  }
  scratch[v] = kept;
  return allowed;
}

// Pins the group's variables that hard unary constraints allow a single value, and lists
// the rest as free (see the header). No pins at all when two would share a value.
void pin(const csp::Problem& problem, PermutationGroup& group, csp::Assignment& scratch) {
  std::vector<char> value_pinned(group.values.size(), 0);
  bool consistent = true;
  for (csp::VariableId v : group.variables) {
    if (group.values.size() < 2) break;
    const std::vector<double> allowed = allowed_values(problem, v, group.values, scratch);
    if (allowed.size() != 1) continue;
    const auto k = static_cast<std::size_t>(
        std::lower_bound(group.values.begin(), group.values.end(), allowed[0]) -
        group.values.begin());
    if (value_pinned[k]) consistent = false;
    value_pinned[k] = 1;
    group.pinned.emplace_back(v, allowed[0]);
  }
  if (!consistent) group.pinned.clear();
  std::fill(value_pinned.begin(), value_pinned.end(), 0);
  std::vector<char> variable_pinned(group.variables.size(), 0);
  for (const auto& [v, value] : group.pinned) {
    value_pinned[static_cast<std::size_t>(
        std::lower_bound(group.values.begin(), group.values.end(), value) -
        group.values.begin())] = 1;
    variable_pinned[static_cast<std::size_t>(
        std::find(group.variables.begin(), group.variables.end(), v) - group.variables.begin())] = 1;
  }
  for (std::size_t i = 0; i < group.variables.size(); ++i) {
    if (!variable_pinned[i]) group.free.push_back(group.variables[i]);
    if (!value_pinned[i]) group.free_values.push_back(group.values[i]);
  }
}

}  // namespace

std::vector<PermutationGroup> find_permutation_groups(const csp::Problem& problem) {
  std::vector<PermutationGroup> groups;
  std::vector<char> taken(problem.num_variables(), 0);
  csp::Assignment scratch;  // filled by allowed_values when a hard unary constraint needs it
  for (csp::ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const auto* all_different = dynamic_cast<const csp::AllDifferent*>(&problem.constraint(id));
    if (!all_different || !all_different->is_hard() || !all_different->has_zero_offsets()) {
      continue;
    }
    const auto scope = all_different->scope();
    if (scope.size() < 2) continue;
    const csp::Domain& first = problem.variable(scope[0]).domain;
    if (!first.is_discrete() || first.size() != scope.size()) continue;
    bool fits = true;
    for (csp::VariableId v : scope) {
      if (taken[v] || !same_values(first, problem.variable(v).domain)) {
        fits = false;
        break;
      }
    }
    if (!fits) continue;
    PermutationGroup group;
    group.constraint = id;
    group.variables.assign(scope.begin(), scope.end());
    group.values.resize(first.size());
    for (std::size_t i = 0; i < first.size(); ++i) group.values[i] = first.value_at(i);
    for (csp::VariableId v : scope) taken[v] = 1;
    if (!std::is_sorted(group.values.begin(), group.values.end())) {
      std::sort(group.values.begin(), group.values.end());
    }
    pin(problem, group, scratch);
    groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace sightline::solvers::detail
