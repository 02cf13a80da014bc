#include "sightline/csp/kinds/abs_deviation.h"

#include <cmath>

#include "sightline/csp/problem.h"

namespace sightline::csp {

AbsDeviation::AbsDeviation(std::vector<VariableId> scope, std::vector<double> coefficients,
                           double constant, NumberOrParameter target, double weight, bool hard)
    : LinearForm(std::move(scope), std::move(coefficients), weight, hard),
      constant_(constant),
      target_(target) {}

double AbsDeviation::violation_of_sum(double s) const {
  return std::abs(s + constant_ - target_.value());
}

double AbsDeviation::slope_at(double s) const {
  const double d = s + constant_ - target_.value();
  return d > 0 ? 1.0 : (d < 0 ? -1.0 : 0.0);
}

double AbsDeviation::smooth_violation_of_sum(double s, double smoothing, double& slope) const {
  const double d = s + constant_ - target_.value();
  slope = smooth_abs_slope(d, smoothing);
  return smooth_abs(d, smoothing);
}

ConstraintKindInfo abs_deviation_kind() {
  return {"abs_deviation",
          "|sum_i a_i x_i + constant - target|: distance of a weighted sum to a target",
          {"coefficients", "constant", "target"},
          [](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
            const Spec& e = r.params;
            auto c = std::make_unique<AbsDeviation>(
                r.scope, read_coefficients(e, r.scope.size()), e.number_or("constant", 0),
                NumberOrParameter::read_or(e, "target", r.problem.parameters(), 0), r.weight,
                r.hard);
            set_bounds_from_domains(*c, r.problem);
            return c;
          },
          2, "coefficients: [1, -1], target: 1"};
}

}  // namespace sightline::csp
