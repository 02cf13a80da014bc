#include "sightline/solvers/detail/compound_moves.h"

#include <algorithm>
#include <unordered_map>

namespace sightline::solvers::detail {

namespace {

bool on_both(const csp::Constraint& c, csp::VariableId x, csp::VariableId y) {
  const auto scope = c.scope();
  return std::find(scope.begin(), scope.end(), x) != scope.end() &&
         std::find(scope.begin(), scope.end(), y) != scope.end();
}

}  // namespace

CompoundMoves::CompoundMoves(const csp::Problem& problem, std::size_t max_entries,
                             double max_density)
    : problem_(problem) {
  const std::size_t n = problem.num_variables();
  // The pairs, in the order of their first hard binary constraint.
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  std::size_t entries = 0;
  for (csp::ConstraintId c = 0; c < problem.num_constraints(); ++c) {
    const csp::Constraint& constraint = problem.constraint(c);
    const auto scope = constraint.scope();
    if (!constraint.is_hard() || scope.size() != 2 || scope[0] == scope[1]) continue;
    const csp::VariableId x = std::min(scope[0], scope[1]);
    const csp::VariableId y = std::max(scope[0], scope[1]);
    if (!problem.domain(x).is_discrete() || !problem.domain(y).is_discrete()) continue;
    const std::uint64_t key = (std::uint64_t{x} << 32) | y;
    if (index.count(key)) continue;
    const std::size_t size = problem.domain(x).size() * problem.domain(y).size();
    if (entries + size > max_entries) continue;
    index.emplace(key, static_cast<std::uint32_t>(pairs_.size()));
    Pair p{};
    p.first = x;
    p.second = y;
    p.rows = static_cast<std::uint32_t>(problem.domain(x).size());
    p.cols = static_cast<std::uint32_t>(problem.domain(y).size());
    p.matrix = entries;
    entries += size;
    pairs_.push_back(p);
  }
  cost_.assign(entries, csp::Score{});
  allowed_.assign(entries, 1);
  wider_start_.assign(pairs_.size() + 1, 0);
  csp::Assignment scratch = problem.default_assignment();
  std::vector<csp::ConstraintId> binary;
  std::vector<char> loose(pairs_.size(), 0);
  for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
    Pair& p = pairs_[k];
    binary.clear();
    for (const csp::Incidence& inc : problem.incidences(p.first)) {
      const csp::Constraint& c = problem.constraint(inc.constraint);
      if (!on_both(c, p.first, p.second)) continue;
      if (c.scope().size() == 2) {
        binary.push_back(inc.constraint);
      } else {
        wider_.push_back(inc.constraint);
      }
    }
    wider_start_[k + 1] = static_cast<std::uint32_t>(wider_.size());
    const csp::Domain& dx = problem.domain(p.first);
    const csp::Domain& dy = problem.domain(p.second);
    for (std::uint32_t a = 0; a < p.rows; ++a) {
      scratch[p.first] = dx.value_at(a);
      for (std::uint32_t b = 0; b < p.cols; ++b) {
        scratch[p.second] = dy.value_at(b);
        const std::size_t at = p.matrix + std::size_t{a} * p.cols + b;
        for (csp::ConstraintId c : binary) {
          const csp::Constraint& constraint = problem.constraint(c);
          const double v = constraint.violation(scratch);
          (constraint.is_hard() ? cost_[at].hard : cost_[at].soft) += constraint.weight() * v;
          if (constraint.is_hard() && v > 0) allowed_[at] = 0;
        }
      }
    }
    // Supports of each row value (columns allowed with it), then of each column value.
    const std::size_t first_support = supports_.size();
    p.row_supports = support_start_.size();
    for (std::uint32_t a = 0; a < p.rows; ++a) {
      support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
      for (std::uint32_t b = 0; b < p.cols; ++b) {
        if (allowed_[p.matrix + std::size_t{a} * p.cols + b]) supports_.push_back(b);
      }
    }
    support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
    p.col_supports = support_start_.size();
    for (std::uint32_t b = 0; b < p.cols; ++b) {
      support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
      for (std::uint32_t a = 0; a < p.rows; ++a) {
        if (allowed_[p.matrix + std::size_t{a} * p.cols + b]) supports_.push_back(a);
      }
    }
    support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
    // Each allowed value pair is listed twice (as a row's support and as a column's).
    loose[k] = static_cast<double>(supports_.size() - first_support) >
               2 * max_density * static_cast<double>(std::size_t{p.rows} * p.cols);
    // Conflicts: the complements, indexed by the partner's value (stored in supports_ too).
    p.row_conflicts = support_start_.size();
    for (std::uint32_t b = 0; b < p.cols; ++b) {
      support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
      for (std::uint32_t a = 0; a < p.rows; ++a) {
        if (!allowed_[p.matrix + std::size_t{a} * p.cols + b]) supports_.push_back(a);
      }
    }
    support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
    p.col_conflicts = support_start_.size();
    for (std::uint32_t a = 0; a < p.rows; ++a) {
      support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
      for (std::uint32_t b = 0; b < p.cols; ++b) {
        if (!allowed_[p.matrix + std::size_t{a} * p.cols + b]) supports_.push_back(b);
      }
    }
    support_start_.push_back(static_cast<std::uint32_t>(supports_.size()));
  }
  // Per variable, its links (CSR); loose pairs get none (their tables stay, unused).
  link_start_.assign(n + 1, 0);
  for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
    if (loose[k]) continue;
    ++link_start_[pairs_[k].first + 1];
    ++link_start_[pairs_[k].second + 1];
  }
  for (std::size_t v = 0; v < n; ++v) link_start_[v + 1] += link_start_[v];
  links_.resize(link_start_[n]);
  std::vector<std::uint32_t> fill(link_start_.begin(), link_start_.end() - 1);
  for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
    if (loose[k]) continue;
    tight_pairs_ += 1;
    links_[fill[pairs_[k].first]++] = {k, true};
    links_[fill[pairs_[k].second]++] = {k, false};
  }
}

bool CompoundMoves::allowed(const Link& link, std::uint32_t a, std::uint32_t b) const {
  const Pair& p = pairs_[link.pair];
  return link.self_is_first ? allowed_[p.matrix + std::size_t{a} * p.cols + b] != 0
                            : allowed_[p.matrix + std::size_t{b} * p.cols + a] != 0;
}

std::span<const std::uint32_t> CompoundMoves::supports(const Link& link, std::uint32_t a) const {
  const Pair& p = pairs_[link.pair];
  const std::size_t at = (link.self_is_first ? p.row_supports : p.col_supports) + a;
  return {supports_.data() + support_start_[at], supports_.data() + support_start_[at + 1]};
}

std::span<const std::uint32_t> CompoundMoves::conflicts(const Link& link, std::uint32_t b) const {
  const Pair& p = pairs_[link.pair];
  const std::size_t at = (link.self_is_first ? p.row_conflicts : p.col_conflicts) + b;
  return {supports_.data() + support_start_[at], supports_.data() + support_start_[at + 1]};
}

csp::Score CompoundMoves::change(const MoveTable& table, csp::VariableId self, const Link& link,
                                 std::uint32_t a, std::uint32_t b,
                                 csp::Assignment& scratch) const {
  const Pair& p = pairs_[link.pair];
  const csp::VariableId other = link.self_is_first ? p.second : p.first;
  const std::uint32_t a0 = table.index_of(self);
  const std::uint32_t b0 = table.index_of(other);
  const auto m = [&](std::uint32_t s, std::uint32_t o) {
    return link.self_is_first ? pair_cost(p, s, o) : pair_cost(p, o, s);
  };
  // The rows count the pair's constraints with the other variable at its old value; the
  // bracket puts the joint value in their place.
  csp::Score total = table.change(self, a) + table.change(other, b);
  total += m(a, b) - m(a, b0) - m(a0, b) + m(a0, b0);
  for (std::uint32_t k = wider_start_[link.pair]; k < wider_start_[link.pair + 1]; ++k) {
    const csp::Constraint& c = problem_.constraint(wider_[k]);
    const auto at = [&](std::uint32_t s, std::uint32_t o) {
      scratch[self] = table.value_at(self, s);
      scratch[other] = table.value_at(other, o);
      return c.violation(scratch);
    };
    const double joint = at(a, b) - at(a, b0) - at(a0, b) + at(a0, b0);
    (c.is_hard() ? total.hard : total.soft) += c.weight() * joint;
  }
  scratch[self] = table.value_at(self, a0);
  scratch[other] = table.value_at(other, b0);
  return total;
}

}  // namespace sightline::solvers::detail
