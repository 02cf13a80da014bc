#include "sightline/solvers/detail/bnb_soft_search.h"
#include "sightline/solvers/detail/bnb_outcome.h"

#include <cmath>
#include <sstream>

namespace sightline::solvers::detail {

namespace {
const char* level_name(SoftArcConsistency::Level level) {
  switch (level) {
    case SoftArcConsistency::Level::kNode:
      return "nc";
    case SoftArcConsistency::Level::kArc:
      return "ac";
    case SoftArcConsistency::Level::kDirectional:
      return "fdac";
    case SoftArcConsistency::Level::kExistential:
      return "edac";
  }
  return "?";
}
}  // namespace

std::int64_t SoftArcSearch::top() const {
  if (!have_incumbent_) return SoftArcConsistency::kForbidden;
  return settings_.count_mode ? ub_ + 1 : ub_;
}

csp::VariableId SoftArcSearch::select_variable() const {
  if (settings_.last_conflict && conflict_ != kNone && state_.alive_count(conflict_) > 1) {
    return conflict_;
  }
  csp::VariableId best = kNone;
  std::uint64_t best_size = 0, best_weight = 1;
  for (csp::VariableId v = 0; v < state_.num_variables(); ++v) {
    const std::uint64_t size = state_.alive_count(v);
    if (size <= 1) continue;
    const std::size_t open_nary = state_.open_nary(v);
    std::uint64_t weight = 1 + open_nary;
    bool isolated = open_nary == 0;
    for (const auto& nb : state_.neighbours(v)) {
      if (state_.alive_count(nb.other) > 1) {
        weight += weight_[nb.edge];
        isolated = false;
      }
    }
    // Every cost function of v has its other variables fixed: v no longer interacts with
    // the rest, so its best value is known without branching (leaf() picks it), as
    // toulbar2 eliminates variables of degree 0. Not when counting: every optimum counts.
    if (isolated && !settings_.count_mode) continue;
    // size / weight < best_size / best_weight, by cross-multiplication.
    if (best == kNone || size * best_weight < best_size * weight) {
      best = v;
      best_size = size;
      best_weight = weight;
    }
  }
  return best;
}

void SoftArcSearch::failed() {
  const std::int64_t e = state_.last_edge();
  if (e >= 0) ++weight_[static_cast<std::size_t>(e)];
}

// The alive value of a fixed variable.
std::uint32_t SoftArcSearch::only_value(csp::VariableId v) const {
  for (std::uint32_t a = 0; a < state_.domain_size(v); ++a) {
    if (state_.alive(v, a)) return a;
  }
  return 0;
}

void SoftArcSearch::leaf() {
  for (csp::VariableId v = 0; v < state_.num_variables(); ++v) {
    if (state_.alive_count(v) <= 1) values_[v] = view_->values[view_->offset[v] + only_value(v)];
  }
  // A variable still unfixed is isolated (select_variable): what it adds to the cost of
  // the completion is its unary cost plus what its pairs with fixed variables still hold
  // (0 once propagation settled, but counted anyway), so the least of that is its best.
  for (csp::VariableId v = 0; v < state_.num_variables(); ++v) {
    if (state_.alive_count(v) <= 1) continue;
    std::int64_t least = -1;
    for (std::uint32_t a = 0; a < state_.domain_size(v); ++a) {
      if (!state_.alive(v, a)) continue;
      std::int64_t cost = state_.unary(v, a);
      for (const auto& nb : state_.neighbours(v)) {
        const std::uint32_t b = only_value(nb.other);
        cost = add_cost(cost, nb.is_x ? state_.binary(nb.edge, a, b) : state_.binary(nb.edge, b, a));
      }
      if (least < 0 || cost < least) {
        least = cost;
        values_[v] = view_->values[view_->offset[v] + a];
      }
    }
  }
  const csp::Score score = problem_->score(values_);
  ++full_evaluations_;
  if (!score.feasible()) return;  // cannot happen: a hard violation costs top
  const auto cost = static_cast<std::int64_t>(std::llround(score.soft));
  if (!have_incumbent_ || cost < ub_) {
    have_incumbent_ = true;
    ub_ = cost;
    best_ = values_;
    optimal_count_ = 1;
    budget_->note_best(full_evaluations_, 0, &score);
  } else if (settings_.count_mode && cost == ub_) {
    ++optimal_count_;
  }
}

void SoftArcSearch::search() {
  const csp::VariableId x = select_variable();
  if (x == kNone) {
    leaf();
    return;
  }
  // The value of least unary cost, ties to the one whose neighbours answer it cheapest
  // (EDAC's existential support costs 0 both ways).
  std::uint32_t a = 0;
  std::int64_t least = -1, least_support = 0;
  for (std::uint32_t b = 0; b < state_.domain_size(x); ++b) {
    if (!state_.alive(x, b) || (least >= 0 && state_.unary(x, b) > least)) continue;
    const std::int64_t support = state_.support_cost(x, b);
    if (least < 0 || state_.unary(x, b) < least || support < least_support) {
      least = state_.unary(x, b);
      least_support = support;
      a = b;
    }
  }
  const std::size_t mark = state_.mark();
  for (int branch = 0; branch < 2; ++branch) {
    if (budget_->exhausted(full_evaluations_, nodes_)) {
      stopped_ = true;
      return;
    }
    ++nodes_;
    state_.set_top(top());
    const bool ok = branch == 0 ? state_.assign(x, a) : state_.remove(x, a);
    const bool consistent = ok && state_.propagate();
    if (state_.stopped()) {
      stopped_ = true;
      state_.undo(mark);
      return;
    }
    if (consistent) {
      if (branch == 0 && conflict_ == x) conflict_ = kNone;
      search();
    } else {
      failed();
      if (branch == 0) conflict_ = x;
    }
    state_.undo(mark);
    if (stopped_) return;
  }
}

void SoftArcSearch::run(const csp::Problem& problem, const WcspView& view,
                        std::span<const double> start, const Settings& settings, Budget& budget,
                        SolverResult& result) {
  problem_ = &problem;
  view_ = &view;
  settings_ = settings;
  budget_ = &budget;
  state_.load(view, settings.level);
  weight_.assign(view.edges.size(), 1);
  values_.assign(start.begin(), start.end());
  best_.assign(start.begin(), start.end());
  have_incumbent_ = false;
  ub_ = 0;
  optimal_count_ = 0;
  nodes_ = 0;
  full_evaluations_ = 0;
  stopped_ = false;
  conflict_ = kNone;
  if (settings.use_start) {
    const csp::Score s = problem.score(start);
    ++full_evaluations_;
    if (s.feasible()) {
      have_incumbent_ = true;
      ub_ = static_cast<std::int64_t>(std::llround(s.soft));
      optimal_count_ = 0;  // the search visits the start again if it is optimal
      budget.note_best(full_evaluations_, 0, &s);  // the start is the first incumbent
    }
  }
  state_.set_stop_check([this] { return budget_->exhausted(full_evaluations_, nodes_); });
  state_.set_top(top());
  const bool root_ok = state_.propagate();
  stopped_ = state_.stopped();
  const std::int64_t root_bound = state_.lower_bound();
  if (root_ok) search();

  result.best = best_;
  result.iterations = nodes_;
  result.evaluations = full_evaluations_;
  result.solutions_at_best = settings.count_mode ? optimal_count_ : 0;
  std::ostringstream message;
  describe_bnb_outcome(stopped_, have_incumbent_, settings.count_mode, optimal_count_, budget, result, message);
  message << "; " << nodes_ << " nodes, soft arc consistency " << level_name(settings.level)
          << " (root lower bound " << (root_ok ? std::to_string(root_bound) : "top") << ")";
  result.message = message.str();
}

}  // namespace sightline::solvers::detail
