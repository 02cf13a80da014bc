#include "csp/problem.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace sightline::csp {

VariableId Problem::add_variable(std::string name, Domain domain) {
  if (name.empty()) throw std::invalid_argument("a variable needs a name");
  const auto id = static_cast<VariableId>(variables_.size());
  index_names();
  if (!variable_ids_.emplace(name, id).second) {
    throw std::invalid_argument("variable '" + name + "' is defined twice");
  }
  variables_.push_back({std::move(name), std::move(domain)});
  incidence_.emplace_back();
  indexed_ = variables_.size();
  return id;
}

namespace {

// Whether `name` is `prefix` followed by a decimal number below `count` without leading
// zeros: one of the names add_variables(prefix, count) makes.
bool is_generated_name(std::string_view name, std::string_view prefix, std::size_t count) {
  if (name.size() <= prefix.size() || name.substr(0, prefix.size()) != prefix) return false;
  const std::string_view digits = name.substr(prefix.size());
  if (digits.size() > 1 && digits[0] == '0') return false;
  std::size_t value = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return false;
    if (value > (count / 10) + 1) return false;  // already too large, and no overflow
    value = value * 10 + static_cast<std::size_t>(c - '0');
  }
  return value < count;
}

}  // namespace

VariableId Problem::add_variables(std::string_view prefix, std::size_t count,
                                  const Domain& domain) {
  if (prefix.empty()) throw std::invalid_argument("generated variable names need a prefix");
  for (const Variable& v : variables_) {
    if (is_generated_name(v.name, prefix, count)) {
      throw std::invalid_argument("variable '" + v.name + "' is defined twice");
    }
  }
  const auto first = static_cast<VariableId>(variables_.size());
  variables_.reserve(variables_.size() + count);
  incidence_.reserve(incidence_.size() + count);
  // One buffer for the names: prefix, then the digits rewritten in place (short names stay
  // in std::string's small-string buffer, so no heap allocation per variable).
  std::string name(prefix);
  char digits[24];
  for (std::size_t i = 0; i < count; ++i) {
    const auto [end, error] = std::to_chars(digits, digits + sizeof digits, i);
    (void)error;
    name.resize(prefix.size());
    name.append(digits, end);
    variables_.push_back({name, domain});
    incidence_.emplace_back();
  }
  return first;
}

void Problem::index_names() const {
  std::lock_guard<std::mutex> lock(index_mutex_);
  if (indexed_ == variables_.size()) return;
  variable_ids_.reserve(variables_.size());
  for (std::size_t i = indexed_; i < variables_.size(); ++i) {
    // add_variables checked these names against the others: none is a duplicate.
    variable_ids_.emplace(variables_[i].name, static_cast<VariableId>(i));
  }
  indexed_ = variables_.size();
}

ConstraintId Problem::add_constraint(std::unique_ptr<Constraint> constraint) {
  const auto scope = constraint->scope();
  if (scope.empty()) throw std::invalid_argument("a constraint needs at least one variable");
  for (VariableId v : scope) {
    if (v >= variables_.size()) {
      throw std::invalid_argument("constraint scope names variable id " + std::to_string(v) +
                                  " but the problem has " + std::to_string(variables_.size()));
    }
  }
  // Repeated variables would make one-variable deltas wrong; refuse them. A scope that
  // covers a good part of the variables (N-queens' all_differents: all of a million) is
  // checked with one mark per variable, in linear time; a small one by sorting a copy.
  auto repeated = [&](VariableId v) {
    throw std::invalid_argument("variable '" + variables_[v].name +
                                "' appears twice in one constraint's scope");
  };
  if (scope.size() * 8 >= variables_.size()) {
    std::vector<char> seen(variables_.size(), 0);
    for (VariableId v : scope) {
      if (seen[v]) repeated(v);
      seen[v] = 1;
    }
  } else {
    std::vector<VariableId> sorted(scope.begin(), scope.end());
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1; i < sorted.size(); ++i) {
      if (sorted[i] == sorted[i - 1]) repeated(sorted[i]);
    }
  }
  const auto id = static_cast<ConstraintId>(constraints_.size());
  for (std::size_t i = 0; i < scope.size(); ++i) {
    std::vector<Incidence>& list = incidence_[scope[i]];
    // Three entries take one 32-byte heap block, the smallest glibc gives anyway: one
    // allocation instead of three for a variable in up to three constraints (N-queens).
    if (list.capacity() == 0) list.reserve(3);
    list.push_back({id, static_cast<std::uint32_t>(i)});
  }
  constraints_.push_back(std::move(constraint));
  return id;
}

std::optional<VariableId> Problem::find_variable(std::string_view name) const {
  index_names();
  std::lock_guard<std::mutex> lock(index_mutex_);
  auto it = variable_ids_.find(std::string(name));
  if (it == variable_ids_.end()) return std::nullopt;
  return it->second;
}

bool Problem::all_discrete() const {
  for (const auto& v : variables_) {
    if (!v.domain.is_discrete()) return false;
  }
  return true;
}

bool Problem::all_continuous() const {
  for (const auto& v : variables_) {
    if (!v.domain.is_continuous()) return false;
  }
  return true;
}

Score Problem::constraint_score(ConstraintId id, std::span<const double> values) const {
  const Constraint& c = *constraints_[id];
  const double weighted = c.weight() * c.violation(values);
  return c.is_hard() ? Score{weighted, 0} : Score{0, weighted};
}

Score Problem::score(std::span<const double> values) const {
  Score total;
  for (ConstraintId id = 0; id < constraints_.size(); ++id) total += constraint_score(id, values);
  return total;
}

std::vector<ConstraintCost> Problem::breakdown(std::span<const double> values) const {
  std::vector<ConstraintCost> out;
  out.reserve(constraints_.size());
  for (ConstraintId id = 0; id < constraints_.size(); ++id) {
    const Constraint& c = *constraints_[id];
    const double v = c.violation(values);
    out.push_back({id, v, c.weight() * v, c.is_hard()});
  }
  return out;
}

Score Problem::delta(std::span<double> values, VariableId var, double new_value) const {
  Score before, after;
  for (const Incidence& inc : incidence_[var]) before += constraint_score(inc.constraint, values);
  const double old_value = values[var];
  values[var] = new_value;
  for (const Incidence& inc : incidence_[var]) after += constraint_score(inc.constraint, values);
  values[var] = old_value;
  return after - before;
}

Assignment Problem::default_assignment() const {
  Assignment a(variables_.size());
  for (std::size_t i = 0; i < variables_.size(); ++i) a[i] = variables_[i].domain.middle();
  return a;
}

void Problem::check_assignment(std::span<const double> values) const {
  if (values.size() != variables_.size()) {
    throw std::invalid_argument("assignment has " + std::to_string(values.size()) +
                                " values but the problem has " +
                                std::to_string(variables_.size()) + " variables");
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isnan(values[i]) || !variables_[i].domain.contains(values[i])) {
      throw std::invalid_argument("value " + std::to_string(values[i]) + " of variable '" +
                                  variables_[i].name + "' is outside its domain " +
                                  variables_[i].domain.describe());
    }
  }
}

}  // namespace sightline::csp
