#include "sightline/csp/kinds/linear.h"

#include <algorithm>
#include <cmath>

#include "sightline/csp/problem.h"

namespace sightline::csp {

LinearConstraint::LinearConstraint(std::vector<VariableId> scope, std::vector<double> coefficients,
                                   Relation relation, NumberOrParameter rhs, double weight,
                                   bool hard)
    : LinearForm(std::move(scope), std::move(coefficients), weight, hard),
      relation_(relation),
      rhs_(rhs) {}

double LinearConstraint::violation_of_sum(double s) const {
  const double excess = s - rhs_.value();
  switch (relation_) {
    case Relation::kLessEqual:
      return std::max(0.0, excess);
    case Relation::kEqual:
      return std::abs(excess);
    case Relation::kGreaterEqual:
      return std::max(0.0, -excess);
  }
  return 0;
}

double LinearConstraint::slope_at(double s) const {
  const double excess = s - rhs_.value();
  switch (relation_) {
    case Relation::kLessEqual:
      return excess > 0 ? 1.0 : 0.0;
    case Relation::kEqual:
      return excess > 0 ? 1.0 : (excess < 0 ? -1.0 : 0.0);
    case Relation::kGreaterEqual:
      return excess < 0 ? -1.0 : 0.0;
  }
  return 0;
}

double LinearConstraint::smooth_violation_of_sum(double s, double smoothing, double& slope) const {
  const double excess = s - rhs_.value();
  switch (relation_) {
    case Relation::kLessEqual:
      slope = smooth_hinge_slope(excess, smoothing);
      return smooth_hinge(excess, smoothing);
    case Relation::kEqual:
      slope = smooth_abs_slope(excess, smoothing);
      return smooth_abs(excess, smoothing);
    case Relation::kGreaterEqual:  // max(0, -excess): the hinge mirrored
      slope = -smooth_hinge_slope(-excess, smoothing);
      return smooth_hinge(-excess, smoothing);
  }
  slope = 0;
  return 0;
}

namespace {

Relation read_relation(const Spec& field) {
  const std::string& op = field.as_string("a relation for 'op' (\"<=\", \"=\" or \">=\")");
  if (op == "<=" || op == "le") return Relation::kLessEqual;
  if (op == "=" || op == "==" || op == "eq") return Relation::kEqual;
  if (op == ">=" || op == "ge") return Relation::kGreaterEqual;
  field.fail("expected a relation for 'op': \"<=\", \"=\" or \">=\" (or le, eq, ge), got " +
             field.preview());
}

}  // namespace

ConstraintKindInfo linear_kind() {
  return {"linear",
          "sum_i a_i x_i OP rhs (OP <=, =, >=): violation is the amount it is broken by",
          {"coefficients", "op", "rhs"},
          [](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
            const Spec& e = r.params;
            auto c = std::make_unique<LinearConstraint>(
                r.scope, read_coefficients(e, r.scope.size()), read_relation(e.at("op")),
                NumberOrParameter::read_or(e, "rhs", r.problem.parameters(), 0), r.weight, r.hard);
            set_bounds_from_domains(*c, r.problem);
            return c;
          },
          3, "coefficients: [1, 2, -1], op: '<=', rhs: 2"};
}

}  // namespace sightline::csp
