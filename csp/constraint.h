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

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sightline/csp/score.h"

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
  virtual double delta(std::span<const double> values, std::size_t position, double new_value) = 0;
  // The variable at `position` is about to take `new_value`.
  virtual void commit(std::span<const double> values, std::size_t position, double new_value) = 0;
  // How much of the current violation the variable at `position` takes part in (0 when it is
  // in no conflict). Local search uses it to pick variables worth moving.
  virtual double involvement(std::span<const double> values, std::size_t position) = 0;
  // The violation of the assignment the state follows, for states that keep it up to date
  // anyway (it saves the owner a full evaluation when the state is built); nullopt otherwise.
  virtual std::optional<double> current_violation() const { return std::nullopt; }

  // Partial assignments (optional). Constructive starts build an assignment one variable at
  // a time and judge each choice against the variables already placed only (Sosic & Gu's
  // placement, stated for any constraint that can say it). A state that supports them can
  // retract a scope variable, which then no longer counts (the violation is that of the
  // rest of the scope), and place it back with a value. Only kinds whose violation means
  // something on part of the scope offer it (all_different: the repeats among the variables
  // present). While a variable is retracted, delta, commit and involvement are not called
  // for it. The defaults say "unsupported" and throw std::logic_error if called anyway.
  virtual bool supports_partial() const { return false; }
  // The variable at `position` (now at values[scope[position]]) stops counting; returns the
  // change in violation.
  virtual double retract(std::span<const double> values, std::size_t position);
  // Every scope variable (there are `arity`) stops counting at once; returns the change in
  // violation. The default retracts them one by one; kinds override it when clearing is
  // cheaper (all_different: zero the counts instead of a random decrement per variable).
  virtual double retract_all(std::span<const double> values, std::size_t arity);
  // Change in violation if the retracted variable at `position` came back at `new_value`.
  virtual double place_delta(std::span<const double> values, std::size_t position,
                             double new_value);
  // The retracted variable at `position` comes back at `new_value` (the owner then sets it
  // in the assignment).
  virtual void place(std::span<const double> values, std::size_t position, double new_value);
  // place() for a value the caller has found does not raise the violation (place_delta
  // <= 0); returns the change. The default is place_delta then place; kinds override it when
  // knowing this is cheaper (all_different: the key was free, so its count goes from 0 to 1,
  // which can wait until its next other call: meant for placing many variables in a row).
  virtual double place_free(std::span<const double> values, std::size_t position, double new_value);

  // A direct view of what place_delta tests (optional), for states whose place_delta is > 0
  // exactly when a key is occupied (all_different: some variable present has that key).
  // Placement tests millions of values; with the view IncrementalEvaluator reads one bit
  // instead of making a virtual call, and the bits (one per key) stay in cache where counts
  // would not. The retracted variable at `position` taking the integer value x would raise
  // the violation exactly when bit k = x + shift(position) of `occupied` is set (bit k % 64
  // of word k / 64); the shifts are 32-bit integers `stride` bytes apart from `shifts` on.
  // The view stays valid, and follows every update, while the state lives. The default
  // offers none.
  struct OccupiedKeys {
    const std::uint64_t* occupied = nullptr;  // nullptr: no view
    const unsigned char* shifts = nullptr;
    std::size_t stride = 0;
    bool is_occupied(std::size_t position, double value) const {
      std::int32_t shift;
      std::memcpy(&shift, shifts + position * stride, sizeof shift);
      const auto k = static_cast<std::uint64_t>(static_cast<std::int64_t>(value) + shift);
      return (occupied[k / 64] >> (k % 64)) & 1;
    }
  };
  virtual OccupiedKeys occupied_keys() const { return {}; }
};

// What a solver or a file writer may exploit in a constraint, asked of it (table_costs(),
// distinctness(), run_lengths()) instead of found by downcasting to a kind: explicit cost
// tables (the `table` kind), pairwise-distinct values (`all_different`) and runs of equal
// values (`stretch`). The default is none of them.
class TableCosts {
 public:
  virtual ~TableCosts() = default;
  virtual double default_cost() const = 0;  // of every tuple not listed
  virtual std::size_t num_tuples() const = 0;
  // Listed tuple i: its value at `position` (scope order), and its cost.
  virtual double tuple_value(std::size_t i, std::size_t position) const = 0;
  virtual double tuple_cost(std::size_t i) const = 0;
};

// Runs of equal values (the `stretch` kind): the violation is the sum, over the maximal runs
// of equal consecutive values along the scope, of max(0, min_length - length) / min_length
// plus, with max_length > 0, max(0, length - max_length) / max_length, so a sequence solver
// can count runs instead of evaluating the whole scope.
struct RunLengths {
  std::size_t min_length = 1;
  std::size_t max_length = 0;  // 0: no maximum
};

struct Distinctness {
  bool zero_offsets = true;      // values compared as they are (no per-variable offsets)
  bool counts_variables = true;  // violation = repeated variables (else: equal pairs)
  const char* measure_name = ""; // the measure's name in toulbar2's salldiff ("var", "dec")
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
  // The score of a violation of this constraint: weight x violation, hard or soft.
  Score score_of(double violation) const {
    const double weighted = weight_ * violation;
    return hard_ ? Score{weighted, 0} : Score{0, weighted};
  }
  // A human label ("height", "WA != NT"); empty means "kind + scope".
  const std::string& label() const { return label_; }
  void set_label(std::string label) { label_ = std::move(label); }

  // The registered kind name ("not_equal", "linear", "camera.height", ...).
  virtual std::string_view kind() const = 0;

  // Structure a solver may exploit (see TableCosts above): null / empty when none.
  virtual const TableCosts* table_costs() const { return nullptr; }
  virtual std::optional<Distinctness> distinctness() const { return std::nullopt; }
  virtual std::optional<RunLengths> run_lengths() const { return std::nullopt; }

  // 0 when satisfied, > 0 otherwise. `values` is the whole assignment, indexed by VariableId.
  virtual double violation(std::span<const double> values) const = 0;

  // For searches that drop a candidate as soon as its weighted sum reaches a bound: the
  // violation, or a lower bound v of it with (cost_before + weight() x v) + cost_after >=
  // bound, where cost_before is the sum before this term and cost_after the one term known
  // to come after it (0 when none). When it does not stop it must return exactly
  // violation(values), computed the same way, so a surviving candidate is scored to the
  // last bit as by violation(). Kinds whose violation counts many tests (sight lines) stop
  // counting once the candidate has lost. Default: violation(values).
  virtual double violation_until(std::span<const double> values, double cost_before,
                                 double bound, double cost_after) const;
  // How much one violation() costs, in queries of an outside world (a ray, a distance
  // query): 0 for arithmetic (the default). Searches ask the cheap ones first and the
  // costly ones in this order, so they stop before the costliest.
  virtual double query_cost() const { return 0; }

  // Incremental state for local search; nullptr means "no special support": callers then
  // re-evaluate violation() with the variable changed, which is correct but O(arity).
  virtual std::unique_ptr<IncrementalState> make_incremental_state(
      std::span<const double> values) const;

  // A lower bound on violation() over every completion of a partial assignment, for exact
  // solvers (bnb): `assigned[v]` (indexed by VariableId, like `values`) is non-zero for the
  // variables that hold their final value; the others' entries in `values` are meaningless.
  // The default is violation() when the whole scope is assigned and 0 otherwise, which is
  // always valid since violations are >= 0. Kinds that can say more override it (a table:
  // its cheapest tuple compatible with the assigned part); the tighter it is, the earlier
  // bnb prunes. It must never exceed the true minimum, and must not decrease as more of
  // the scope is assigned.
  virtual double min_violation(std::span<const double> values,
                               std::span<const std::uint8_t> assigned) const;

  // True when violation_and_gradient is exact (analytic or automatic differentiation).
  virtual bool has_exact_gradient() const { return false; }
  // Returns violation(values) and writes d violation / d values[scope()[i]] into gradient[i]
  // (gradient.size() == scope().size()). Default: central finite differences.
  virtual double violation_and_gradient(std::span<const double> values,
                                        std::span<double> gradient) const;
  // A continuously differentiable stand-in for the violation, and its gradient, for
  // gradient-based solvers (ceres-refine), which stall on kinks. `smoothing` > 0 is the width
  // of the rounded region, in the units of the quantity whose kink is rounded (the argument
  // of the abs or hinge: metres for a height deviation, degrees for an angle). Constraints
  // shaped like |r| or max(0, r) override this with smooth_abs / smooth_hinge below; the
  // smooth value must be 0 exactly where the violation is 0, so a smoothed optimum of a
  // satisfiable problem is still a true optimum. Default: violation_and_gradient (already
  // smooth, or nothing better known).
  virtual double smooth_violation_and_gradient(std::span<const double> values,
                                               std::span<double> gradient, double smoothing) const;

 private:
  std::vector<VariableId> scope_;
  double weight_;
  bool hard_;
  std::string label_;
};

// Smooth forms of the two kinks weighted CSPs are made of, shared by every constraint that
// overrides smooth_violation_and_gradient. Templates so they also take ceres::Jet (the
// unqualified sqrt finds Jet's through argument-dependent lookup). `s` > 0 is the width.
//
//   smooth_abs(r, s)   = sqrt(r^2 + s^2) - s          (pseudo-Huber: C-infinity, 0 only at
//                        r = 0, |r| - s <= value <= |r|, slope r / sqrt(r^2 + s^2))
//   smooth_hinge(r, s) = 0                 if r <= 0  (Huber-rounded max(0, r): C1, exactly 0
//                        r^2 / (2 s)       if 0 < r < s   on the satisfied side, value and
//                        r - s / 2         if r >= s      slope continuous at 0 and at s)
template <class T>
T smooth_abs(const T& r, double s) {
  using std::sqrt;
  return r * r / (sqrt(r * r + s * s) + s);  // = sqrt(r^2 + s^2) - s, without cancellation
}
template <class T>
T smooth_hinge(const T& r, double s) {
  if (r <= 0.0) return T(0.0);
  if (r < s) return r * r / (2 * s);
  return r - s / 2;
}
// Their derivatives, for constraints that write gradients by hand.
inline double smooth_abs_slope(double r, double s) {
  return r == 0 ? 0.0 : r / std::sqrt(r * r + s * s);
}
inline double smooth_hinge_slope(double r, double s) {
  return r <= 0 ? 0.0 : (r < s ? r / s : 1.0);
}

}  // namespace sightline::csp
