#include "sightline/solvers/detail/move_table.h"

namespace sightline::solvers::detail {

namespace {
constexpr std::uint32_t kNotListed = ~std::uint32_t{0};
}

MoveTable::MoveTable(const csp::Problem& problem) : problem_(problem) {
  const std::size_t n = problem.num_variables();
  offset_.assign(n + 1, 0);
  for (csp::VariableId v = 0; v < n; ++v) {
    offset_[v + 1] = offset_[v] + static_cast<std::uint32_t>(problem.domain(v).size());
  }
  domain_values_.resize(offset_.back());
  for (csp::VariableId v = 0; v < n; ++v) {
    const csp::Domain& d = problem.domain(v);
    for (std::size_t a = 0; a < d.size(); ++a) domain_values_[offset_[v] + a] = d.value_at(a);
  }
  rows_.assign(offset_.back(), csp::Score{});
  move_work_.assign(n, 0);
  for (csp::VariableId v = 0; v < n; ++v) {
    std::uint64_t work = 0;
    for (const csp::Incidence& inc : problem.incidences(v)) {
      for (csp::VariableId u : problem.constraint(inc.constraint).scope()) {
        if (u != v) work += domain_size(u);
      }
    }
    move_work_[v] = work;
  }
  const std::size_t m = problem.num_constraints();
  weights_.resize(m);
  hard_.resize(m);
  for (csp::ConstraintId c = 0; c < m; ++c) {
    weights_[c] = problem.constraint(c).weight();
    hard_[c] = problem.constraint(c).is_hard();
  }
}

void MoveTable::rebuild(std::span<const double> values) {
  const std::size_t n = problem_.num_variables();
  const std::size_t m = problem_.num_constraints();
  values_.assign(values.begin(), values.end());
  index_.resize(n);
  for (csp::VariableId v = 0; v < n; ++v) {
    index_[v] = static_cast<std::uint32_t>(*problem_.domain(v).index_of(values_[v]));
  }
  states_.clear();
  states_.resize(m);
  violations_.assign(m, 0.0);
  violated_on_.assign(n, 0);
  conflict_slot_.assign(n, kNotListed);
  conflicting_.clear();
  total_ = {};
  for (csp::ConstraintId c = 0; c < m; ++c) {
    const csp::Constraint& constraint = problem_.constraint(c);
    states_[c] = constraint.make_incremental_state(values_);
    const auto known = states_[c] ? states_[c]->current_violation() : std::nullopt;
    set_violation(c, known ? *known : constraint.violation(values_));
  }
  for (csp::VariableId v = 0; v < n; ++v) fill_row(v);
}

double MoveTable::constraint_delta(csp::ConstraintId c, std::uint32_t position, double value) {
  if (states_[c]) return states_[c]->delta(values_, position, value);
  const csp::Constraint& constraint = problem_.constraint(c);
  const csp::VariableId var = constraint.scope()[position];
  const double old = values_[var];
  values_[var] = value;
  const double after = constraint.violation(values_);
  values_[var] = old;
  return after - violations_[c];
}

void MoveTable::set_violation(csp::ConstraintId c, double violation) {
  const double old = violations_[c];
  violations_[c] = violation;
  (hard_[c] ? total_.hard : total_.soft) += weights_[c] * (violation - old);
  if ((old > 0) == (violation > 0)) return;
  for (csp::VariableId v : problem_.constraint(c).scope()) {
    if (violation > 0) {
      if (violated_on_[v]++ == 0) {
        conflict_slot_[v] = static_cast<std::uint32_t>(conflicting_.size());
        conflicting_.push_back(v);
      }
    } else if (--violated_on_[v] == 0) {
      const std::uint32_t slot = conflict_slot_[v];
      conflicting_[slot] = conflicting_.back();
      conflict_slot_[conflicting_[slot]] = slot;
      conflicting_.pop_back();
      conflict_slot_[v] = kNotListed;
    }
  }
}

void MoveTable::fill_row(csp::VariableId var) {
  csp::Score* row = rows_.data() + offset_[var];
  const std::size_t d = domain_size(var);
  for (std::size_t a = 0; a < d; ++a) row[a] = {};
  const std::uint32_t current = index_[var];
  for (const csp::Incidence& inc : problem_.incidences(var)) {
    const double w = weights_[inc.constraint];
    const double here = violations_[inc.constraint];
    double csp::Score::*part = hard_[inc.constraint] ? &csp::Score::hard : &csp::Score::soft;
    for (std::uint32_t a = 0; a < d; ++a) {
      const double change =
          a == current ? 0.0 : constraint_delta(inc.constraint, inc.position, value_at(var, a));
      row[a].*part += w * (here + change);
    }
  }
}

void MoveTable::add_neighbour_parts(csp::ConstraintId c, csp::VariableId mover, double sign) {
  const auto scope = problem_.constraint(c).scope();
  const double w = sign * weights_[c];
  const double here = violations_[c];
  double csp::Score::*part = hard_[c] ? &csp::Score::hard : &csp::Score::soft;
  for (std::uint32_t q = 0; q < scope.size(); ++q) {
    const csp::VariableId u = scope[q];
    if (u == mover) continue;
    csp::Score* row = rows_.data() + offset_[u];
    const std::uint32_t d = static_cast<std::uint32_t>(domain_size(u));
    const std::uint32_t current = index_[u];
    for (std::uint32_t b = 0; b < d; ++b) {
      const double change = b == current ? 0.0 : constraint_delta(c, q, value_at(u, b));
      row[b].*part += w * (here + change);
    }
  }
}

void MoveTable::move(csp::VariableId var, std::uint32_t index) {
  if (index == index_[var]) return;
  const double value = value_at(var, index);
  const auto incidences = problem_.incidences(var);
  for (const csp::Incidence& inc : incidences) add_neighbour_parts(inc.constraint, var, -1);
  // Every state is told before the assignment changes (IncrementalState's protocol).
  for (const csp::Incidence& inc : incidences) {
    const double change = constraint_delta(inc.constraint, inc.position, value);
    if (states_[inc.constraint]) states_[inc.constraint]->commit(values_, inc.position, value);
    violations_scratch_.push_back(change);
  }
  values_[var] = value;
  index_[var] = index;
  for (std::size_t k = 0; k < incidences.size(); ++k) {
    const csp::ConstraintId c = incidences[k].constraint;
    // A constraint re-evaluated from scratch gets its exact violation (no drift).
    set_violation(c, states_[c] ? violations_[c] + violations_scratch_[k]
                                : problem_.constraint(c).violation(values_));
  }
  violations_scratch_.clear();
  for (const csp::Incidence& inc : incidences) add_neighbour_parts(inc.constraint, var, +1);
  // var's own row does not change: it depends on the other variables only.
}

}  // namespace sightline::solvers::detail
