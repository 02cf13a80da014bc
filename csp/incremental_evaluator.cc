#include "sightline/csp/incremental_evaluator.h"

#include <stdexcept>

namespace sightline::csp {

IncrementalEvaluator::IncrementalEvaluator(const Problem& problem, Assignment start,
                                           std::span<const ConstraintId> constant)
    : problem_(&problem), values_(std::move(start)), index_(problem.incidence_index()) {
  problem.check_assignment(values_);
  constant_.assign(problem.num_constraints(), 0);
  for (ConstraintId id : constant) {
    if (id >= problem.num_constraints()) {
      throw std::invalid_argument("IncrementalEvaluator: no constraint " + std::to_string(id));
    }
    constant_[id] = 1;
  }
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
    if (!constant_[id]) states_[id] = c.make_incremental_state(values_);
    const auto known = states_[id] ? states_[id]->current_violation() : std::nullopt;
    violations_[id] = known ? *known : c.violation(values_);
    const double w = c.weight() * violations_[id];
    (c.is_hard() ? total_.hard : total_.soft) += w;
  }
  evaluations_ += m;
  tracked_.resize(m);
  occupied_keys_.assign(m, {});
  all_partial_ = true;
  for (ConstraintId id = 0; id < m; ++id) {
    const Constraint& c = problem_->constraint(id);
    IncrementalState* state = states_[id].get();
    const bool partial = state && state->supports_partial();
    tracked_[id] = {state, &c, c.weight(), c.is_hard(), partial, constant_[id] != 0};
    if (partial) occupied_keys_[id] = state->occupied_keys();
    if (!partial && !constant_[id]) all_partial_ = false;
  }
}

Score IncrementalEvaluator::delta(VariableId var, double new_value) {
  Score change;
  const double old_value = values_[var];
  if (old_value == new_value) return change;
  for (const Incidence& link : links(var)) {
    const Tracked& t = tracked_[link.constraint];
    if (t.constant) continue;
    ++evaluations_;
    double dv;
    if (t.state) {
      dv = t.state->delta(values_, link.position, new_value);
    } else {
      values_[var] = new_value;
      dv = t.constraint->violation(values_) - violations_[link.constraint];
      values_[var] = old_value;
    }
    add(change, link.constraint, dv);
  }
  return change;
}

void IncrementalEvaluator::assign(VariableId var, double new_value) {
  const double old_value = values_[var];
  if (old_value == new_value) return;
  for (const Incidence& link : links(var)) {
    const Tracked& t = tracked_[link.constraint];
    if (t.constant) continue;
    ++evaluations_;
    double dv;
    if (t.state) {
      dv = t.state->delta(values_, link.position, new_value);
      t.state->commit(values_, link.position, new_value);
    } else {
      values_[var] = new_value;
      dv = t.constraint->violation(values_) - violations_[link.constraint];
      values_[var] = old_value;
    }
    violations_[link.constraint] += dv;
    add(total_, link.constraint, dv);
  }
  values_[var] = new_value;
}

double IncrementalEvaluator::involvement(VariableId var) {
  double sum = 0;
  for (const Incidence& link : links(var)) {
    const Tracked& t = tracked_[link.constraint];
    if (t.constant) continue;
    const double v =
        t.state ? t.state->involvement(values_, link.position) : violations_[link.constraint];
    sum += t.weight * v;
  }
  return sum;
}

bool IncrementalEvaluator::can_retract(VariableId var) const {
  if (all_partial_) return true;
  for (const Incidence& link : links(var)) {
    const Tracked& t = tracked_[link.constraint];
    if (!t.constant && !t.partial) return false;
  }
  return true;
}

void IncrementalEvaluator::require_retractable(VariableId var) const {
  if (!can_retract(var)) {
    throw std::logic_error("IncrementalEvaluator::retract: variable " + std::to_string(var) +
                           " has a constraint without partial-assignment support");
  }
}

void IncrementalEvaluator::retract(VariableId var) {
  require_retractable(var);
  for (const Incidence& link : links(var)) {
    if (tracked_[link.constraint].constant) continue;
    const double dv = tracked_[link.constraint].state->retract(values_, link.position);
    violations_[link.constraint] += dv;
    add(total_, link.constraint, dv);
  }
}

void IncrementalEvaluator::retract(std::span<const VariableId> vars) {
  // One pass counts, per constraint, the variables retracted (and checks that each can
  // be, before anything changes); the constraints whose whole scope goes are cleared at
  // once, and only when some constraint loses part of its scope is a second pass needed.
  // A permutation group retracted whole (constructive placement) takes the single pass.
  hits_.assign(problem_->num_constraints(), 0);
  for (VariableId v : vars) {
    for (const Incidence& link : links(v)) {
      const Tracked& t = tracked_[link.constraint];
      if (t.constant) continue;
      if (!t.partial) require_retractable(v);  // throws
      ++hits_[link.constraint];
    }
  }
  const auto whole = [&](ConstraintId id) {
    return hits_[id] == problem_->constraint(id).scope().size();
  };
  bool some_part = false;
  for (ConstraintId id = 0; id < hits_.size(); ++id) {
    if (hits_[id] != 0 && !whole(id)) some_part = true;
  }
  if (some_part) {
    for (VariableId v : vars) {
      for (const Incidence& link : links(v)) {
        if (tracked_[link.constraint].constant || whole(link.constraint)) continue;
        const double dv = tracked_[link.constraint].state->retract(values_, link.position);
        violations_[link.constraint] += dv;
        add(total_, link.constraint, dv);
      }
    }
  }
  for (ConstraintId id = 0; id < hits_.size(); ++id) {
    if (hits_[id] == 0 || !whole(id)) continue;
    const double dv = tracked_[id].state->retract_all(values_, hits_[id]);
    violations_[id] += dv;
    add(total_, id, dv);
  }
}

Score IncrementalEvaluator::place_delta(VariableId var, double value) {
  Score change;
  for (const Incidence& link : links(var)) {
    const Tracked& t = tracked_[link.constraint];
    if (t.constant) continue;
    ++evaluations_;
    add(change, link.constraint, t.state->place_delta(values_, link.position, value));
  }
  return change;
}

void IncrementalEvaluator::place(VariableId var, double value) {
  for (const Incidence& link : links(var)) {
    const Tracked& t = tracked_[link.constraint];
    if (t.constant) continue;
    IncrementalState* state = t.state;
    const double dv = state->place_delta(values_, link.position, value);
    state->place(values_, link.position, value);
    violations_[link.constraint] += dv;
    add(total_, link.constraint, dv);
  }
  values_[var] = value;
}

void IncrementalEvaluator::place_free(VariableId var, double value) {
  for (const Incidence& link : links(var)) {
    const Tracked& t = tracked_[link.constraint];
    if (t.constant) continue;
    const double dv = t.state->place_free(values_, link.position, value);
    if (dv != 0) {
      violations_[link.constraint] += dv;
      add(total_, link.constraint, dv);
    }
  }
  values_[var] = value;
}

}  // namespace sightline::csp
