// AbsDeviation: |sum_i a_i x_i + constant - target|, a soft "be close to" constraint.
//
// The violation is the distance from the weighted sum to its target, so a weight w makes it
// cost w per unit of deviation (an L1 penalty: robust, and exact for "as close as possible"
// goals such as a camera's preferred distance). Incremental and exactly differentiable
// through LinearForm; at zero deviation the gradient reported is 0 (a subgradient). `target`
// may name a problem parameter, read at every evaluation.
//
// File form: {kind: abs_deviation, scope: [x, y], coefficients: [1, -1], constant: 0, target: 2}
#pragma once

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/linear_form.h"
#include "sightline/csp/kinds/number_or_parameter.h"

namespace sightline::csp {

class AbsDeviation : public LinearForm {
 public:
  AbsDeviation(std::vector<VariableId> scope, std::vector<double> coefficients, double constant,
               NumberOrParameter target, double weight = 1, bool hard = false);

  std::string_view kind() const override { return "abs_deviation"; }
  double constant() const { return constant_; }
  double target() const { return target_.value(); }

  // |s + constant - target|, and its slope sign(s + constant - target) (0 at the kink).
  double violation_of_sum(double s) const override;
  double slope_at(double s) const override;
  // smooth_abs of the deviation.
  double smooth_violation_of_sum(double s, double smoothing, double& slope) const override;
  double minimiser_of_sum() const override { return target_.value() - constant_; }

 private:
  double constant_;
  NumberOrParameter target_;
};

// Registry entry: fields `coefficients` (default all 1), `constant` (default 0),
// `target` (default 0).
ConstraintKindInfo abs_deviation_kind();

}  // namespace sightline::csp
