// Constraint: the abstract unit of a weighted CSP.
//
// A constraint has a scope (the variables it reads), a weight, and is hard or soft. Its
// violation(values) is 0 when satisfied and grows with how badly it is violated. For a soft
// constraint the cost is weight x violation; a hard constraint with violation > 0 makes the
// assignment infeasible (its weighted violation still guides search toward feasibility).
//
// Two optional capabilities let solvers go faster without knowing the concrete kind:
//  - incremental evaluation: a per-search IncrementalState answers "how would the violation
//    change if this one variable took that value" in (ideally) O(1), which is what makes
//    local search on 1,000,000-queens practical;
//  - differentiation: the gradient of the violation with respect to the scope, used by
//    continuous solvers (Ceres). The default is central finite differences.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sightline::csp {

using VariableId = std::uint32_t;
using ConstraintId = std::uint32_t;

// Incremental evaluation state of one constraint during one search. Created from the current
// assignment by Constraint::make_incremental_state; the owner calls commit() every time one
// of the scope's variables changes (before the assignment itself is updated).
class IncrementalState {
 public:
  virtual ~IncrementalState() = default;
  // Change in violation if the variable at `position` in the scope took `new_value`.
  // `values` is the whole current assignment, indexed by VariableId.
  virtual double delta(std::span<const double> values, std::size_t position,
                       double new_value) = 0;
  // The variable at `position` is about to take `new_value`.
  virtual void commit(std::span<const double> values, std::size_t position,
                      double new_value) = 0;
  // How much of the current violation the variable at `position` takes part in (0 when it is
  // in no conflict). Local search uses it to pick variables worth moving.
  virtual double involvement(std::span<const double> values, std::size_t position) = 0;
};

class Constraint {
 public:
  explicit Constraint(std::vector<VariableId> scope, double weight = 1.0, bool hard = false);
  virtual ~Constraint();
  Constraint(const Constraint&) = delete;
  Constraint& operator=(const Constraint&) = delete;

  std::span<const VariableId> scope() const { return scope_; }
  double weight() const { return weight_; }
  void set_weight(double weight) { weight_ = weight; }
  bool is_hard() const { return hard_; }
  void set_hard(bool hard) { hard_ = hard; }
  // A human label ("height", "WA != NT"); empty means "kind + scope".
  const std::string& label() const { return label_; }
  void set_label(std::string label) { label_ = std::move(label); }

  // The registered kind name ("not_equal", "linear", "camera.height", ...).
  virtual std::string_view kind() const = 0;

  // 0 when satisfied, > 0 otherwise. `values` is the whole assignment, indexed by VariableId.
  virtual double violation(std::span<const double> values) const = 0;

  // Incremental state for local search; nullptr means "no special support": callers then
  // re-evaluate violation() with the variable changed, which is correct but O(arity).
  virtual std::unique_ptr<IncrementalState> make_incremental_state(
      std::span<const double> values) const;

  // True when violation_and_gradient is exact (analytic or automatic differentiation).
  virtual bool has_exact_gradient() const { return false; }
  // Returns violation(values) and writes d violation / d values[scope()[i]] into gradient[i]
  // (gradient.size() == scope().size()). Default: central finite differences.
  virtual double violation_and_gradient(std::span<const double> values,
                                        std::span<double> gradient) const;

  // Kind and scope as text, for reports: "not_equal(x0, x3)".
  std::string describe() const;

 private:
  std::vector<VariableId> scope_;
  double weight_;
  bool hard_;
  std::string label_;
};

}  // namespace sightline::csp
