#include "sightline/solvers/detail/bnb_search.h"
#include "sightline/solvers/detail/bnb_outcome.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sightline::solvers::detail {

void BranchAndBoundSearch::setup(const csp::Problem& problem, std::span<const double> start) {
  problem_ = &problem;
  n_ = problem.num_variables();
  const std::size_t m = problem.num_constraints();
  offset_.assign(n_ + 1, 0);
  std::uint32_t widest = 0;
  for (std::size_t v = 0; v < n_; ++v) {
    const auto d = static_cast<std::uint32_t>(problem.domain(v).size());
    offset_[v + 1] = offset_[v] + d;
    widest = std::max(widest, d);
  }
  const std::size_t slots = offset_[n_];
  domain_values_.resize(slots);
  for (std::size_t v = 0; v < n_; ++v) {
    const csp::Domain& d = problem.domain(v);
    for (std::size_t i = 0; i < d.size(); ++i) domain_values_[offset_[v] + i] = d.value_at(i);
  }
  values_.resize(n_);
  for (std::size_t v = 0; v < n_; ++v) values_[v] = domain_values_[offset_[v]];
  assigned_.assign(n_, 0);
  alive_.assign(slots, 1);
  alive_count_.resize(n_);
  for (std::size_t v = 0; v < n_; ++v) alive_count_[v] = offset_[v + 1] - offset_[v];
  ic_soft_.assign(slots, 0.0);
  ic_hard_.assign(slots, 0.0);
  min_soft_.assign(n_, 0.0);
  unassigned_in_.resize(m);
  degree_.assign(n_, 0);
  target_.assign(m, kNoTarget);
  contribution_offset_.assign(m + 1, 0);
  for (csp::ConstraintId c = 0; c < m; ++c) {
    const auto scope = problem.constraint(c).scope();
    unassigned_in_[c] = static_cast<std::uint32_t>(scope.size());
    std::uint32_t size = 0;
    if (scope.size() >= 2) {
      for (csp::VariableId v : scope) {
        ++degree_[v];
        if (!problem.constraint(c).is_hard()) size = std::max(size, offset_[v + 1] - offset_[v]);
      }
    }
    contribution_offset_[c + 1] = contribution_offset_[c] + size;
  }
  contribution_.assign(contribution_offset_[m], 0.0);
  bound_row_.assign(widest, 0.0);
  sums_ = {};
  trail_.clear();
  row_buffer_.clear();
  touched_.clear();
  touched_stamp_.assign(n_, 0);
  stamp_ = 0;
  order_stack_.clear();
  order_stack_.reserve(slots);
  have_incumbent_ = false;
  ub_ = std::numeric_limits<double>::infinity();
  best_.assign(start.begin(), start.end());
  optimal_count_ = 0;
  nodes_ = 0;
  evaluations_ = 0;
  full_evaluations_ = 0;
  stopped_ = false;
  next_budget_check_ = kPropagationStride;
}

bool BranchAndBoundSearch::propagation_stopped() {
  if (stopped_) return true;
  if (evaluations_ < next_budget_check_) return false;
  next_budget_check_ = evaluations_ + kPropagationStride;
  if (budget_->exhausted(full_evaluations_, nodes_)) stopped_ = true;
  return stopped_;
}

void BranchAndBoundSearch::kill(csp::VariableId v, std::uint32_t index) {
  const std::uint32_t slot = offset_[v] + index;
  alive_[slot] = 0;
  --alive_count_[v];
  trail_.push_back({Undo::kAlive, slot, v, 0.0});
}

void BranchAndBoundSearch::touch(csp::VariableId v) {
  if (touched_stamp_[v] == stamp_) return;
  touched_stamp_[v] = stamp_;
  touched_.push_back(v);
}

// Adds constraint c's cost for each alive value of w (its only unassigned variable) to
// ic(w, .), after saving the row so backtracking restores it exactly.
void BranchAndBoundSearch::project(csp::ConstraintId c, csp::VariableId w) {
  const csp::Constraint& con = problem_->constraint(c);
  const std::uint32_t begin = offset_[w], end = offset_[w + 1];
  trail_.push_back({Undo::kRow, w, static_cast<std::uint32_t>(row_buffer_.size()), 0.0});
  row_buffer_.insert(row_buffer_.end(), ic_soft_.begin() + begin, ic_soft_.begin() + end);
  row_buffer_.insert(row_buffer_.end(), ic_hard_.begin() + begin, ic_hard_.begin() + end);
  const double saved = values_[w];
  for (std::uint32_t slot = begin; slot < end; ++slot) {
    if (!alive_[slot]) continue;
    values_[w] = domain_values_[slot];
    const double cost = con.weight() * con.violation(values_);
    ++evaluations_;
    if (con.is_hard()) {
      ic_hard_[slot] += cost;
      if (ic_hard_[slot] > 0) kill(w, slot - begin);
    } else {
      ic_soft_[slot] += cost;
    }
  }
  values_[w] = saved;
  touch(w);
}

// Forward checking on a hard constraint with two or more unassigned variables: false when
// its assigned part already breaks it; otherwise removes every value a of an unassigned
// variable u for which min_violation with u = a is positive.
bool BranchAndBoundSearch::check_hard_partial(csp::ConstraintId c) {
  const csp::Constraint& con = problem_->constraint(c);
  ++evaluations_;
  if (con.min_violation(values_, assigned_) > 0) return false;
  for (csp::VariableId w : con.scope()) {
    if (assigned_[w]) continue;
    const double saved = values_[w];
    assigned_[w] = 1;
    for (std::uint32_t slot = offset_[w]; slot < offset_[w + 1]; ++slot) {
      if (!alive_[slot]) continue;
      if (propagation_stopped()) break;
      values_[w] = domain_values_[slot];
      ++evaluations_;
      if (con.min_violation(values_, assigned_) > 0) {
        kill(w, slot - offset_[w]);
        touch(w);
      }
    }
    assigned_[w] = 0;
    values_[w] = saved;
    if (stopped_) return false;
  }
  return true;
}

// The bound a soft constraint c with >= 2 unassigned variables lends its target t:
//   dac_c(a) = w_c * min over completions with t = a of violation,
// exact over the alive values of the other variable when exactly two are unassigned (the
// directed arc consistency counts of PFC-DAC), min_violation() otherwise. Each such
// constraint counts for one future variable only, so the sum over future variables of
// min_a (ic + dac) stays a lower bound.
void BranchAndBoundSearch::compute_contribution(csp::ConstraintId c, csp::VariableId t) {
  const csp::Constraint& con = problem_->constraint(c);
  double* out = contribution_.data() + contribution_offset_[c];
  csp::VariableId other = kNoTarget;
  if (unassigned_in_[c] == 2) {
    for (csp::VariableId v : con.scope()) {
      if (!assigned_[v] && v != t) other = v;
    }
  }
  const double saved_t = values_[t];
  assigned_[t] = 1;
  for (std::uint32_t slot = offset_[t]; slot < offset_[t + 1]; ++slot) {
    double& bound = out[slot - offset_[t]];
    bound = 0;
    if (!alive_[slot] || propagation_stopped()) continue;  // stopped: the node fails anyway
    values_[t] = domain_values_[slot];
    if (other != kNoTarget && alive_count_[other] <= 64) {
      const double saved_o = values_[other];
      double lowest = std::numeric_limits<double>::infinity();
      for (std::uint32_t o = offset_[other]; o < offset_[other + 1] && lowest > 0; ++o) {
        if (!alive_[o]) continue;
        values_[other] = domain_values_[o];
        lowest = std::min(lowest, con.violation(values_));
        ++evaluations_;
      }
      values_[other] = saved_o;
      // No alive value left: the branch fails when `other` is refreshed; 0 keeps sums finite.
      bound = std::isinf(lowest) ? 0.0 : con.weight() * lowest;
    } else {
      bound = con.weight() * con.min_violation(values_, assigned_);
      ++evaluations_;
    }
  }
  assigned_[t] = 0;
  values_[t] = saved_t;
}

// Chooses (again) the target of soft constraint c after its assigned part changed: its
// first unassigned variable, or none once fewer than two are unassigned.
void BranchAndBoundSearch::retarget(csp::ConstraintId c) {
  const csp::Constraint& con = problem_->constraint(c);
  const csp::VariableId old = target_[c];
  const std::uint32_t begin = contribution_offset_[c], size = contribution_offset_[c + 1] - begin;
  trail_.push_back({Undo::kContribution, c, static_cast<std::uint32_t>(row_buffer_.size()),
                    static_cast<double>(old)});
  row_buffer_.insert(row_buffer_.end(), contribution_.begin() + begin,
                     contribution_.begin() + begin + size);
  if (old != kNoTarget && !assigned_[old]) touch(old);
  target_[c] = kNoTarget;
  if (unassigned_in_[c] < 2) return;
  for (csp::VariableId v : con.scope()) {
    if (!assigned_[v]) {
      target_[c] = v;
      break;
    }
  }
  compute_contribution(c, target_[c]);
  touch(target_[c]);
}

// bound_row_[a] = ic(u, a) + sum of the contributions targeting u, for u's values.
void BranchAndBoundSearch::fill_bound_row(csp::VariableId u) {
  const std::uint32_t begin = offset_[u], size = offset_[u + 1] - begin;
  std::copy_n(ic_soft_.begin() + begin, size, bound_row_.begin());
  for (const csp::Incidence& inc : problem_->incidences(u)) {
    if (target_[inc.constraint] != u) continue;
    const double* from = contribution_.data() + contribution_offset_[inc.constraint];
    for (std::uint32_t i = 0; i < size; ++i) bound_row_[i] += from[i];
  }
}

// Recomputes min alive (ic + dac) of the touched variables; false on an emptied domain.
bool BranchAndBoundSearch::refresh_touched() {
  for (csp::VariableId w : touched_) {
    if (alive_count_[w] == 0) return false;
    fill_bound_row(w);
    double lowest = std::numeric_limits<double>::infinity();
    for (std::uint32_t slot = offset_[w]; slot < offset_[w + 1]; ++slot) {
      if (alive_[slot]) lowest = std::min(lowest, bound_row_[slot - offset_[w]]);
    }
    if (lowest != min_soft_[w]) {
      trail_.push_back({Undo::kMin, w, 0, min_soft_[w]});
      sums_.future_min += lowest - min_soft_[w];
      min_soft_[w] = lowest;
    }
  }
  // Node consistency with respect to ub: a value whose own bound, added to everyone
  // else's, reaches ub can be dropped (only once every touched minimum is current, since a
  // minimum may also go down when a constraint stops lending its bound to w).
  if (!have_incumbent_) return true;
  const double lb = lower_bound();
  for (csp::VariableId w : touched_) {
    fill_bound_row(w);
    const double others = lb - min_soft_[w];
    for (std::uint32_t slot = offset_[w]; slot < offset_[w + 1]; ++slot) {
      if (alive_[slot] && prunes(others + bound_row_[slot - offset_[w]]))
        kill(w, slot - offset_[w]);
    }
    if (alive_count_[w] == 0) return false;
  }
  return true;
}

bool BranchAndBoundSearch::initial_propagation() {
  ++stamp_;
  touched_.clear();
  for (csp::VariableId v = 0; v < n_; ++v) touch(v);
  for (csp::ConstraintId c = 0; c < problem_->num_constraints(); ++c) {
    const csp::Constraint& con = problem_->constraint(c);
    if (con.scope().size() == 1) {
      project(c, con.scope()[0]);
    } else if (con.is_hard()) {
      if (!check_hard_partial(c)) return false;
    }
  }
  // Soft targets after the hard pruning, so their bounds see the smaller domains.
  for (csp::ConstraintId c = 0; c < problem_->num_constraints(); ++c) {
    const csp::Constraint& con = problem_->constraint(c);
    if (con.scope().size() >= 2 && !con.is_hard()) retarget(c);
  }
  // min_soft_ starts at 0 for every variable, so future_min starts at 0 too.
  return !stopped_ && refresh_touched();
}

bool BranchAndBoundSearch::assign(csp::VariableId u, std::uint32_t index) {
  ++stamp_;
  touched_.clear();
  const std::uint32_t slot = offset_[u] + index;
  trail_.push_back({Undo::kAssign, u, 0, values_[u]});
  assigned_[u] = 1;
  values_[u] = domain_values_[slot];
  sums_.assigned_cost += ic_soft_[slot];
  sums_.future_min -= min_soft_[u];
  for (const csp::Incidence& inc : problem_->incidences(u)) {
    const csp::ConstraintId c = inc.constraint;
    const csp::Constraint& con = problem_->constraint(c);
    trail_.push_back({Undo::kCount, c, 0, 0.0});
    const std::uint32_t left = --unassigned_in_[c];
    if (left == 0) continue;  // its cost came in through ic(u, index)
    if (!con.is_hard()) retarget(c);
    if (left == 1) {
      csp::VariableId w = 0;
      for (csp::VariableId v : con.scope()) {
        if (!assigned_[v]) w = v;
      }
      trail_.push_back({Undo::kDegree, w, 0, 0.0});
      --degree_[w];
      project(c, w);
    } else if (con.is_hard() && !check_hard_partial(c)) {
      return false;
    }
  }
  if (stopped_ || !refresh_touched()) return false;
  return !prunes(lower_bound());
}

void BranchAndBoundSearch::undo_to(std::size_t mark) {
  while (trail_.size() > mark) {
    const Undo& u = trail_.back();
    switch (u.kind) {
      case Undo::kAssign:
        assigned_[u.a] = 0;
        values_[u.a] = u.old;
        break;
      case Undo::kCount:
        ++unassigned_in_[u.a];
        break;
      case Undo::kAlive:
        alive_[u.a] = 1;
        ++alive_count_[u.b];
        break;
      case Undo::kRow: {
        const std::uint32_t begin = offset_[u.a], size = offset_[u.a + 1] - begin;
        std::copy_n(row_buffer_.begin() + u.b, size, ic_soft_.begin() + begin);
        std::copy_n(row_buffer_.begin() + u.b + size, size, ic_hard_.begin() + begin);
        row_buffer_.resize(u.b);
        break;
      }
      case Undo::kContribution: {
        const std::uint32_t begin = contribution_offset_[u.a];
        const std::uint32_t size = contribution_offset_[u.a + 1] - begin;
        std::copy_n(row_buffer_.begin() + u.b, size, contribution_.begin() + begin);
        row_buffer_.resize(u.b);
        target_[u.a] = static_cast<csp::VariableId>(u.old);
        break;
      }
      case Undo::kMin:
        min_soft_[u.a] = u.old;
        break;
      case Undo::kDegree:
        ++degree_[u.a];
        break;
    }
    trail_.pop_back();
  }
}

csp::VariableId BranchAndBoundSearch::select_variable() const {
  // Smallest alive / (1 + degree), compared by cross-multiplication.
  csp::VariableId best = static_cast<csp::VariableId>(n_);
  for (csp::VariableId v = 0; v < n_; ++v) {
    if (assigned_[v]) continue;
    if (best == n_ || std::uint64_t{alive_count_[v]} * (degree_[best] + 1) <
                          std::uint64_t{alive_count_[best]} * (degree_[v] + 1)) {
      best = v;
    }
  }
  return best;
}

void BranchAndBoundSearch::leaf() {
  const csp::Score score = problem_->score(values_);
  evaluations_ += problem_->num_constraints();
  ++full_evaluations_;
  if (!score.feasible()) return;  // cannot happen: hard constraints were checked on the way
  const double tol = 1e-9 * std::max(1.0, std::abs(ub_));
  if (!have_incumbent_ || score.soft < ub_ - tol) {
    have_incumbent_ = true;
    ub_ = score.soft;
    best_ = values_;
    optimal_count_ = 1;
    budget_->note_best(full_evaluations_, 0, &score);
  } else if (count_mode_ && score.soft <= ub_ + tol) {
    ++optimal_count_;
  }
}

void BranchAndBoundSearch::search(std::size_t depth) {
  if (budget_->exhausted(full_evaluations_, nodes_)) {
    stopped_ = true;
    return;
  }
  if (depth == n_) {
    leaf();
    return;
  }
  const csp::VariableId u = select_variable();
  const std::uint32_t base = offset_[u];
  fill_bound_row(u);
  const std::size_t order_begin = order_stack_.size();
  for (std::uint32_t slot = base; slot < offset_[u + 1]; ++slot) {
    if (alive_[slot]) order_stack_.emplace_back(bound_row_[slot - base], slot - base);
  }
  std::sort(order_stack_.begin() + order_begin, order_stack_.end());
  const std::size_t order_end = order_stack_.size();
  const double others = lower_bound() - min_soft_[u];
  for (std::size_t k = order_begin; k < order_end && !stopped_; ++k) {
    const auto [bound, index] = order_stack_[k];
    if (prunes(others + bound)) break;  // later values are no cheaper
    // Checked per branch, not only per node entered: failed assignments (forward checking
    // wiping a domain out) can otherwise run through whole subtrees unchecked.
    if (budget_->exhausted(full_evaluations_, nodes_)) {
      stopped_ = true;
      break;
    }
    ++nodes_;
    const Sums saved = sums_;
    const std::size_t mark = trail_.size();
    if (assign(u, index)) search(depth + 1);
    undo_to(mark);
    sums_ = saved;
  }
  order_stack_.resize(order_begin);
}

void BranchAndBoundSearch::run(const csp::Problem& problem, std::span<const double> start,
                               bool count_mode, bool use_start, Budget& budget,
                               SolverResult& result) {
  setup(problem, start);
  count_mode_ = count_mode;
  budget_ = &budget;
  if (use_start) {
    const csp::Score s = problem.score(start);
    evaluations_ += problem.num_constraints();
    ++full_evaluations_;
    if (s.feasible()) {
      have_incumbent_ = true;
      ub_ = s.soft;
      budget.note_best(full_evaluations_, 0, &s);  // the start is the first incumbent
    }
  }
  const bool consistent = initial_propagation();
  trail_.clear();  // the root is never undone
  row_buffer_.clear();
  if (consistent && !prunes(lower_bound())) search(0);

  result.best = best_;
  result.iterations = nodes_;
  result.evaluations = full_evaluations_;
  result.solutions_at_best = count_mode ? optimal_count_ : 0;
  std::ostringstream message;
  describe_bnb_outcome(stopped_, have_incumbent_, count_mode, optimal_count_, budget, result, message);
  message << "; " << nodes_ << " nodes, " << evaluations_ << " constraint checks";
  result.message = message.str();
}

}  // namespace sightline::solvers::detail
