#include "sightline/solvers/detail/permutation_groups.h"

#include <algorithm>

namespace sightline::solvers::detail {

namespace {

bool same_values(const csp::Domain& a, const csp::Domain& b) {
  if (&a == &b) return true;  // one domain shared by a batch of variables (add_variables)
  if (a.size() != b.size() || a.lower() != b.lower() || a.upper() != b.upper()) return false;
  if (a.kind() == csp::DomainKind::kIntegerRange && b.kind() == csp::DomainKind::kIntegerRange) {
    return true;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.value_at(i) != b.value_at(i)) return false;
  }
  return true;
}

// Per variable: does a hard unary constraint bear on it? One pass over the constraints, so
// that the usual variable, with none, costs pin() a single look-up.
std::vector<char> hard_unary_variables(const csp::Problem& problem) {
  std::vector<char> marked(problem.num_variables(), 0);
  for (csp::ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const csp::Constraint& c = problem.constraint(id);
    if (c.is_hard() && c.scope().size() == 1) marked[c.scope()[0]] = 1;
  }
  return marked;
}

// The values hard unary constraints allow `v` among `values` (`v` has at least one).
std::vector<double> allowed_values(const csp::Problem& problem, csp::VariableId v,
                                   const std::vector<double>& values, csp::Assignment& scratch) {
  std::vector<double> allowed;
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
void pin(const csp::Problem& problem, const std::vector<char>& hard_unary,
         PermutationGroup& group, csp::Assignment& scratch) {
  std::vector<char> value_pinned;  // made when the first pin is found
  bool consistent = true;
  for (csp::VariableId v : group.variables) {
    if (group.values.size() < 2) break;
    if (!hard_unary[v]) continue;  // the usual case: nothing can pin it
    if (value_pinned.empty()) value_pinned.assign(group.values.size(), 0);
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
  if (group.pinned.empty()) return;  // free_variables() and free_values() are the whole group
  std::fill(value_pinned.begin(), value_pinned.end(), 0);
  std::vector<char> variable_pinned(group.variables.size(), 0);
  for (const auto& [v, value] : group.pinned) {
    value_pinned[static_cast<std::size_t>(
        std::lower_bound(group.values.begin(), group.values.end(), value) -
        group.values.begin())] = 1;
    variable_pinned[static_cast<std::size_t>(
        std::find(group.variables.begin(), group.variables.end(), v) - group.variables.begin())] = 1;
  }
  group.unpinned_variables.reserve(group.variables.size() - group.pinned.size());
  group.unpinned_values.reserve(group.values.size() - group.pinned.size());
  for (std::size_t i = 0; i < group.variables.size(); ++i) {
    if (!variable_pinned[i]) group.unpinned_variables.push_back(group.variables[i]);
    if (!value_pinned[i]) group.unpinned_values.push_back(group.values[i]);
  }
}

}  // namespace

std::vector<PermutationGroup> find_permutation_groups(const csp::Problem& problem) {
  std::vector<PermutationGroup> groups;
  std::vector<char> taken(problem.num_variables(), 0);
  csp::Assignment scratch;  // filled by allowed_values when a hard unary constraint needs it
  std::vector<char> hard_unary;  // filled when the first group is found
  for (csp::ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const csp::Constraint& all_different = problem.constraint(id);
    const std::optional<csp::Distinctness> distinct = all_different.distinctness();
    if (!distinct || !all_different.is_hard() || !distinct->zero_offsets) continue;
    const auto scope = all_different.scope();
    if (scope.size() < 2) continue;
    const csp::Domain& first = problem.domain(scope[0]);
    if (!first.is_discrete() || first.size() != scope.size()) continue;
    bool fits = true;
    for (csp::VariableId v : scope) {
      if (taken[v] || !same_values(first, problem.domain(v))) {
        fits = false;
        break;
      }
    }
    if (!fits) continue;
    PermutationGroup group;
    group.constraint = id;
    group.variables = scope;
    group.values.resize(first.size());
    for (std::size_t i = 0; i < first.size(); ++i) group.values[i] = first.value_at(i);
    for (csp::VariableId v : scope) taken[v] = 1;
    if (!std::is_sorted(group.values.begin(), group.values.end())) {
      std::sort(group.values.begin(), group.values.end());
    }
    if (hard_unary.empty()) hard_unary = hard_unary_variables(problem);
    pin(problem, hard_unary, group, scratch);
    groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace sightline::solvers::detail
