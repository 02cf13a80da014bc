// ExpressionConstraint: a constraint written as a formula, for the cases no kind covers.
//
// The formula is read by muparser over the scope's variable names and the problem's named
// parameters (read live, so a re-parameterised problem needs no rebuild). Its value is the
// violation, with negative values clamped to 0:
//     "x - 2"          x <= 2, violation the excess over 2
//     "x + y != 3"     comparisons are 0/1, so this is a 0/1 constraint
//     "abs(x - y)"     a deviation
//     "abs(_1 - _2)"   _1 .. _n name the scope's variables by position, so one formula
//                      serves every scope of a `scopes:` list
//     "idiv(x, 3) == idiv(y, 3)"   integer functions: floor, ceil, mod (sign of the
//                      divisor, as Python's %), idiv (floor of the quotient); min, max, abs
// A formula that is undefined somewhere (sqrt of a negative, 0/0, 1/0) yields NaN or +inf; that
// point counts as violated by kUndefinedViolation so that search moves away from it instead
// of poisoning every sum with NaN.
//
// The gradient is the base class's central finite differences (has_exact_gradient false).
// muparser parsers are not thread-safe and violation() is const, so each constraint owns one
// parser and the buffer it reads variables from: a problem is used by one thread at a time.
// An evaluation copies the scope's values and the used parameters into that buffer and runs
// muparser's bytecode; it allocates nothing.
//
// File form: {kind: expression, scope: [x, y], formula: "abs(x - y) - gap"}
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/parameters.h"

namespace sightline::csp {

class ExpressionConstraint : public Constraint {
 public:
  static constexpr double kUndefinedViolation = 1e9;

  // names[i] is how scope[i] is called in the formula. Every parameter of `parameters`
  // (may be null) whose name is a valid identifier can be used too. Throws
  // std::invalid_argument carrying muparser's message for a formula that does not parse or
  // names something unknown, or when a name is both a scope variable and a parameter.
  // `constants`: names the formula may use for fixed numbers (a problem file's value labels:
  // `r == A` with A the label of value 0); a name also a scope variable or a parameter is
  // refused.
  ExpressionConstraint(std::vector<VariableId> scope, std::vector<std::string> names,
                       std::string formula, const Parameters* parameters, double weight = 1,
                       bool hard = false,
                       const std::vector<std::pair<std::string, double>>& constants = {});
  ~ExpressionConstraint() override;

  std::string_view kind() const override { return "expression"; }
  const std::string& formula() const { return formula_; }

  double violation(std::span<const double> values) const override;

 private:
  struct Compiled;  // the muparser parser and its variable buffer
  std::string formula_;
  std::unique_ptr<Compiled> compiled_;
};

// Registry entry: field `formula` (required).
ConstraintKindInfo expression_kind();

}  // namespace sightline::csp
