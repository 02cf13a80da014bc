#include "sightline/csp/kinds/stretch.h"

#include <string>

#include "sightline/csp/input_error.h"

namespace sightline::csp {

double run_shortfall(std::size_t length, std::size_t min_length, std::size_t max_length) {
  double cost = 0;
  if (length < min_length) {
    cost += static_cast<double>(min_length - length) / static_cast<double>(min_length);
  }
  if (max_length > 0 && length > max_length) {
    cost += static_cast<double>(length - max_length) / static_cast<double>(max_length);
  }
  return cost;
}

StretchConstraint::StretchConstraint(std::vector<VariableId> scope, std::size_t min_length,
                                     double weight, bool hard, std::size_t max_length)
    : Constraint(std::move(scope), weight, hard),
      min_length_(min_length < 1 ? 1 : min_length),
      max_length_(max_length) {}

namespace {

// The shortfalls of the runs of positions [a, b] of the scope, with position `changed` read
// as `value` (changed outside [a, b]: none), the runs cut at a and b.
double runs_cost(std::span<const VariableId> scope, std::span<const double> values, std::size_t a,
                 std::size_t b, std::size_t changed, double value, std::size_t min_length,
                 std::size_t max_length) {
  auto at = [&](std::size_t i) { return i == changed ? value : values[scope[i]]; };
  double cost = 0;
  std::size_t start = a;
  for (std::size_t i = a + 1; i <= b + 1; ++i) {
    if (i == b + 1 || at(i) != at(i - 1)) {
      cost += run_shortfall(i - start, min_length, max_length);
      start = i;
    }
  }
  return cost;
}

// Positions [a, b] holding every run a change at `p` can touch: from the start of the run
// through p - 1 to the end of the run through p + 1 (runs beyond are closed at both ends
// before and after the change).
std::pair<std::size_t, std::size_t> window(std::span<const VariableId> scope,
                                           std::span<const double> values, std::size_t p) {
  std::size_t a = p == 0 ? 0 : p - 1;
  while (a > 0 && values[scope[a - 1]] == values[scope[a]]) --a;
  std::size_t b = p + 1 < scope.size() ? p + 1 : p;
  while (b + 1 < scope.size() && values[scope[b + 1]] == values[scope[b]]) ++b;
  return {a, b};
}

class StretchState : public IncrementalState {
 public:
  explicit StretchState(const StretchConstraint& c) : c_(&c) {}
  double delta(std::span<const double> values, std::size_t p, double new_value) override {
    const auto scope = c_->scope();
    const auto [a, b] = window(scope, values, p);
    const std::size_t none = scope.size();
    return runs_cost(scope, values, a, b, p, new_value, c_->min_length(), c_->max_length()) -
           runs_cost(scope, values, a, b, none, 0, c_->min_length(), c_->max_length());
  }
  void commit(std::span<const double>, std::size_t, double) override {}
  double involvement(std::span<const double> values, std::size_t p) override {
    const auto scope = c_->scope();
    std::size_t a = p, b = p;
    while (a > 0 && values[scope[a - 1]] == values[scope[p]]) --a;
    while (b + 1 < scope.size() && values[scope[b + 1]] == values[scope[p]]) ++b;
    return run_shortfall(b - a + 1, c_->min_length(), c_->max_length());
  }

 private:
  const StretchConstraint* c_;
};

}  // namespace

double StretchConstraint::violation(std::span<const double> values) const {
  const auto s = scope();
  if (s.empty()) return 0.0;
  return runs_cost(s, values, 0, s.size() - 1, s.size(), 0, min_length_, max_length_);
}

std::unique_ptr<IncrementalState> StretchConstraint::make_incremental_state(
    std::span<const double>) const {
  return std::make_unique<StretchState>(*this);
}

ConstraintKindInfo stretch_kind() {
  return {"stretch",
          "runs of equal values along the scope at least min (and at most max) long: sum of "
          "(min - length) / min over the shorter runs and (length - max) / max over the longer",
          {"min", "max"},
          [](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
            if (r.scope.empty()) throw InputError(r.where, "stretch needs at least 1 variable");
            const Spec& min = r.params.at("min");
            const long long m = min.as_integer("a whole number of variables, at least 1");
            if (m < 1) min.fail("stretch's min must be at least 1, got " + std::to_string(m));
            long long most = 0;
            if (const Spec* max = r.params.find("max"); max != nullptr) {
              most = max->as_integer("a whole number of variables, at least min");
              if (most < m) max->fail("stretch's max must be at least its min (" + std::to_string(m) + "), got " + std::to_string(most));
            }
            return std::make_unique<StretchConstraint>(r.scope, static_cast<std::size_t>(m),
                                                       r.weight, r.hard, static_cast<std::size_t>(most));
          },
          3, "min: 2"};
}

}  // namespace sightline::csp
