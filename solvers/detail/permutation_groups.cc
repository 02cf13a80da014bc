#include "solvers/detail/permutation_groups.h"

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

}  // namespace

std::vector<PermutationGroup> find_permutation_groups(const csp::Problem& problem) {
  std::vector<PermutationGroup> groups;
  std::vector<char> taken(problem.num_variables(), 0);
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
    group.variables.assign(scope.begin(), scope.end());
    group.values.resize(first.size());
    for (std::size_t i = 0; i < first.size(); ++i) group.values[i] = first.value_at(i);
    for (csp::VariableId v : scope) taken[v] = 1;
    groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace sightline::solvers::detail
