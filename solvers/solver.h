// Solver: the one interface every search method implements, with its result and limits.
//
// solve(problem, start, context) -> SolverResult. The start assignment is where local
// methods begin (the camera's current position, or the previous stage of a pipeline); the
// context carries the seed and the limits. Every solver is deterministic for a given seed
// and honours the limits, reporting which one stopped it. Solvers may keep scratch memory
// between calls (a camera solves every frame), so solve() is not const; one Solver object
// is used by one thread at a time.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "csp/problem.h"

namespace sightline::solvers {

// 0 means "no limit" for each field.
struct SolveLimits {
  std::uint64_t max_evaluations = 0;  // constraint-set evaluations (one candidate = one)
  std::uint64_t max_iterations = 0;   // solver-specific steps (moves, passes, nodes)
  double time_limit_seconds = 0;      // wall-clock
};

struct SolveContext {
  std::uint64_t seed = 1;
  SolveLimits limits;
  bool want_breakdown = true;  // fill SolverResult::breakdown (costs an evaluation)
};

enum class StopReason {
  kCompleted,        // the method ran its course (passes done, local optimum, lattice done)
  kProvenOptimal,    // an exact method proved the best is optimal
  kTargetReached,    // a zero-cost feasible assignment was found
  kEvaluationLimit,
  kIterationLimit,
  kTimeLimit,
};
const char* to_string(StopReason reason);

struct SolverResult {
  csp::Assignment best;                        // best assignment found
  csp::Score score;                            // its (hard, soft) score
  std::vector<csp::ConstraintCost> breakdown;  // per-constraint costs of `best`, if asked
  std::uint64_t evaluations = 0;
  std::uint64_t iterations = 0;
  // Exhaustive solvers only (grid, bnb when asked to count): how many assignments reach the
  // best score. 0 when the solver does not count.
  std::uint64_t solutions_at_best = 0;
  double wall_seconds = 0;
  StopReason stop = StopReason::kCompleted;
  std::string message;  // solver-specific detail, may be empty

  bool feasible() const { return score.feasible(); }
  double cost() const { return score.soft; }
  // "sls: cost 0 feasible, 1234 evaluations, 56 iterations, 0.012 s, stop: target reached"
  std::string brief_report(const std::string& solver_name) const;
};

class Solver {
 public:
  virtual ~Solver() = default;
  // The name it was created under (for pipelines: "a>b").
  virtual std::string name() const = 0;
  // Empty when this solver can work on `problem`, else why not ("needs discrete domains").
  virtual std::string unsuitable_reason(const csp::Problem& problem) const;
  // Fills `result` (its vectors are reused, so a per-frame caller need not allocate).
  virtual void solve_into(const csp::Problem& problem, std::span<const double> start,
                          const SolveContext& context, SolverResult& result) = 0;
  SolverResult solve(const csp::Problem& problem, std::span<const double> start,
                     const SolveContext& context = {});
};

// Tracks the limits during a solve. Checking the clock is cheap but not free, so
// exhausted() reads it only every `clock_stride` calls.
class Budget {
 public:
  explicit Budget(const SolveLimits& limits, unsigned clock_stride = 64);
  // True once any limit is reached; `reason()` then says which.
  bool exhausted(std::uint64_t evaluations, std::uint64_t iterations);
  StopReason reason() const { return reason_; }
  double elapsed_seconds() const;

 private:
  SolveLimits limits_;
  unsigned clock_stride_;
  unsigned calls_ = 0;
  std::chrono::steady_clock::time_point start_;
  StopReason reason_ = StopReason::kCompleted;
};

// Shared ending: stores score/breakdown of `result.best` and the wall time.
void finish_result(const csp::Problem& problem, const SolveContext& context,
                   const Budget& budget, SolverResult& result);

}  // namespace sightline::solvers
