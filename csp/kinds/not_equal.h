// NotEqual: the binary disequality x != y + offset, the workhorse of colouring problems.
//
// Violation is 1 when x == y + offset and 0 otherwise (a 0/1 constraint; with weight w a
// broken soft disequality costs w). Values are compared exactly, which is what integer and
// value-set domains need; on real variables equality almost never happens, so do not use it
// there. Its incremental state is O(1) per delta and per involvement.
//
// File form: {kind: not_equal, scope: [x, y], offset: 0}.
#pragma once

#include "sightline/csp/constraint.h"
#include "sightline/csp/kinds/constraint_kinds.h"

namespace sightline::csp {

class NotEqual : public Constraint {
 public:
  NotEqual(VariableId a, VariableId b, double offset = 0, double weight = 1, bool hard = false);

  std::string_view kind() const override { return "not_equal"; }
  double offset() const { return offset_; }

  double violation(std::span<const double> values) const override {
    return values[scope()[0]] == values[scope()[1]] + offset_ ? 1.0 : 0.0;
  }
  std::unique_ptr<IncrementalState> make_incremental_state(
      std::span<const double> values) const override;

 private:
  double offset_;
};

// Registry entry: fields `offset` (default 0); the scope must hold exactly two variables.
ConstraintKindInfo not_equal_kind();

}  // namespace sightline::csp
