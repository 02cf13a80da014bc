// LinearConstraint: sum_i a_i x_i OP rhs, with OP one of <=, =, >=.
//
// Violation is the amount by which the relation is broken:
//     <=  : max(0, s - rhs)        =  : |s - rhs|        >=  : max(0, rhs - s)
// where s = sum_i a_i x_i. It is incremental and exactly differentiable through LinearForm;
// at the boundary s == rhs the reported gradient is 0 (a subgradient). `rhs` may name a
// problem parameter, read at every evaluation.
//
// File form: {kind: linear, scope: [x, y], coefficients: [1, 2], op: "<=", rhs: 10}
// (quote ">=": a bare > starts a folded block in YAML; `le`, `eq`, `ge` are accepted too).
#pragma once

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/linear_form.h"
#include "sightline/csp/kinds/number_or_parameter.h"

namespace sightline::csp {

enum class Relation { kLessEqual, kEqual, kGreaterEqual };

class LinearConstraint : public LinearForm {
 public:
  LinearConstraint(std::vector<VariableId> scope, std::vector<double> coefficients,
                   Relation relation, NumberOrParameter rhs, double weight = 1, bool hard = false);

  std::string_view kind() const override { return "linear"; }
  Relation relation() const { return relation_; }
  double rhs() const { return rhs_.value(); }

  double violation_of_sum(double s) const override;
  double slope_at(double s) const override;
  // smooth_hinge of the excess for <= and >=, smooth_abs of it for =.
  double smooth_violation_of_sum(double s, double smoothing, double& slope) const override;
  double minimiser_of_sum() const override { return rhs_.value(); }

 private:
  Relation relation_;
  NumberOrParameter rhs_;
};

// Registry entry: fields `coefficients` (default all 1), `op` (required), `rhs` (default 0).
ConstraintKindInfo linear_kind();

}  // namespace sightline::csp
