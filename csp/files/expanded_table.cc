#include "sightline/csp/files/expanded_table.h"

#include <sstream>
#include <stdexcept>

namespace sightline::csp {

std::vector<double> expand_violations(const Problem& problem, ConstraintId id, const char* format) {
  const Constraint& c = problem.constraint(id);
  const auto scope = c.scope();
  double count = 1;
  for (VariableId v : scope) {
    if (!problem.domain(v).is_discrete()) {
      throw std::invalid_argument("cannot write " + problem.constraint_name(id) + " to " + format + ": variable " +
                                  problem.variable_name(v) + " is continuous");
    }
    count *= static_cast<double>(problem.domain(v).size());
  }
  if (count > static_cast<double>(kMaxExpandedTuples)) {
    std::ostringstream message;
    message << "cannot write " << problem.constraint_name(id) << " to " << format << ": as a cost table it has "
            << count << " tuples, more than the " << kMaxExpandedTuples
            << " a constraint may expand to";
    throw std::invalid_argument(message.str());
  }
  std::vector<double> violations;
  violations.reserve(static_cast<std::size_t>(count));
  std::vector<double> values(problem.num_variables());
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    values[v] = problem.domain(v).is_discrete() ? problem.domain(v).value_at(0) : problem.domain(v).lower();
  }
  std::vector<std::size_t> digit(scope.size(), 0);
  while (true) {
    violations.push_back(c.violation(values));
    std::size_t p = scope.size();
    while (p > 0) {
      --p;
      const Domain& d = problem.domain(scope[p]);
      if (++digit[p] < d.size()) {
        values[scope[p]] = d.value_at(digit[p]);
        break;
      }
      digit[p] = 0;
      values[scope[p]] = d.value_at(0);
      if (p == 0) return violations;
    }
    if (scope.empty()) return violations;
  }
}

}  // namespace sightline::csp
