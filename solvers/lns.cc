#include "sightline/solvers/lns.h"

#include <algorithm>
#include <cstdio>

#include "sightline/csp/incremental_evaluator.h"
#include "sightline/solvers/detail/conditioned_problem.h"
#include "sightline/solvers/detail/random.h"
#include "sightline/solvers/detail/start.h"
#include "sightline/solvers/registry.h"

namespace sightline::solvers {

namespace {

// Without any limit, the search ends after this many rounds without improvement.
constexpr std::int64_t kUnlimitedRounds = 3;

// Picks neighbourhoods: breadth first along the constraint graph from a random variable.
class NeighbourhoodPicker {
 public:
  explicit NeighbourhoodPicker(const csp::Problem& problem)
      : problem_(problem),
        variable_mark_(problem.num_variables(), 0),
        constraint_mark_(problem.num_constraints(), 0) {}

  // `size` (<= variables) distinct variables into `out`.
  void pick(std::size_t size, detail::Random& random, std::vector<csp::VariableId>& out) {
    ++stamp_;
    out.clear();
    const std::size_t n = problem_.num_variables();
    std::size_t head = 0;
    while (out.size() < size) {
      if (head == out.size()) {  // a new component (or the first): a random fresh variable
        csp::VariableId seed = static_cast<csp::VariableId>(random.index(n));
        while (variable_mark_[seed] == stamp_) seed = static_cast<csp::VariableId>((seed + 1) % n);
        add(seed, out);
        continue;
      }
      const csp::VariableId v = out[head++];
      const auto incidences = problem_.incidences(v);
      const std::size_t shift = incidences.empty() ? 0 : random.index(incidences.size());
      for (std::size_t i = 0; i < incidences.size() && out.size() < size; ++i) {
        const csp::ConstraintId c = incidences[(i + shift) % incidences.size()].constraint;
        if (constraint_mark_[c] == stamp_) continue;
        constraint_mark_[c] = stamp_;
        const auto scope = problem_.constraint(c).scope();
        const std::size_t turn = random.index(scope.size());
        for (std::size_t j = 0; j < scope.size() && out.size() < size; ++j) {
          const csp::VariableId u = scope[(j + turn) % scope.size()];
          if (variable_mark_[u] != stamp_) add(u, out);
        }
      }
    }
  }

 private:
  void add(csp::VariableId v, std::vector<csp::VariableId>& out) {
    variable_mark_[v] = stamp_;
    out.push_back(v);
  }

  const csp::Problem& problem_;
  std::vector<std::uint64_t> variable_mark_, constraint_mark_;
  std::uint64_t stamp_ = 0;
};

// Remaining share of a limit (0 = none): what is left after `used`, at least 1 when set.
std::uint64_t left_of(std::uint64_t limit, std::uint64_t used) {
  if (limit == 0) return 0;
  return limit > used ? limit - used : 1;
}

}  // namespace

const OptionSchema<LnsSolver::Options>& LnsSolver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.integer("min_size", &Options::min_size, "smallest neighbourhood, variables (>= 1)", 1);
    s.integer("max_size", &Options::max_size,
              "largest neighbourhood, variables (>= min_size); 0 = every variable", 0);
    s.integer("node_limit", &Options::node_limit, "bnb nodes per neighbourhood (>= 1)", 1);
    s.integer("rounds", &Options::rounds,
              "cap on rounds of sizes without improvement; -1 = none when a limit is set "
              "(3 without)",
              -1);
    s.integer("node_doublings", &Options::node_doublings,
              "the node limit doubles after each round of sizes without improvement, at most "
              "this many times (0 = fixed); an improvement brings it back (0..30)",
              0);
    s.boolean("greedy_start", &Options::greedy_start, "one greedy pass over the start first");
    s.real("tabu_seconds", &Options::tabu_seconds,
           "run tabu this many seconds first, within the time limit (0 = not at all)", 0);
    return s;
  }();
  return schema;
}

std::string LnsSolver::Options::validate() const {
  if (min_size < 1) return "min_size must be >= 1, got " + std::to_string(min_size);
  if (max_size != 0 && max_size < min_size) {
    return "max_size must be 0 (every variable) or >= min_size (" + std::to_string(min_size) +
           "), got " + std::to_string(max_size);
  }
  if (node_limit < 1) return "node_limit must be >= 1, got " + std::to_string(node_limit);
  if (node_doublings < 0 || node_doublings > 30) {
    return "node_doublings must be in 0..30, got " + std::to_string(node_doublings);
  }
  if (rounds < -1) return "rounds must be >= -1 (-1 = no cap), got " + std::to_string(rounds);
  if (!(tabu_seconds >= 0)) {
    return "tabu_seconds must be >= 0, got " + detail::format_real(tabu_seconds);
  }
  return "";
}

LnsSolver::LnsSolver(std::string name, Options options)
    : name_(std::move(name)), options_(options) {}

LnsSolver::~LnsSolver() = default;

std::string LnsSolver::unsuitable_reason(const csp::Problem& problem) const {
  if (!problem.all_discrete()) return "needs discrete domains (every variable)";
  return "";
}

void LnsSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                           const SolveContext& context, SolverResult& result) {
  if (std::string why = unsuitable_reason(problem); !why.empty()) {
    throw std::invalid_argument(name_ + ": " + why);
  }
  // Created here, not in the constructor: the registry may still be being built then.
  if (!bnb_) bnb_ = SolverRegistry::global().create("bnb");
  Budget budget(context, 1);  // a step costs far more than reading the clock
  const SolveLimits& limits = context.limits;
  const bool unlimited =
      limits.max_evaluations == 0 && limits.max_iterations == 0 && !(limits.time_limit_seconds > 0);
  detail::Random random(context.seed);
  const std::size_t n = problem.num_variables();
  csp::Assignment current;
  detail::prepare_start(problem, start, current);
  std::uint64_t evaluations = 0, iterations = 0;
  StopReason stop = StopReason::kCompleted;
  bool stopped = false;
  double best_seconds = 0;
  std::string note;

  // Time left, for a sub-solve (0 = no limit).
  auto time_left = [&] {
    if (!(limits.time_limit_seconds > 0)) return 0.0;
    return std::max(1e-6, limits.time_limit_seconds - budget.elapsed_seconds());
  };
  auto out_of_budget = [&](std::uint64_t extra_evaluations) {
    if (!budget.exhausted(evaluations + extra_evaluations, iterations)) return false;
    stop = budget.reason();
    stopped = true;
    return true;
  };

  csp::IncrementalEvaluator evaluator(problem, current);
  // The start is the first best: when nothing improves on it (it is already at the target),
  // the time to best is still recorded, as the trajectory's one point.
  const csp::Score start_score = evaluator.score();
  budget.note_best(evaluations, 0, &start_score);
  // Greedy pass: each variable takes its best value if that improves the score.
  if (options_.greedy_start) {
    for (csp::VariableId v = 0; v < n && !stopped; ++v) {
      const csp::Domain& d = problem.domain(v);
      if (out_of_budget(d.size())) break;
      csp::Score best_change;
      double best_value = evaluator.values()[v];
      for (std::size_t a = 0; a < d.size(); ++a) {
        const csp::Score change = evaluator.delta(v, d.value_at(a));
        ++evaluations;
        if (change.better_than(best_change)) {
          best_change = change;
          best_value = d.value_at(a);
        }
      }
      evaluator.assign(v, best_value);
    }
    if (const csp::Score now = evaluator.score(); now.better_than(start_score)) {
      budget.note_best(evaluations, 0, &now);
      best_seconds = budget.best_found_seconds();
    }
  }
  // Then tabu, if asked, for its share of the time.
  if (options_.tabu_seconds > 0 && !stopped && !out_of_budget(0)) {
    if (!tabu_) tabu_ = SolverRegistry::global().create("tabu");
    SolveContext tabu_context;
    tabu_context.seed = context.seed;
    tabu_context.want_breakdown = false;
    tabu_context.limits.stop = limits.stop;
    tabu_context.limits.max_evaluations = left_of(limits.max_evaluations, evaluations);
    tabu_context.limits.max_iterations = left_of(limits.max_iterations, iterations);
    const double left = time_left();
    tabu_context.limits.time_limit_seconds =
        left > 0 ? std::min(left, options_.tabu_seconds) : options_.tabu_seconds;
    const SolverResult r = tabu_->solve(problem, evaluator.values(), tabu_context);
    evaluations += r.evaluations;
    iterations += r.iterations;
    if (r.score.better_than(evaluator.score())) {
      for (csp::VariableId v = 0; v < n; ++v) evaluator.assign(v, r.best[v]);
      best_seconds = budget.elapsed_seconds();
      const csp::Score now = evaluator.score();
      budget.record_best(evaluations, best_seconds, &now);
    }
  }

  csp::Assignment best = evaluator.values();
  csp::Score best_score = evaluator.score();
  const std::size_t min_size =
      std::min<std::size_t>(n, static_cast<std::size_t>(options_.min_size));
  const std::size_t max_size =
      options_.max_size == 0
          ? n
          : std::min<std::size_t>(n, static_cast<std::size_t>(options_.max_size));
  const std::int64_t round_cap =
      options_.rounds >= 0 ? options_.rounds : (unlimited ? kUnlimitedRounds : -1);
  std::size_t size = min_size;
  std::int64_t fruitless_rounds = 0;
  // bnb's node limit: `node_limit`, doubled after each round of sizes without improvement
  // (up to 2^node_doublings times), back to `node_limit` on an improvement.
  const auto base_nodes = static_cast<std::uint64_t>(options_.node_limit);
  std::uint64_t node_limit = base_nodes;
  NeighbourhoodPicker picker(problem);
  std::vector<csp::VariableId> free;
  std::vector<double> previous;
  SolverResult sub_result;
  std::uint64_t neighbourhoods = 0, improvements = 0;
  while (n > 0 && !stopped && !out_of_budget(2)) {
    picker.pick(size, random, free);
    detail::ConditionedProblem conditioned(problem, evaluator.values(), free);
    SolveContext sub_context;
    sub_context.seed = random.bits();
    sub_context.want_breakdown = false;
    sub_context.limits.stop = limits.stop;
    sub_context.limits.max_iterations = node_limit;
    // One evaluation is kept back for scoring the result in the whole problem.
    sub_context.limits.max_evaluations =
        limits.max_evaluations ? limits.max_evaluations - evaluations - 1 : 0;
    sub_context.limits.time_limit_seconds = time_left();
    bnb_->solve_into(conditioned.problem(), conditioned.restrict(evaluator.values()), sub_context,
                     sub_result);
    evaluations += sub_result.evaluations + 1;
    ++iterations;
    ++neighbourhoods;
    const csp::Score before = evaluator.score();
    previous.clear();
    for (std::size_t i = 0; i < free.size(); ++i) {
      previous.push_back(evaluator.values()[free[i]]);
      evaluator.assign(free[i], sub_result.best[i]);
    }
    if (before.better_than(evaluator.score())) {  // worse (only from an infeasible start)
      for (std::size_t i = 0; i < free.size(); ++i) evaluator.assign(free[i], previous[i]);
    }
    const bool whole = free.size() == n;
    if (evaluator.score().better_than(best_score)) {
      best = evaluator.values();
      best_score = evaluator.score();
      best_seconds = budget.elapsed_seconds();
      budget.record_best(evaluations, best_seconds, &best_score);
      ++improvements;
    }
    if (evaluator.score().better_than(before)) {
      size = min_size;
      fruitless_rounds = 0;
      node_limit = base_nodes;
    } else if (++size > max_size) {
      size = min_size;
      if (node_limit < (base_nodes << options_.node_doublings)) node_limit *= 2;
      if (round_cap >= 0 && ++fruitless_rounds >= round_cap) break;
    }
    if (detail::is_zero(best_score)) {  // nothing beats a zero-cost feasible assignment
      stop = StopReason::kTargetReached;
      break;
    }
    if (whole && (sub_result.stop == StopReason::kProvenOptimal ||
                  sub_result.stop == StopReason::kCompleted)) {
      // bnb searched the whole problem to the end from the current bound.
      stop = best_score.feasible() ? StopReason::kProvenOptimal : StopReason::kCompleted;
      note = best_score.feasible()
                 ? "; proved optimal (the neighbourhood was the whole problem)"
                 : "; proved infeasible (the neighbourhood was the whole problem)";
      break;
    }
  }
  result.best = std::move(best);
  result.evaluations = evaluations;
  result.iterations = iterations;
  result.stop = stop;
  result.solutions_at_best = 0;
  char text[200];
  std::snprintf(text, sizeof text, "best found at %.3f s; %llu neighbourhoods, %llu improving",
                best_seconds, static_cast<unsigned long long>(neighbourhoods),
                static_cast<unsigned long long>(improvements));
  result.message = text + note;
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
