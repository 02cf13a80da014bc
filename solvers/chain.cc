#include "sightline/solvers/chain.h"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sightline::solvers {

const OptionSchema<ChainSolver::Options>& ChainSolver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.integer("max_transitions", &Options::max_transitions,
              "largest n x D^2 x L the dynamic programme agrees to run (>= 1)", 1);
    return s;
  }();
  return schema;
}

std::string ChainSolver::Options::validate() const {
  if (max_transitions < 1) {
    return "max_transitions must be at least 1, got " + std::to_string(max_transitions);
  }
  return "";
}

namespace {

// How a problem is a chain: its unary and consecutive-pair constraints by position, its run
// constraints, and the runs' cap.
struct ChainShape {
  std::string why_not;                         // empty: a chain
  std::vector<std::vector<csp::ConstraintId>> unary, pair;  // pair[i]: between i and i + 1
  std::vector<csp::ConstraintId> runs;
  std::size_t cap = 1;                         // the largest minimum run length
  double transitions = 0;                      // n x D^2 x cap
};

bool whole_sequence(std::span<const csp::VariableId> scope, std::size_t n) {
  if (scope.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (scope[i] != i) return false;
  }
  return true;
}

ChainShape shape_of(const csp::Problem& problem) {
  ChainShape shape;
  const std::size_t n = problem.num_variables();
  shape.unary.resize(n);
  shape.pair.resize(n);
  std::size_t widest = 1;
  for (csp::VariableId v = 0; v < n; ++v) {
    const csp::Domain& d = problem.domain(v);
    if (!d.is_discrete()) {
      shape.why_not = "variable " + problem.variable_name(v) + " is continuous (chain needs discrete domains)";
      return shape;
    }
    if (d.size() == 0) {
      shape.why_not = "variable " + problem.variable_name(v) + " has an empty domain";
      return shape;
    }
    widest = std::max(widest, d.size());
  }
  for (csp::ConstraintId c = 0; c < problem.num_constraints(); ++c) {
    const csp::Constraint& constraint = problem.constraint(c);
    const auto scope = constraint.scope();
    if (const auto runs = constraint.run_lengths()) {
      if (!whole_sequence(scope, n)) {
        shape.why_not = problem.constraint_name(c) +
                        " counts runs over other than all the variables in id order";
        return shape;
      }
      shape.runs.push_back(c);
      // Lengths up to the minimum are told apart exactly; past a maximum, each step costs.
      shape.cap = std::max({shape.cap, runs->min_length,
                            runs->max_length > 0 ? runs->max_length + 1 : std::size_t{1}});
    } else if (scope.size() == 1) {
      shape.unary[scope[0]].push_back(c);
    } else if (scope.size() == 2 && (scope[0] + 1 == scope[1] || scope[1] + 1 == scope[0])) {
      shape.pair[std::min(scope[0], scope[1])].push_back(c);
    } else {
      shape.why_not = problem.constraint_name(c) +
                      " is not unary, nor between two consecutive variables, nor a run count";
      return shape;
    }
  }
  shape.transitions = static_cast<double>(n) * static_cast<double>(widest) *
                      static_cast<double>(widest) * static_cast<double>(shape.cap);
  return shape;
}

void add_cost(const csp::Constraint& c, double violation, csp::Score& score) {
  if (violation <= 0) return;
  (c.is_hard() ? score.hard : score.soft) += c.weight() * violation;
}

// Why the solver refuses a problem of this shape, or "".
std::string refusal(const ChainShape& shape, std::int64_t max_transitions) {
  if (!shape.why_not.empty()) return shape.why_not;
  if (shape.transitions > static_cast<double>(max_transitions)) {
    std::ostringstream out;
    out << "the dynamic programme has " << shape.transitions
        << " transitions, above max_transitions = " << max_transitions;
    return out.str();
  }
  return "";
}

}  // namespace

std::string ChainSolver::unsuitable_reason(const csp::Problem& problem) const {
  return refusal(shape_of(problem), options_.max_transitions);
}

void ChainSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                             const SolveContext& context, SolverResult& result) {
  const ChainShape shape = shape_of(problem);
  if (const std::string why = refusal(shape, options_.max_transitions); !why.empty()) {
    throw std::invalid_argument("chain: " + why);
  }
  Budget budget(context);
  const std::size_t n = problem.num_variables();
  const std::size_t cap = shape.cap;
  result.best.assign(start.begin(), start.end());
  result.best.resize(n, 0.0);
  result.evaluations = result.iterations = 0;
  result.stop = StopReason::kCompleted;
  result.message.clear();
  if (n == 0) {
    finish_result(problem, context, budget, result);
    return;
  }
  std::vector<double> values(result.best);
  auto size = [&](std::size_t i) { return problem.domain(static_cast<csp::VariableId>(i)).size(); };
  auto value = [&](std::size_t i, std::size_t a) {
    return problem.domain(static_cast<csp::VariableId>(i)).value_at(a);
  };
  // The cost of a run of `length` ending (its shortfall under each run constraint), and of
  // a run of `length` (cap: cap or longer) growing by one (its excess over each maximum).
  std::vector<csp::Score> run_end(cap + 1), run_grows(cap + 1);
  for (std::size_t length = 1; length <= cap; ++length) {
    for (const csp::ConstraintId c : shape.runs) {
      const csp::Constraint& constraint = problem.constraint(c);
      const csp::RunLengths runs = *constraint.run_lengths();
      const std::size_t m = runs.min_length;
      const double shortfall =
          length >= m ? 0.0 : static_cast<double>(m - length) / static_cast<double>(m);
      add_cost(constraint, shortfall, run_end[length]);
      if (runs.max_length > 0 && (length == cap || length + 1 > runs.max_length)) {
        add_cost(constraint, 1.0 / static_cast<double>(runs.max_length), run_grows[length]);
      }
    }
  }
  const csp::Score kNone{std::numeric_limits<double>::infinity(), 0};
  // best[i][a * cap + (r - 1)]: the best score of variables 0..i with i at value a in a run
  // of r (r = cap: cap or longer); from[i][...]: the state of i - 1 it came from.
  std::vector<std::vector<csp::Score>> best(n);
  std::vector<std::vector<std::uint32_t>> from(n);
  auto unary = [&](std::size_t i, std::size_t a) {
    csp::Score s;
    values[i] = value(i, a);
    for (const csp::ConstraintId c : shape.unary[i]) {
      add_cost(problem.constraint(c), problem.constraint(c).violation(values), s);
      ++result.evaluations;
    }
    return s;
  };
  best[0].assign(size(0) * cap, kNone);
  from[0].assign(size(0) * cap, 0);
  for (std::size_t a = 0; a < size(0); ++a) best[0][a * cap] = unary(0, a);
  std::vector<csp::Score> pair_cost;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (budget.exhausted(result.evaluations, result.iterations)) {
      result.stop = budget.reason();
      result.message = "stopped at variable " + std::to_string(i) + " of " + std::to_string(n) +
                       ": the start is returned";
      finish_result(problem, context, budget, result);
      return;
    }
    const std::size_t da = size(i), db = size(i + 1);
    pair_cost.assign(da * db, csp::Score{});
    for (std::size_t a = 0; a < da; ++a) {
      values[i] = value(i, a);
      for (std::size_t b = 0; b < db; ++b) {
        values[i + 1] = value(i + 1, b);
        for (const csp::ConstraintId c : shape.pair[i]) {
          add_cost(problem.constraint(c), problem.constraint(c).violation(values),
                   pair_cost[a * db + b]);
          ++result.evaluations;
        }
      }
    }
    best[i + 1].assign(db * cap, kNone);
    from[i + 1].assign(db * cap, 0);
    for (std::size_t b = 0; b < db; ++b) {
      const csp::Score here = unary(i + 1, b);
      const double vb = value(i + 1, b);
      for (std::size_t a = 0; a < da; ++a) {
        const bool same = value(i, a) == vb;
        for (std::size_t r = 1; r <= cap; ++r) {
          const csp::Score& before = best[i][a * cap + (r - 1)];
          if (before.hard == kNone.hard) continue;
          ++result.iterations;
          csp::Score s = before + pair_cost[a * db + b] + here;
          std::size_t r2 = 1;
          if (same) {
            r2 = std::min(r + 1, cap);
            s += run_grows[r];
          } else {
            s += run_end[r];
          }
          csp::Score& slot = best[i + 1][b * cap + (r2 - 1)];
          if (slot.hard == kNone.hard || s.better_than(slot)) {
            slot = s;
            from[i + 1][b * cap + (r2 - 1)] = static_cast<std::uint32_t>(a * cap + (r - 1));
          }
        }
      }
    }
  }
  // The last run ends with the sequence.
  std::size_t state = 0;
  csp::Score top = kNone;
  for (std::size_t s = 0; s < best[n - 1].size(); ++s) {
    if (best[n - 1][s].hard == kNone.hard) continue;
    const csp::Score total = best[n - 1][s] + run_end[s % cap + 1];
    if (top.hard == kNone.hard || total.better_than(top)) {
      top = total;
      state = s;
    }
  }
  for (std::size_t i = n; i-- > 0;) {
    result.best[i] = value(i, state / cap);
    state = from[i][state];
  }
  budget.note_best(result.evaluations, 0, &top);
  result.stop = StopReason::kProvenOptimal;
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
