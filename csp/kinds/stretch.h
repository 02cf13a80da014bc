// StretchConstraint (`stretch`): every run of equal values along a sequence of variables is at
// least `min` long -- a shot held for at least two seconds, a shift worked for at least three
// days (Pesant's stretch constraint, soft).
//
// Violation: the sum, over the maximal runs of equal consecutive values along the scope (in
// scope order, the first and the last run included), of max(0, min - length) / min, and,
// with `max`, of max(0, length - max) / max. So one run a single variable long costs
// (min - 1) / min, a run twice the maximum costs 1, and a sequence whose runs all lie within
// [min, max] costs 0. It says so through run_lengths(), which lets a sequence solver (`chain`)
// count runs instead of evaluating the scope; local search moves it incrementally.
//
// File form: {kind: stretch, scope: [x0, x1, ..., xn], min: 8} (max: 32 optional).
#pragma once

#include "sightline/csp/constraint.h"
#include "sightline/csp/kinds/constraint_kinds.h"

namespace sightline::csp {

class StretchConstraint : public Constraint {
 public:
  // min_length >= 1; max_length 0 (none) or >= min_length.
  StretchConstraint(std::vector<VariableId> scope, std::size_t min_length, double weight = 1,
                    bool hard = false, std::size_t max_length = 0);
  std::string_view kind() const override { return "stretch"; }
  std::optional<RunLengths> run_lengths() const override { return RunLengths{min_length_, max_length_}; }
  double violation(std::span<const double> values) const override;
  std::unique_ptr<IncrementalState> make_incremental_state(
      std::span<const double> values) const override;
  std::size_t min_length() const { return min_length_; }
  std::size_t max_length() const { return max_length_; }

 private:
  std::size_t min_length_, max_length_;
};

// The cost of one run of `length`: max(0, min - length) / min, plus max(0, length - max) / max
// when max > 0.
double run_shortfall(std::size_t length, std::size_t min_length, std::size_t max_length = 0);

// Registry entry: `stretch`, field `min` (a whole number >= 1), optional `max` (>= min),
// scope of 1 or more variables.
ConstraintKindInfo stretch_kind();

}  // namespace sightline::csp
