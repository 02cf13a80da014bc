#include "sightline/csp/kinds/not_equal.h"

#include <string>

namespace sightline::csp {
namespace {

// Nothing to remember: with two variables the current violation is one comparison away, so
// the state only answers in O(1) what a generic re-evaluation would answer in O(arity) too,
// but without writing into the assignment.
class NotEqualState : public IncrementalState {
 public:
  explicit NotEqualState(const NotEqual& c) : c_(c) {}

  double delta(std::span<const double> values, std::size_t position, double new_value) override {
    const double x = values[c_.scope()[0]];
    const double y = values[c_.scope()[1]];
    const double before = x == y + c_.offset() ? 1.0 : 0.0;
    const double after = position == 0 ? (new_value == y + c_.offset() ? 1.0 : 0.0)
                                       : (x == new_value + c_.offset() ? 1.0 : 0.0);
    return after - before;
  }
  void commit(std::span<const double>, std::size_t, double) override {}
  double involvement(std::span<const double> values, std::size_t) override {
    return c_.violation(values);
  }

 private:
  const NotEqual& c_;
};

}  // namespace

NotEqual::NotEqual(VariableId a, VariableId b, double offset, double weight, bool hard)
    : Constraint({a, b}, weight, hard), offset_(offset) {}

std::unique_ptr<IncrementalState> NotEqual::make_incremental_state(std::span<const double>) const {
  return std::make_unique<NotEqualState>(*this);
}

ConstraintKindInfo not_equal_kind() {
  return {"not_equal",
          "x != y + offset: violation 1 when equal (exact comparison)",
          {"offset"},
          [](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
            if (r.scope.size() != 2) {
              throw InputError(r.where, "not_equal needs exactly 2 variables in its scope, got " +
                                            std::to_string(r.scope.size()));
            }
            return std::make_unique<NotEqual>(r.scope[0], r.scope[1],
                                              r.params.number_or("offset", 0), r.weight, r.hard);
          },
          2, "offset: 1"};
}

}  // namespace sightline::csp
