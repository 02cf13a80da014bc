// ValueSetConstraint: a unary constraint, a variable's value in (or out of) a set of values
// -- the `in` and `not_in` kinds, and `equals` (in a set of one).
//
// Violation 1 when the value breaks the rule, 0 otherwise (values compared exactly, as on
// integer and value-set domains). With weight w a soft one costs w: a preference for some
// values ("prefers the morning slots"), or, hard, a restriction of the domain that a model
// states where it means it.
//
// File forms: {kind: in, scope: [x], values: [1, 2, 5]}, {kind: not_in, scope: [x], values:
// [0]}, {kind: equals, scope: [x], value: 3}.
#pragma once

#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/csp/kinds/constraint_kinds.h"

namespace sightline::csp {

class ValueSetConstraint : public Constraint {
 public:
  // `inside`: the value must be one of `values` (in, equals), else none of them (not_in).
  ValueSetConstraint(VariableId x, std::vector<double> values, bool inside, const char* kind,
                     double weight = 1, bool hard = false);
  std::string_view kind() const override { return kind_; }
  double violation(std::span<const double> values) const override;
  const std::vector<double>& values() const { return values_; }
  bool inside() const { return inside_; }

 private:
  std::vector<double> values_;  // sorted
  bool inside_;
  const char* kind_;
};

// Registry entries: `in` and `not_in` (field `values`, a non-empty list of numbers) and
// `equals` (field `value`); the scope must hold exactly one variable.
ConstraintKindInfo in_kind();
ConstraintKindInfo not_in_kind();
ConstraintKindInfo equals_kind();

}  // namespace sightline::csp
