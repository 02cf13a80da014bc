// CeresRefineSolver (`ceres-refine`): local refinement of a start point over the continuous
// variables with Ceres' line-search minimiser, for pipelines such as `grid>ceres-refine`.
//
// Why a GradientProblem and not residual blocks: the objective is sum_i w_i v_i(x), a sum of
// weighted violations, not of squares. Residual blocks minimise 1/2 sum r_i^2, so each term
// would need r_i = sqrt(2 w_i v_i), whose derivative is infinite where v_i = 0, exactly at
// the satisfied constraints the optimum is made of. ceres::GradientProblemSolver minimises
// any C1 function from its value and gradient, which every Constraint supplies
// (violation_and_gradient, or its smooth form), so nothing about the kinds leaks in here.
//
// What is minimised (docs/CERES.md tells the whole story):
//   f(x) = sum over soft constraints c touching a free variable of w_c * smooth_c(x, s)
// where smooth_c is Constraint::smooth_violation_and_gradient with width s (`smoothing`):
// |r| becomes sqrt(r^2 + s^2) - s and max(0, r) a Huber-rounded hinge. Free variables are the
// continuous ones with a non-empty interval; discrete ones stay at their start values.
//
// Hard constraints are not in f; the Score puts feasibility first, and the phases follow it:
//  1. restore (only from an infeasible start): minimise f_hard = sum_h w_h v_h(x) with the
//     exact violations: feasibility is a plateau at 0, and the kink at its edge is what lets
//     a step land strictly inside it, where a smoothed hinge would only creep toward it.
//  2. refine: minimise f, guarded: a trial point whose weighted hard violation exceeds the
//     phase's start is reported to Ceres as "cannot evaluate", which makes its line search
//     contract the step, so iterates never leave the feasible region. Safe with any hard
//     constraint (a 0/1 occlusion test too), but a guarded search stalls against a wall.
//     Up to smoothing_rounds rounds, each 10 times less smoothed and starting where the last
//     ended (continuation: a smoothed optimum is O(s) away from a kinked one).
//  3. slide (only when the guard rejected points, and hard_penalty > 0): minimise
//     f + hard_penalty * sum_h w_h v_h(x)^2 without the guard. The quadratic penalty is C1
//     for any hinge-shaped v_h, whatever smooth form the constraint offers, and lets the
//     search slide along walls whose violation has a gradient (a 0/1 test stays flat and
//     costs nothing); its minimiser lies about lambda / (2 penalty w_h) inside the wall
//     (lambda: the wall's Lagrange multiplier), so a restore run (1) pushes it back out, and
//     the result is kept only if better.
//  4. poll (poll_evaluations > 0, and only where the smooth part's projected gradient is not
//     ~0): a derivative-free search on the true Score (ceres_refine_poll.h) that follows the
//     edges Ceres stalls on, 0/1 hard constraints and piecewise-constant soft terms (a
//     visible fraction), which no gradient describes; it only ever moves to better points.
//     If it moved, one more refine round polishes the smooth part from there.
// After each phase the true Score of its best point is compared with the best so far (the
// anchor, initially the start); if it is not better, the segment anchor -> point is bisected
// for the farthest point that is (backoff_steps probes); if none is, the anchor stays. So the
// result is never worse than the start and never less feasible.
//
// Alternatives: after a global solver in a pipeline ("occlusion-octree>ceres-refine"), the
// phases run from the start, then from up to `alternatives` of the previous stage's
// alternatives (SolveContext::alternative_starts: its best points in other basins, which no
// local method can reach across the walls between them), and the best result is kept.
//
// Boxes: Ceres' GradientProblem is unconstrained, so each free variable is written as
//   x = c + r sin(u / r),  c = (lo + hi) / 2,  r = (hi - lo) / 2,  u unbounded,
// which maps R onto [lo, hi] exactly and smoothly (no clamping kinks, no penalty that lets
// points out), keeps x's units near the centre (dx/du = cos(u / r) = 1 at c), and turns an
// active bound into a quadratic well in u: near u = r pi / 2,
//   f ~ f(hi) + |df/dx| (u - r pi / 2)^2 / (2 r),
// so L-BFGS converges to a point on the boundary instead of creeping toward it as a
// logistic map would make it. A start on a bound (where dx/du = 0) is moved kNudgeRadians in
// angle inside so the gradient there is not zero by construction.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sightline/solvers/ceres_refine_poll.h"
#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

namespace detail {

// The largest weighted hard violation that counts as "no less feasible" than `hard`: 0 for a
// feasible level, else `hard` plus round-off.
double hard_tolerance(double hard);
// Whether `score` may replace `anchor`: strictly better, and feasible if the anchor is.
bool improves(const csp::Score& score, const csp::Score& anchor);

// The function Ceres sees, in the unbounded parameters u, without any Ceres type (so tests
// can check its gradient by finite differences). One object per solver, reused across
// solves: reset() sizes it for a problem and start, evaluate() never allocates.
class RefinementObjective {
 public:
  // How far inside a bound a start on the bound is moved, as an angle of the sine map
  // (x moves by r (1 - cos 0.05) = 0.00125 r).
  static constexpr double kNudgeRadians = 0.05;

  // What f sums: the soft constraints (refine), the hard ones (restore; never guarded), or
  // both, the hard ones as hard_penalty w v^2 (slide; never guarded).
  enum class Terms { kSoft, kHard, kSoftAndPenalisedHard };

  // Chooses the free variables, the constraints of f and the guarding hard constraints, and
  // records the start's hard violation. `smoothing` = 0 uses the exact (possibly kinked)
  // violation_and_gradient. Clears the counters and the best point.
  void reset(const csp::Problem& problem, std::span<const double> start, Terms terms,
             double smoothing, bool guard_hard, double hard_penalty = 0);

  // Number of free variables (the dimension of u).
  std::size_t num_parameters() const { return free_.size(); }
  // The free variables, in id order, and the half-widths of their intervals.
  std::span<const csp::VariableId> free_variables() const { return free_; }
  std::span<const double> half_widths() const { return radius_; }
  // Number of constraints in f.
  std::size_t num_terms() const { return terms_.size(); }
  // u of the free variables of `values` (nudged off the bounds).
  void to_parameters(std::span<const double> values, std::span<double> u) const;
  // The whole assignment at u: the start with the free variables replaced.
  void to_assignment(std::span<const double> u, std::span<double> values) const;

  // f(u) and, if `gradient` is not empty, df/du. Returns false, computing nothing, when the
  // evaluation cap is reached; false when a guarding hard constraint is broken more than at
  // the start, or f is not finite. Counts one evaluation per call that computes anything.
  bool evaluate(std::span<const double> u, double& cost, std::span<double> gradient);

  // f and df/dx (over the free variables, in their order) at an assignment that differs from
  // the start only in free variables; never guarded, not recorded as a best point. Counts one
  // evaluation; false as evaluate() when capped or not finite.
  bool evaluate_at(std::span<const double> values, double& cost, std::span<double> gradient_x);

  // 0 = no cap. Calls past the cap return false and set cap_reached().
  void set_evaluation_cap(std::uint64_t cap) { cap_ = cap; }
  bool cap_reached() const { return cap_reached_; }
  std::uint64_t evaluations() const { return evaluations_; }
  // Evaluations refused because a guarding hard constraint was broken more than at the start.
  std::uint64_t guard_rejections() const { return guard_rejections_; }
  // The u with the lowest f among the successful evaluations (the start's u before any).
  std::span<const double> best_parameters() const { return best_u_; }
  double best_cost() const { return best_cost_; }

 private:
  // f and gradient_x_ at values_; false when f is not finite.
  bool smooth_cost(double& cost);

  const csp::Problem* problem_ = nullptr;
  std::vector<csp::VariableId> free_;     // free variables, in id order
  std::vector<std::int32_t> free_index_;  // variable id -> index in free_, or -1
  std::vector<double> centre_, radius_;   // the sine map of each free variable
  std::vector<csp::ConstraintId> terms_;  // the constraints f sums
  std::vector<double> term_weights_;      // their weights in f; < 0: -(p w) of p w v^2
  std::vector<csp::ConstraintId> hard_;   // guards
  double hard_limit_ = 0;                 // largest weighted hard violation accepted
  double smoothing_ = 0;
  bool guard_hard_ = true;
  std::vector<double> values_;          // scratch assignment
  std::vector<double> scope_gradient_;  // scratch, max arity
  std::vector<double> gradient_x_;      // scratch, df/dx per free variable
  std::vector<double> best_u_;
  double best_cost_ = 0;
  std::uint64_t evaluations_ = 0;
  std::uint64_t cap_ = 0;
  bool cap_reached_ = false;
  std::uint64_t guard_rejections_ = 0;
};

}  // namespace detail

class CeresRefineSolver : public Solver {
 public:
  struct Options {
    std::int64_t max_iterations = 100;   // Ceres minimiser iterations, per Ceres run
    double function_tolerance = 1e-10;   // stop when |df| < tol * f (relative)
    double gradient_tolerance = 1e-10;   // stop when the (u-space) gradient max norm < tol
    double parameter_tolerance = 1e-10;  // stop when |step| < tol * (|u| + tol)
    // Width of the rounded kinks, in the units of each constraint's inner quantity; 0 = use
    // the exact violations (fine for already smooth problems).
    double smoothing = 1e-3;
    // Refine rounds (continuation): round k uses smoothing / 10^k and starts where round k-1
    // ended; they stop at the first round that gains nothing.
    std::int64_t smoothing_rounds = 3;
    // lbfgs | bfgs | nonlinear_cg | steepest_descent (Ceres' line search directions).
    std::string line_search_direction = "lbfgs";
    std::int64_t backoff_steps = 30;  // bisection probes of anchor->point when it is worse
    bool guard_hard = true;           // reject trial points that break hard constraints more
    bool restore_feasibility = true;  // phase 1 from an infeasible start
    // p of the slide phase's penalty p w v^2 on hard constraints; 0 = no slide phase.
    double hard_penalty = 1000;
    // In a pipeline, refine also from up to this many of the previous stage's alternatives
    // (SolverResult::alternatives: its best points in other basins) and keep the best.
    std::int64_t alternatives = 2;
    // The poll phase (ceres_refine_poll.h): at most this many Score evaluations; 0 = none.
    std::int64_t poll_evaluations = 300;
    double poll_step = 0.05;       // its first step, as a fraction of each half-width
    double poll_min_step = 5e-4;   // it stops below this step (same units)

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  CeresRefineSolver(std::string name, Options options);
  std::string name() const override { return name_; }
  // Needs at least one continuous variable with a non-empty interval.
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  std::size_t alternatives_wanted() const override {
    return static_cast<std::size_t>(options_.alternatives);
  }
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;
  const Options& options() const { return options_; }

 private:
  using Terms = detail::RefinementObjective::Terms;
  // The phases below from one start; leaves the best point in anchor_ (never worse than the
  // start, nor less feasible) and adds to the result's counts, stop and message.
  void refine_from(const csp::Problem& problem, std::span<const double> start,
                   const SolveContext& context, Budget& budget, SolverResult& result);
  // The poll is skipped where max_i |df/dx_i| (half-width_i), over the components that do not
  // push out of the box at an active bound, is at most this times (1 + |f|): the refine
  // rounds ended on a smooth optimum, with no edge to follow.
  static constexpr double kStationaryGradient = 1e-6;
  // One Ceres run from `from` over `terms`; leaves its best point in candidate_ and returns
  // false when it evaluated nothing (a limit reached, no term). Updates counts, stop, message.
  bool run_ceres(const csp::Problem& problem, std::span<const double> from, Terms terms,
                 double smoothing, bool guard, const SolveContext& context, Budget& budget,
                 SolverResult& result);
  // The true Score of `values`, counted as one evaluation; false (and stop = evaluation
  // limit) when the context's evaluation limit is spent.
  bool judge(const csp::Problem& problem, std::span<const double> values, SolverResult& result,
             csp::Score& score) const;
  // Moves candidate_ (feasible after a push out) toward inside_ (the slide phase's point) as
  // far as it stays as feasible as the anchor, by bisection (backoff_steps probes).
  void bisect_toward_inside(const csp::Problem& problem, SolverResult& result);
  // Makes candidate_ the anchor if it beats it, else the best of the bisection probes of
  // anchor -> candidate that does. Returns whether the anchor moved.
  bool accept_along_segment(const csp::Problem& problem, SolverResult& result);
  // Phase 4: the derivative-free poll from the anchor, then one more refine round if it
  // moved. Skipped where the smooth part is stationary (nothing for the poll to follow).
  void poll_and_refine(const csp::Problem& problem, double smoothing,
                       const SolveContext& context, Budget& budget, SolverResult& result);

  std::string name_;
  Options options_;
  detail::RefinementObjective objective_;
  detail::BoundaryPoll poll_;
  std::vector<double> gradient_;       // scratch, df/dx over the free variables
  std::uint64_t max_evaluations_ = 0;  // the current solve's limit (0 = none)
  std::vector<double> u_;              // Ceres' parameters
  csp::Assignment anchor_;             // best point so far, never worse than the start
  csp::Score anchor_score_;
  csp::Assignment best_;  // the best over the start and the alternatives refined
  csp::Score best_score_;
  csp::Assignment candidate_;  // a phase's best point
  csp::Assignment inside_;     // the slide phase's point, before it is pushed out
  csp::Assignment probe_;      // a bisection probe
  csp::Assignment best_probe_;
};

}  // namespace sightline::solvers
