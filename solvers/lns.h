// LnsSolver (`lns`): large-neighbourhood search for discrete problems: free a neighbourhood
// of variables chosen along the constraint graph and re-optimise it exactly with `bnb`,
// the other variables fixed (toulbar2's VNS/LDS-based "VNS", Loudni & Boizumault's VNS for
// weighted CSPs, with a complete sub-solver bounded by a node limit).
//
// From the start (a pipeline's previous stage, or the given assignment), optionally improved
// by one greedy pass (`greedy_start`: each variable in order takes its best value if that
// lowers the score) and by `tabu` for `tabu_seconds`, each step:
//  1. picks a neighbourhood of k variables: a random variable, then the variables reached
//     from it breadth first through the constraints they share (constraints and scopes
//     visited in random order; another random variable when a component is exhausted);
//  2. conditions the problem on the others' values (detail/conditioned_problem.h) and
//     solves the k-variable problem with `bnb`, created through the registry, its start
//     the current values (so its initial bound is the current cost: it only returns
//     something better, or the current values), at most `node_limit` nodes;
//  3. keeps the result when it is not worse (it never is, unless the current assignment is
//     infeasible and so gives bnb no bound).
// Neighbourhood size, as in variable neighbourhood search: k starts at `min_size`, grows by
// one after each step that brings no improvement, up to `max_size` (0 = every variable),
// then starts over at `min_size` (a "round"); an improvement resets it to `min_size`.
// Optionally (`node_doublings` > 0; off by default, no clear gain measured) bnb's node
// limit grows likewise, as toulbar2's VNS doubles its discrepancy limit when a
// round of sizes brings nothing: `node_limit` doubles after each fruitless round (at most
// `node_doublings` times) and comes back to `node_limit` on an improvement, so a search
// stuck with neighbourhoods too large for the limit searches them deeper instead of
// repeating the same shallow dives. When
// the neighbourhood is the whole problem and bnb completes, the result is proved optimal
// (or the problem infeasible) and the search stops.
//
// Anytime: with any limit set it runs until the limit (or a proof), unless `rounds` caps the
// rounds without improvement (>= 0); with no limit at all it stops after 3 such rounds.
// The message says when the best was found. Iterations count neighbourhoods solved (bnb's
// nodes are not added); evaluations are bnb's (whole candidates scored) plus one per
// neighbourhood result and one per value tried by the greedy pass. Deterministic for a seed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class LnsSolver : public Solver {
 public:
  struct Options {
    std::int64_t min_size = 4;        // smallest neighbourhood, variables (>= 1)
    std::int64_t max_size = 0;        // largest neighbourhood; 0 = every variable
    std::int64_t node_limit = 10000;  // bnb nodes per neighbourhood (>= 1)
    std::int64_t node_doublings = 0;  // node limit doubles per fruitless round, this often
    std::int64_t rounds = -1;         // cap on rounds without improvement; -1 = none when a
                                      // limit is set (3 without)
    bool greedy_start = true;         // one greedy pass over the start first
    double tabu_seconds = 0;          // run `tabu` this long first (0 = not at all)

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  LnsSolver(std::string name, Options options);
  ~LnsSolver() override;
  std::string name() const override { return name_; }
  // Needs every domain discrete.
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;
  const Options& options() const { return options_; }

 private:
  std::string name_;
  Options options_;
  std::unique_ptr<Solver> bnb_, tabu_;  // created on first use, through the registry
};

}  // namespace sightline::solvers
