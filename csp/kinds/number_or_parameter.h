// NumberOrParameter: a constraint field that is either a fixed number or a named parameter.
//
// Re-parameterised problems (a target that moves every frame) must not be rebuilt, so a kind
// field such as `rhs: 10` may also be written `rhs: goal`, naming one of the problem's
// parameters; the constraint then reads the parameter's current value at every evaluation.
#pragma once

#include <string>

#include "sightline/csp/parameters.h"
#include "sightline/csp/spec.h"

namespace sightline::csp {

class NumberOrParameter {
 public:
  NumberOrParameter(double constant = 0) : constant_(constant) {}  // NOLINT: implicit on purpose
  explicit NumberOrParameter(ParameterRef parameter) : parameter_(parameter) {}

  // The current value: the constant, or the parameter's value right now.
  double value() const { return parameter_.valid() ? parameter_.value() : constant_; }
  bool is_parameter() const { return parameter_.valid(); }

  // Reads a field: a number, or the name of one of `parameters`. Throws InputError at the
  // field's location ("expected <what> or a parameter name (known parameters: ...)").
  static NumberOrParameter read(const Spec& field, const Parameters& parameters,
                                const std::string& what);
  // Same for an optional field of `entry`, with a default when absent.
  static NumberOrParameter read_or(const Spec& entry, const std::string& key,
                                   const Parameters& parameters, double fallback);

 private:
  double constant_ = 0;
  ParameterRef parameter_;
};

}  // namespace sightline::csp
