#include "sightline/solvers/detail/conditioned_problem.h"

#include <string>

namespace sightline::solvers::detail {

namespace {

// One constraint of the original problem seen on its free variables only.
class ConditionedConstraint : public csp::Constraint {
 public:
  ConditionedConstraint(const csp::Constraint& original, std::vector<csp::VariableId> sub_scope,
                        std::vector<csp::VariableId> original_ids,
                        std::shared_ptr<ConditionedProblem::Scratch> scratch)
      : Constraint(std::move(sub_scope), original.weight(), original.is_hard()),
        original_(original),
        original_ids_(std::move(original_ids)),
        scratch_(std::move(scratch)) {
    set_label(original.label());
  }

  std::string_view kind() const override { return original_.kind(); }

  double violation(std::span<const double> values) const override {
    write(values);
    return original_.violation(scratch_->values);
  }

  double min_violation(std::span<const double> values,
                       std::span<const std::uint8_t> assigned) const override {
    write(values);
    const auto sub_scope = scope();
    for (std::size_t i = 0; i < sub_scope.size(); ++i) {
      scratch_->assigned[original_ids_[i]] = assigned[sub_scope[i]];
    }
    return original_.min_violation(scratch_->values, scratch_->assigned);
  }

 private:
  void write(std::span<const double> values) const {
    const auto sub_scope = scope();
    for (std::size_t i = 0; i < sub_scope.size(); ++i) {
      scratch_->values[original_ids_[i]] = values[sub_scope[i]];
    }
  }

  const csp::Constraint& original_;
  std::vector<csp::VariableId> original_ids_;  // per position of the sub-scope
  std::shared_ptr<ConditionedProblem::Scratch> scratch_;
};

}  // namespace

ConditionedProblem::ConditionedProblem(const csp::Problem& problem, std::span<const double> values,
                                       std::span<const csp::VariableId> free)
    : free_(free.begin(), free.end()),
      scratch_(std::make_shared<Scratch>()),
      sub_(std::make_unique<csp::Problem>(problem.name() + " (conditioned)")) {
  scratch_->values.assign(values.begin(), values.end());
  scratch_->assigned.assign(problem.num_variables(), 1);
  constexpr csp::VariableId kFixed = ~csp::VariableId{0};
  std::vector<csp::VariableId> sub_id(problem.num_variables(), kFixed);
  for (csp::VariableId v : free_) {
    sub_id[v] = sub_->add_variable(problem.variable_name(v), problem.domain(v));
  }
  // Each constraint on a free variable once: the first free variable of its scope adds it.
  for (csp::VariableId v : free_) {
    for (const csp::Incidence& inc : problem.incidences(v)) {
      const csp::Constraint& c = problem.constraint(inc.constraint);
      std::vector<csp::VariableId> sub_scope, original_ids;
      bool first = true;
      for (std::size_t p = 0; p < c.scope().size(); ++p) {
        const csp::VariableId u = c.scope()[p];
        if (sub_id[u] == kFixed) continue;
        if (sub_scope.empty() && u != v) first = false;
        sub_scope.push_back(sub_id[u]);
        original_ids.push_back(u);
      }
      if (!first) continue;
      sub_->add_constraint(std::make_unique<ConditionedConstraint>(
          c, std::move(sub_scope), std::move(original_ids), scratch_));
    }
  }
}

csp::Assignment ConditionedProblem::restrict(std::span<const double> full) const {
  csp::Assignment out(free_.size());
  for (std::size_t i = 0; i < free_.size(); ++i) out[i] = full[free_[i]];
  return out;
}

void ConditionedProblem::extend(std::span<const double> sub_values, std::span<double> full) const {
  for (std::size_t i = 0; i < free_.size(); ++i) full[free_[i]] = sub_values[i];
}

}  // namespace sightline::solvers::detail
