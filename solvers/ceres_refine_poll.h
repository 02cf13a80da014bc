// BoundaryPoll: ceres-refine's derivative-free phase, which follows the edges Ceres cannot see.
//
// Ceres minimises the smooth part of the objective from its gradient. Two kinds of terms have
// no useful gradient: 0/1 hard constraints (a sight line is blocked or not) and piecewise-
// constant soft terms (the fraction of sample rays that reach the character, in steps of
// 1/9). Where the smooth part's descent direction crosses such an edge, every step Ceres
// tries lands on a jump, its line search shrinks the step to nothing, and it stops right on
// the edge although a feasible, cheaper point lies a little way along it. Measured on the
// camera frames of bench/solver_quality: half of the frames the pipeline missed were such
// stalls, with a straight, feasible, descending segment to the reference optimum.
//
// The remedy is a direct search on the true Score, in the manner of OrthoMADS (Abramson,
// Audet, Dennis & Le Digabel, SIAM J. Optim. 2009), helped by the smooth part's gradient g.
// Coordinates are scaled by S = diag(half-widths of the free variables), so a step h is a
// fraction of each interval; g below is the scaled, unit gradient. Each iteration, from the
// anchor x with step h, tries until one improves the Score (Score::better_than, and never
// less feasible), and moves there:
//  1. the last successful direction again (along a straight edge it keeps succeeding);
//  2. x + h S d for d = +-(columns of H), H = I - 2 v v^T with v a fresh random unit vector,
//     in the order of their slope g.d (most negative first). H is orthogonal, so the 2n
//     directions are a positive basis, and as v changes every iteration they become dense:
//     no fixed set of edges blocks them all, as edges can block the compass +-e_i;
//  3. the edge's tangent: with w = v made orthogonal to g, the directions
//     d(t) = cos t (-g) + sin t (+-w) for t = 90 (1 - 2^-k) degrees, k = 1..10, then
//     bisection of t between the last that failed and the first that improved. At an edge
//     that blocks -g, the improving directions form a wedge between the edge and the level
//     set of the smooth part; when -g is nearly normal to the edge (the usual stall) the
//     wedge is a few degrees wide and random directions seldom fall in it, but the fan
//     brackets its side. Along d(t) the smooth part falls at rate cos t, so d(t) is tried
//     with the step h sqrt(2) cos t: shorter near the tangent, where the curvature would
//     otherwise eat the gain.
// On success h doubles (up to 4 times the initial step); after an iteration without one it
// shrinks by kShrink = 0.7 (more rotations per decade of step than halving); the poll ends
// below the minimum step, after max_failures failed iterations in a row (stagnation: the
// fans have then tried steps down to h / 400 near the tangent), or at its evaluation budget.
// Cost: up to 2n + 22 evaluations per iteration; about 5 (2n + 20) where nothing improves.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::solvers::detail {

class BoundaryPoll {
 public:
  static constexpr double kShrink = 0.7;  // step factor after an iteration without success

  struct Settings {
    double initial_step = 0.05;  // h at the start, as a fraction of each half-width, > 0
    double min_step = 5e-4;      // stop once h falls below this, > 0
    std::uint64_t max_evaluations = 300;  // Score evaluations of this phase, > 0
    // Stagnation: stop after this many iterations in a row without success, > 0.
    int max_failures = 5;
    std::uint64_t seed = 1;               // for the rotations v
  };
  // What the poll asks of its caller.
  class Target {
   public:
    virtual ~Target() = default;
    // The Score of an assignment, counted by the caller (Settings::max_evaluations counts
    // these calls); false when the caller's evaluation limit is spent (the poll then stops).
    virtual bool judge(std::span<const double> values, csp::Score& score) = 0;
    // The smooth part's gradient df/dx over the free variables at `values`, used only to
    // order the directions; false when it cannot be computed (they keep their order).
    virtual bool gradient(std::span<const double> values, std::span<double> g) = 0;
  };

  // Moves `anchor` (whose Score is `anchor_score`) to better points and returns whether it
  // moved. `free` are the variables it may change, `half_widths` their scales (> 0).
  // Never allocates after the first call with a given size.
  bool run(const csp::Problem& problem, std::span<const csp::VariableId> free,
           std::span<const double> half_widths, const Settings& settings, Target& target,
           std::vector<double>& anchor, csp::Score& anchor_score);

 private:
  static constexpr int kTangentScan = 10;  // t = 45, 67.5, ..., 89.9 degrees
  static constexpr int kTangentBisections = 5;  // then t to 1/32 of its bracket

  // Fills probe_ with anchor + h S d (clamped to the domains) and judges it; false when the
  // probe equals the anchor (nothing evaluated) or the caller refused (`refused` = true).
  bool try_direction(const csp::Problem& problem, std::span<const csp::VariableId> free,
                     std::span<const double> half_widths, std::span<const double> d, double h,
                     const std::vector<double>& anchor, Target& target, csp::Score& score,
                     bool& refused);

  std::vector<double> v_, g_, d_, last_, best_d_, slope_, probe_, best_probe_;
  std::vector<std::uint32_t> order_;  // direction k: column k / 2, sign + for even k
  std::uint64_t evaluations_ = 0;
};

}  // namespace sightline::solvers::detail
