#include "sightline/csp/kinds/value_set.h"

#include <algorithm>
#include <string>

#include "sightline/csp/input_error.h"

namespace sightline::csp {

ValueSetConstraint::ValueSetConstraint(VariableId x, std::vector<double> values, bool inside,
                                       const char* kind, double weight, bool hard)
    : Constraint({x}, weight, hard), values_(std::move(values)), inside_(inside), kind_(kind) {
  std::sort(values_.begin(), values_.end());
}

double ValueSetConstraint::violation(std::span<const double> values) const {
  const bool member = std::binary_search(values_.begin(), values_.end(), values[scope()[0]]);
  return member == inside_ ? 0.0 : 1.0;
}

namespace {

void check_unary(const ConstraintRequest& r, const char* kind) {
  if (r.scope.size() != 1) {
    throw InputError(r.where, std::string(kind) + " needs exactly 1 variable in its scope, got " +
                                  std::to_string(r.scope.size()));
  }
}

ConstraintKindInfo set_kind(const char* name, const char* description, bool inside,
                            const char* example) {
  return {name, description, {"values"},
          [name, inside](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
            check_unary(r, name);
            const Spec& list = r.params.at("values");
            std::vector<double> values = list.as_numbers("a list of values");
            if (values.empty()) list.fail(std::string(name) + " needs at least one value");
            return std::make_unique<ValueSetConstraint>(r.scope[0], std::move(values), inside, name,
                                                        r.weight, r.hard);
          },
          1, example};
}

}  // namespace

ConstraintKindInfo in_kind() {
  return set_kind("in", "x in {values}: violation 1 when x is none of them", true, "values: [0, 2]");
}

ConstraintKindInfo not_in_kind() {
  return set_kind("not_in", "x not in {values}: violation 1 when x is one of them", false,
                  "values: [1]");
}

ConstraintKindInfo equals_kind() {
  return {"equals", "x == value: violation 1 when it differs (exact comparison)", {"value"},
          [](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
            check_unary(r, "equals");
            return std::make_unique<ValueSetConstraint>(
                r.scope[0], std::vector<double>{r.params.at("value").as_number("a value")}, true,
                "equals", r.weight, r.hard);
          },
          1, "value: 1"};
}

}  // namespace sightline::csp
