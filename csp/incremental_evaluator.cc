#include "csp/incremental_evaluator.h"

namespace sightline::csp {

IncrementalEvaluator::IncrementalEvaluator(const Problem& problem, Assignment start)
    : problem_(&problem), values_(std::move(start)) {
  problem.check_assignment(values_);
  resynchronise();
}

void IncrementalEvaluator::resynchronise() {
  const std::size_t m = problem_->num_constraints();
  states_.clear();
  states_.resize(m);
  violations_.assign(m, 0.0);
  total_ = {};
  for (ConstraintId id = 0; id < m; ++id) {
    const Constraint& c = problem_->constraint(id);
    states_[id] = c.make_incremental_state(values_);
    violations_[id] = c.violation(values_);
    const double w = c.weight() * violations_[id];
    (c.is_hard() ? total_.hard : total_.soft) += w;
  }
  evaluations_ += m;
}

Score IncrementalEvaluator::delta(VariableId var, double new_value) {
  Score change;
  const double old_value = values_[var];
  if (old_value == new_value) return change;
  for (const Incidence& inc : problem_->incidences(var)) {
    const Constraint& c = problem_->constraint(inc.constraint);
    double dv;
    if (IncrementalState* s = states_[inc.constraint].get()) {
      dv = s->delta(values_, inc.position, new_value);
    } else {
      values_[var] = new_value;
      dv = c.violation(values_) - violations_[inc.constraint];
      values_[var] = old_value;
    }
    (c.is_hard() ? change.hard : change.soft) += c.weight() * dv;
  }
  evaluations_ += problem_->incidences(var).size();
  return change;
}

void IncrementalEvaluator::assign(VariableId var, double new_value) {
  const double old_value = values_[var];
  if (old_value == new_value) return;
  for (const Incidence& inc : problem_->incidences(var)) {
    const Constraint& c = problem_->constraint(inc.constraint);
    double dv;
    if (IncrementalState* s = states_[inc.constraint].get()) {
      dv = s->delta(values_, inc.position, new_value);
      s->commit(values_, inc.position, new_value);
    } else {
      values_[var] = new_value;
      dv = c.violation(values_) - violations_[inc.constraint];
      values_[var] = old_value;
    }
    violations_[inc.constraint] += dv;
    (c.is_hard() ? total_.hard : total_.soft) += c.weight() * dv;
  }
  values_[var] = new_value;
  evaluations_ += problem_->incidences(var).size();
}

double IncrementalEvaluator::involvement(VariableId var) {
  double sum = 0;
  for (const Incidence& inc : problem_->incidences(var)) {
    const Constraint& c = problem_->constraint(inc.constraint);
    if (IncrementalState* s = states_[inc.constraint].get()) {
      sum += c.weight() * s->involvement(values_, inc.position);
    } else {
      sum += c.weight() * violations_[inc.constraint];
    }
  }
  return sum;
}

}  // namespace sightline::csp
