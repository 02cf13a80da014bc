// SlsSolver (`sls`): stochastic local search, for discrete, continuous and mixed problems.
//
// Discrete problems (every domain discrete): min-conflicts. Each step picks a variable in
// conflict (IncrementalEvaluator::involvement > 0, from a list refreshed by full scans) and
// moves it to its best value among the candidates (all values, or `value_samples` random
// ones for large domains), scored by O(1) deltas; ties are broken at random and sideways
// moves are allowed. When the variable has neither an improving nor a sideways move, with
// probability `walk_probability` it takes a random value anyway (random walk out of the
// local minimum). Tabu: a move that does not improve the score may not give a variable back
// the value it left less than `tabu_tenure` steps ago. After `stall_moves` steps without
// improving the run's best the search restarts from a random assignment (see "Anytime"
// below for how many times).
//
// Permutation structure (see detail/permutation_groups.h): variables tied by a hard
// all_different whose domains are exactly its k values are kept a permutation. The search
// starts from one (the start's if it is one, else a random one) and moves by swapping two
// variables' values, a swap being two assigns scored through the evaluator and reverted if
// rejected. Partners are screened first by the cheap half of the swap, delta(v -> the
// partner's value), which reads only v's side of the constraints; only the best-screened
// partners are tried for real (improving first, else sideways).
//
// The all_different that makes a group is satisfied by every permutation, so the evaluator
// is told it is constant and never follows it (one constraint fewer per move).
//
// Greedy start (`greedy_start`): one pass over the variables in order. A variable in conflict
// tries `greedy_samples` values and takes the best if it lowers the score. A group whose
// values were dealt at random (the start was not a permutation, or a restart) is rebuilt by
// constructive placement (detail/group_placement.h: Sosic & Gu's placement, each variable
// taking a value that adds no cost given the ones already placed, `placement_attempts` draws
// per variable) when its constraints support partial assignments. Otherwise, and for a
// start that already was a permutation (its structure is kept), each group variable in
// conflict swaps with the first of up to `greedy_samples` later partners (drawn from the
// next `greedy_window` ones, which keeps the memory traffic local) after which it is in no
// conflict at all, the partner taking over its conflicts until its own turn. Partners are
// screened by the half swap and only strict improvements of v's half are tried.
//
// Continuous and mixed problems: random-neighbourhood search. From the current point, a
// candidate moves every variable by a Gaussian step of standard deviation radius x its
// domain's width (discrete variables move along their value indices); an improving
// candidate is accepted, and after `patience` failures in a row the radius shrinks by
// `shrink`; below `min_radius` the search restarts from a uniform random point. The first
// run starts from the given start.
//
// Anytime: both stop at a zero-cost feasible assignment (kTargetReached) when
// `stop_at_zero`, the one optimum they can recognise. Otherwise they restart without end and
// stop when a limit of the context is reached (its reason), reporting the best found and when
// (SolverResult::best_found_seconds). `restarts` > 0 caps the restarts (kCompleted once they
// are used up). With no limit and no cap (or as a stage before the last of a pipeline, see
// SolveContext::anytime) they make kDefaultRestarts restarts and the message says so: a solve
// must end, and this is the short run the camera makes every frame. Deterministic for a
// given seed. Evaluations count candidates scored (a delta, a swap, a point); iterations
// count steps.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class SlsSolver : public Solver {
 public:
  struct Options {
    // Discrete search.
    double walk_probability = 0.02;    // chance of a random move at a local minimum, [0, 1]
    std::int64_t tabu_tenure = 10;     // steps a left value stays forbidden to sideways moves
    std::int64_t value_samples = 32;   // candidate values per step when a domain is larger
    std::int64_t swap_samples = 16;    // swap partners tried per step in a permutation group
    bool permutation_moves = true;     // use the swap neighbourhood where the structure allows
    bool greedy_start = true;          // one greedy repair pass at each (re)start
    std::int64_t greedy_samples = 64;  // values or partners tried per variable in that pass
    std::int64_t greedy_window = 256;  // partners come from the next this-many group
                                       // variables (cache-friendly); 0 = all later ones
    double placement_attempts = 3.08;  // constructive placement of a randomly dealt group:
                                       // draws per variable (Sosic & Gu's 3.08); 0 = off
    std::int64_t stall_moves = 0;      // steps without progress before a restart; 0 = auto
                                       // (10 x variables + 1000)
    // Both.
    std::int64_t restarts = 0;   // cap on the restarts after a stall (discrete) or a
                                 // collapsed radius; 0 = none (see "Anytime" above)
    bool stop_at_zero = true;    // stop at a zero-cost feasible assignment
    // Continuous search.
    double initial_radius = 0.25;  // step scale as a fraction of each domain's width
    double min_radius = 1e-6;      // below this (same unit) the run restarts
    double shrink = 0.5;           // radius multiplier after `patience` failures, (0, 1)
    std::int64_t patience = 8;     // failed candidates in a row before shrinking

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  // The restarts made when there is neither a limit nor a cap.
  static constexpr std::int64_t kDefaultRestarts = 10;
  // The restart cap of a solve in `context`: `restarts` when set, else 0 (none) when the
  // solve runs to a limit, else kDefaultRestarts.
  std::uint64_t restart_cap(const SolveContext& context) const;

  SlsSolver(std::string name, Options options);
  std::string name() const override { return name_; }
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;
  const Options& options() const { return options_; }

 private:
  std::string name_;
  Options options_;
  // Scratch of the continuous search, reused between solves.
  std::vector<double> current_, candidate_;
};

}  // namespace sightline::solvers
