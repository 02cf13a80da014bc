// Solver: the one interface every search method implements, with its result and limits.
//
// solve(problem, start, context) -> SolverResult. The start assignment is where local
// methods begin (the camera's current position, or the previous stage of a pipeline); the
// context carries the seed and the limits. Every solver is deterministic for a given seed
// and honours the limits, reporting which one stopped it. Solvers may keep scratch memory
// between calls (a camera solves every frame), so solve() is not const; one Solver object
// is used by one thread at a time.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::solvers {

// 0 means "no limit" for each field.
struct SolveLimits {
  std::uint64_t max_evaluations = 0;  // constraint-set evaluations (one candidate = one)
  std::uint64_t max_iterations = 0;   // solver-specific steps (moves, passes, nodes)
  double time_limit_seconds = 0;      // wall-clock
  // A request from outside to stop as soon as possible with the best so far (Ctrl-C in the
  // Python module, whose solve runs on a thread of its own): set by another thread, read
  // by Budget::exhausted (StopReason::kInterrupted). Not owned; null = none. Not a limit:
  // it does not count in any(), so a solve nobody stops runs as it would without it.
  const std::atomic<bool>* stop = nullptr;

  bool any() const { return max_evaluations || max_iterations || time_limit_seconds > 0; }
  bool stop_requested() const { return stop && stop->load(std::memory_order_relaxed); }
};

struct SolveContext {
  std::uint64_t seed = 1;
  SolveLimits limits;
  bool want_breakdown = true;  // fill SolverResult::breakdown (one vector, same pass as the score)
  // Alternatives (see SolverResult::alternatives): how many a solver should hand over, 0 =
  // none. A pipeline sets it to what its next stage asks for (Solver::alternatives_wanted),
  // and a global solver that explores may then spend extra work to find them.
  std::size_t alternatives_wanted = 0;
  // Other start points besides `start`, handed over by the previous stage of a pipeline (its
  // alternatives), best first; a local method may refine from them too. Not owned: valid
  // during the solve only. Each has one value per variable.
  std::span<const csp::Assignment> alternative_starts;
  // Anytime solvers (the stochastic ones, which cannot recognise an optimum above zero) use
  // their whole budget: they run until a limit stops them, and a restart count of their own
  // caps them only when the user sets one. A solver must end, though, so with no limit at
  // all they run a default course instead (sls: SlsSolver::kDefaultRestarts) and say so in
  // the result's message. A pipeline clears this flag for the stages before its last: they
  // run that default course within the pipeline's limits, and the last stage gets what is
  // left (`sls>bnb` under a time limit is sls's default run, then bnb for the rest).
  bool anytime = true;
  // Keep the anytime trajectory (SolverResult::trajectory): every improvement of the best
  // with its time. Off by default: a camera's frame keeps nothing.
  bool want_trajectory = false;

  // True when an anytime solver should run until a limit stops it.
  bool runs_to_the_limit() const { return anytime && limits.any(); }
};

enum class StopReason {
  kCompleted,        // the method ran its course (passes done, local optimum, lattice done)
  kProvenOptimal,    // an exact method proved the best is optimal
  kTargetReached,    // a zero-cost feasible assignment was found
  kEvaluationLimit,
  kIterationLimit,
  kTimeLimit,
  kInterrupted,      // SolveLimits::stop was set (Ctrl-C)
};
const char* to_string(StopReason reason);

// One improvement of a solver's best: when (seconds since the solve began, evaluations by
// then) and its score.
struct AnytimePoint {
  double seconds = 0;
  std::uint64_t evaluations = 0;
  csp::Score score;
};

struct SolverResult {
  csp::Assignment best;                        // best assignment found
  csp::Score score;                            // its (hard, soft) score
  std::vector<csp::ConstraintCost> breakdown;  // per-constraint costs of `best`, if asked
  std::uint64_t evaluations = 0;
  std::uint64_t iterations = 0;
  // Exhaustive solvers only (grid, bnb when asked to count): how many assignments reach the
  // best score. 0 when the solver does not count.
  std::uint64_t solutions_at_best = 0;
  // Up to SolveContext::alternatives_wanted other good assignments, best first, each in
  // another region of the search space than `best` and than each other (another side of an
  // obstacle, another basin), for a local method that follows to refine from besides
  // `best`: a local method cannot cross the walls between basins, so a global method that
  // has seen several is the one to say where they are. Empty when not asked for, or when
  // the solver does not explore (most leave it empty).
  std::vector<csp::Assignment> alternatives;
  double wall_seconds = 0;
  // When `best` was found: seconds since the solve began and the evaluations made by then
  // (time to best, for anytime solvers). -1 and 0 when the solver does not record it.
  double best_found_seconds = -1;
  std::uint64_t evaluations_at_best = 0;
  // With SolveContext::want_trajectory: the best score over time, one point per improvement
  // the solver reports (in order; the last is the result's own score), so anytime curves can
  // be drawn. Solvers that report none give one point, the end.
  std::vector<AnytimePoint> trajectory;
  StopReason stop = StopReason::kCompleted;
  std::string message;  // solver-specific detail, may be empty

  bool feasible() const { return score.feasible(); }
  double cost() const { return score.soft; }
  // "sls: cost 0 feasible, 1234 evaluations, 56 iterations, 0.012 s, best at 0.004 s
  // (800 evaluations), stop: target reached"
  std::string brief_report(const std::string& solver_name) const;
};

class Solver {
 public:
  virtual ~Solver() = default;
  // The name it was created under (for pipelines: "a>b").
  virtual std::string name() const = 0;
  // Empty when this solver can work on `problem`, else why not ("needs discrete domains").
  virtual std::string unsuitable_reason(const csp::Problem& problem) const;
  // How many alternative starts (SolveContext::alternative_starts) this solver would refine
  // from when it follows another in a pipeline; 0 (the default) = it uses only `start`.
  virtual std::size_t alternatives_wanted() const { return 0; }
  // Fills `result` (its vectors are reused, so a per-frame caller need not allocate).
  virtual void solve_into(const csp::Problem& problem, std::span<const double> start,
                          const SolveContext& context, SolverResult& result) = 0;
  SolverResult solve(const csp::Problem& problem, std::span<const double> start,
                     const SolveContext& context = {});
};

// Tracks the limits during a solve. Checking the clock is cheap but not free, so
// exhausted() reads it (and the stop request) only every `clock_stride` calls.
class Budget {
 public:
  explicit Budget(const SolveLimits& limits, unsigned clock_stride = 64);
  // The same, keeping the anytime trajectory when the context asks for it.
  explicit Budget(const SolveContext& context, unsigned clock_stride = 64);
  // True once any limit is reached; `reason()` then says which.
  bool exhausted(std::uint64_t evaluations, std::uint64_t iterations);
  StopReason reason() const { return reason_; }
  double elapsed_seconds() const;

  // The solver's best so far was found now, after `evaluations` evaluations (time to best,
  // copied into the result by finish_result). Reading the clock at every improvement would
  // cost a local search that improves 10^5 times a second, so the last reading is reused
  // when it was taken at most `stale_evaluations` evaluations ago (0: always read it).
  // `score`, when given, is the new best's, for the anytime trajectory.
  void note_best(std::uint64_t evaluations, std::uint64_t stale_evaluations = 0,
                 const csp::Score* score = nullptr);
  // The same at a known time (a pipeline passing on a stage's own record).
  void record_best(std::uint64_t evaluations, double seconds, const csp::Score* score = nullptr);
  // The improvements noted with a score, when the context asked for the trajectory.
  const std::vector<AnytimePoint>& trajectory() const { return trajectory_; }
  double best_found_seconds() const { return best_seconds_; }          // -1 if never noted
  std::uint64_t evaluations_at_best() const { return best_evaluations_; }

 private:
  double read_clock(std::uint64_t evaluations);

  SolveLimits limits_;
  unsigned clock_stride_;
  unsigned calls_ = 0;
  std::chrono::steady_clock::time_point start_;
  StopReason reason_ = StopReason::kCompleted;
  double last_reading_ = 0;                    // seconds at the last clock reading
  std::uint64_t last_reading_evaluations_ = 0;  // evaluations at that reading
  bool read_once_ = false;
  double best_seconds_ = -1;
  std::uint64_t best_evaluations_ = 0;
  bool keep_trajectory_ = false;
  std::vector<AnytimePoint> trajectory_;
};

// One from-scratch evaluation of an assignment, constraint by constraint: its score and, when
// kept, the per-constraint costs it is the sum of. Kept together so that a solver which must
// verify its final assignment from scratch (sls at a zero-cost assignment) and the result's
// printed score and breakdown share one evaluation instead of making it two or three times.
struct FullEvaluation {
  csp::Score score;
  std::vector<csp::ConstraintCost> breakdown;  // empty unless asked for
};

// Evaluates every constraint once. `score` is bit for bit Problem::score(values) (the same
// sums in the same order); `breakdown`, when `keep_breakdown`, is Problem::breakdown(values).
FullEvaluation evaluate_fully(const csp::Problem& problem, std::span<const double> values,
                              bool keep_breakdown);

// Shared ending: stores score/breakdown of `result.best`, the wall time and the time to best
// (from the budget's note_best; -1 when the solver noted none). Score and breakdown come
// from one evaluate_fully of result.best unless the solver passes `evaluated`: its own
// evaluate_fully of result.best, made from scratch just before it stopped (sls checks a
// zero-cost assignment that way), with the breakdown kept if context.want_breakdown.
void finish_result(const csp::Problem& problem, const SolveContext& context,
                   const Budget& budget, SolverResult& result,
                   std::optional<FullEvaluation> evaluated = std::nullopt);

}  // namespace sightline::solvers
