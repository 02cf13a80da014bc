// BranchAndBoundSolver (`bnb`): exact depth-first branch and bound for discrete problems.
//
// It either proves the best assignment optimal (stop = kProvenOptimal), proves that no
// assignment satisfies every hard constraint (kCompleted, with a message saying so), or
// stops at a limit with the best assignment found (the limit's stop reason; "not proved").
// Nodes (variable assignments tried) count as iterations.
//
// The search, in the words of the weighted-CSP literature: depth-first search with
// forward checking and directed arc inconsistency counts (PFC-DAC, Freuder & Wallace 1992,
// Larrosa & Meseguer 1996), on every kind of constraint:
//  - Lower bound of a node:
//        lb = g + sum over future u of min over alive a of (ic(u, a) + dac(u, a))
//    g: the cost of the constraints whose scope is fully assigned;
//    ic(u, a): the cost of the constraints whose only unassigned variable is u, if u = a
//      (their "projection" on u, computed with violation() when the next-to-last variable
//      of the scope is assigned; a unary constraint is projected at the root);
//    dac(u, a): bounds lent to u by the soft constraints with two or more unassigned
//      variables, each constraint to one of them only (its "target"): the least cost of
//      the constraint with u = a, exact over the other variable's alive values when two
//      are unassigned, Constraint::min_violation() (u = a added) otherwise.
//    Every constraint counts in one term only, so lb never exceeds the cost of any
//    completion. A node is pruned when lb >= ub, the incumbent's soft cost (lb > ub when
//    counting optimal solutions, so every optimum is visited), and so is a value whose own
//    bound, added to the other variables', reaches ub.
//  - Hard constraints prune: a value whose projection breaks a hard constraint is removed
//    from its variable's domain, and so is a value a of u for which a hard constraint with
//    several unassigned variables has min_violation > 0 once u = a is added (forward
//    checking on n-ary constraints, through the same min_violation). An emptied domain ends
//    the branch. Only feasible assignments are ever reached, so comparing soft costs of
//    feasible assignments is the lexicographic (hard, soft) order of csp::Score.
//  - Variable ordering: smallest remaining domain divided by (1 + number of constraints
//    shared with other unassigned variables) ("dom/deg"), ties to the lower id. Value
//    ordering: increasing ic + dac, so cheap values come first; the loop stops at the first
//    value whose bound reaches ub (all later ones are no cheaper).
//  - Initial upper bound: the start assignment's score when it is feasible (so a pipeline
//    `sls>bnb` starts from what sls found and only looks for better).
// Everything the search changes is recorded on a trail and undone on backtrack (rows of ic
// and contributions are saved and restored, never recomputed by subtraction, so no
// round-off builds up); the search allocates nothing per node once its buffers have grown
// (what a kind's violation() does is its own business). The search itself is
// solvers/detail/bnb_search.h.
//
// Costs are compared with a relative tolerance of 1e-9 (integer costs are exact).
//
// Soft arc consistency (option `consistency`, default edac): when the problem is a weighted
// CSP with integer costs (constraints of arity 1 or 2 of any kind, n-ary tables and
// all_differents, every weighted cost integral: solvers/detail/bnb_wcsp_view.h), the search
// above is replaced by depth-first binary branching maintaining NC*, AC*, FDAC* or EDAC*
// (solvers/detail/bnb_soft_arc.h, bnb_soft_search.h): a far stronger bound (c0 after cost
// moves between constraints), value ordering by unary cost, dom/wdeg variable ordering
// (last-conflict optional), no branching on a variable whose cost functions all have their
// other variables fixed (it takes its cheapest value; not when counting optima). Any other
// problem, or `consistency: none`, uses the
// forward-checking search described above. docs/WCSP.md compares both with toulbar2.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

namespace detail {
class BranchAndBoundSearch;
class SoftArcSearch;
struct WcspView;
}  // namespace detail

class BranchAndBoundSolver : public Solver {
 public:
  struct Options {
    // Count the assignments reaching the optimum (SolverResult::solutions_at_best). The
    // search then prunes only with lb > ub, which visits every optimal assignment.
    bool count_optimal = false;
    // Use the start assignment's score, when it is feasible, as the initial upper bound.
    bool use_start_bound = true;
    // Soft arc consistency on integer-cost WCSPs: none, nc, ac, fdac or edac.
    std::string consistency = "edac";
    // With soft arc consistency: branch again on the variable whose assignment last failed.
    bool last_conflict = false;

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  BranchAndBoundSolver(std::string name, Options options);
  ~BranchAndBoundSolver() override;
  std::string name() const override { return name_; }
  // Needs every domain discrete.
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;
  const Options& options() const { return options_; }

 private:
  std::string name_;
  Options options_;
  std::unique_ptr<detail::BranchAndBoundSearch> search_;  // scratch, reused across solves
  std::unique_ptr<detail::WcspView> view_;
  std::unique_ptr<detail::SoftArcSearch> soft_search_;
};

}  // namespace sightline::solvers
