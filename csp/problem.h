// Problem: a weighted CSP instance: variables with domains, constraints, parameters, and the
// variable -> constraint index that keeps every one-variable delta O(constraints touching it).
//
// The Problem owns its constraints. It evaluates whole assignments (Score, per-constraint
// breakdown, feasibility) and one-variable changes; solvers that move one variable at a time
// should use IncrementalEvaluator, which adds per-constraint incremental state on top.
// Values are indexed by VariableId; see Assignment.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "csp/constraint.h"
#include "csp/domain.h"
#include "csp/parameters.h"
#include "csp/score.h"

namespace sightline::csp {

using Assignment = std::vector<double>;

struct Variable {
  std::string name;
  Domain domain;
};

// One entry of the variable -> constraint index: the constraint, and where the variable sits
// in its scope (so incremental states can be addressed in O(1)).
struct Incidence {
  ConstraintId constraint;
  std::uint32_t position;
};

struct ConstraintCost {
  ConstraintId id;
  double violation;  // raw violation (0 = satisfied)
  double cost;       // weight x violation
  bool hard;
};

class Problem {
 public:
  explicit Problem(std::string name = "problem") : name_(std::move(name)) {}
  Problem(const Problem&) = delete;
  Problem& operator=(const Problem&) = delete;

  const std::string& name() const { return name_; }
  void set_name(std::string name) { name_ = std::move(name); }

  // Adds a variable; throws std::invalid_argument on an empty or duplicate name.
  VariableId add_variable(std::string name, Domain domain);
  // Adds `count` variables named prefix0 .. prefix<count-1> (decimal, no leading zeros),
  // each with `domain`, and returns the first one's id (the others follow in order). The
  // same as as many add_variable calls, but without a name-index insert per variable: a
  // model of a million variables (1,000,000-queens) would spend more on the index than on
  // its solve. The index catches up when a name is looked up or a variable added one at a
  // time. Throws std::invalid_argument on an empty prefix, or when an existing name has
  // that form (it would be defined twice).
  VariableId add_variables(std::string_view prefix, std::size_t count, const Domain& domain);
  // Adds a constraint; throws std::invalid_argument if its scope names an unknown variable,
  // repeats a variable, or is empty. Returns its id (ids are dense, in order of addition).
  ConstraintId add_constraint(std::unique_ptr<Constraint> constraint);

  std::size_t num_variables() const { return variables_.size(); }
  std::size_t num_constraints() const { return constraints_.size(); }
  const Variable& variable(VariableId id) const { return variables_[id]; }
  const std::vector<Variable>& variables() const { return variables_; }
  std::optional<VariableId> find_variable(std::string_view name) const;
  // Re-parameterisation: replaces a variable's domain (the camera's search box moves with the
  // character every frame). Constraints and the index are untouched.
  void set_domain(VariableId id, Domain domain) { variables_[id].domain = std::move(domain); }
  const Constraint& constraint(ConstraintId id) const { return *constraints_[id]; }
  Constraint& mutable_constraint(ConstraintId id) { return *constraints_[id]; }
  std::span<const Incidence> incidences(VariableId id) const { return incidence_[id]; }

  Parameters& parameters() { return parameters_; }
  const Parameters& parameters() const { return parameters_; }

  bool all_discrete() const;
  bool all_continuous() const;

  // Weighted score of a whole assignment (values.size() == num_variables()).
  Score score(std::span<const double> values) const;
  double cost(std::span<const double> values) const { return score(values).soft; }
  bool is_feasible(std::span<const double> values) const { return score(values).feasible(); }
  // Every constraint's violation and weighted cost, in id order.
  std::vector<ConstraintCost> breakdown(std::span<const double> values) const;
  // Weighted score contribution of one constraint.
  Score constraint_score(ConstraintId id, std::span<const double> values) const;
  // Score change if `var` took `new_value`; O(constraints touching var). `values` is
  // modified during the call and restored before it returns.
  Score delta(std::span<double> values, VariableId var, double new_value) const;

  // A start assignment: each domain's middle value.
  Assignment default_assignment() const;
  // Throws std::invalid_argument naming the first variable whose value is missing, NaN or
  // outside its domain.
  void check_assignment(std::span<const double> values) const;

 private:
  std::string name_;
  std::vector<Variable> variables_;
  // Brings the name index up to date (the names of add_variables batches are indexed late).
  void index_names() const;

  // name -> id, O(1) lookups, for variables_[0 .. indexed_). Built lazily (see add_variables)
  // under a lock, so that concurrent lookups (queries are thread-safe) may trigger it.
  mutable std::unordered_map<std::string, VariableId> variable_ids_;
  mutable std::size_t indexed_ = 0;
  mutable std::mutex index_mutex_;
  std::vector<std::unique_ptr<Constraint>> constraints_;
  std::vector<std::vector<Incidence>> incidence_;
  Parameters parameters_;
};

}  // namespace sightline::csp
