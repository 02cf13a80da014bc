// SlidingOctreeSolver (`sliding-octree`): Bourne's Sliding Octree Solver, the search of the
// original reactive chase camera (Bourne & Sattar 2006; Ali 2007, section 3.2, table 8),
// generalised from 3 to any number d of continuous variables.
//
// The search space is a box (the "octree") of edge length size_k per dimension, centred on
// the start, i.e. the camera's current position. Each pass splits the box into 2^d children
// (8 in 3-D) and evaluates each child's centre, centre_k +- size_k / 4; the best candidate
// ever seen is kept. Then, as in table 8,
//   size   <- size * scale                          (reduce the domain size)
//   centre <- centre + (best - centre) * slide      (slide toward the best solution)
// clamped to the domains. With slide = 1 the next box is centred on the best child and, as
// scale >= 1/2, covers the best child's region plus a margin around it: "the selected region
// and the surrounding area of the selected region" of the thesis. After `passes` passes the
// best candidate is returned. Table 8's "slide direction * domain size" reads a normalised
// domain size; `slide` makes that factor explicit.
//
// The start itself is evaluated first, so the result is never worse than where the camera
// already is. Reach: with slide = 1 the centre can travel at most
// sum_p size_p / 4 = initial_size / (4 (1 - scale)) from the start, so this is a local,
// frame-to-frame method, as Bourne meant it. Scores are compared lexicographically
// (csp::Score), so a feasible candidate always beats an infeasible one. Deterministic: it
// uses no random numbers. Unsuitable for problems with discrete variables, and above
// kMaxDimensions (2^d children per pass).
//
// Initial size: `initial_size` is a fraction of each domain's width (default 0.5); a
// positive `initial_size_absolute` overrides it with one edge length, in the variables' own
// units, for every dimension (metres for a camera position).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class SlidingOctreeSolver : public Solver {
 public:
  static constexpr std::size_t kMaxDimensions = 16;  // 65,536 children per pass

  struct Options {
    std::int64_t passes = 8;           // number of passes (>= 1)
    double initial_size = 0.5;         // edge length as a fraction of each domain's width
    double initial_size_absolute = 0;  // > 0: edge length in the variables' units instead
    double scale = 0.6;                // size multiplier per pass, in [0.5, 1)
    double slide = 1.0;                // fraction of the way to the best, in (0, 1]

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  SlidingOctreeSolver(std::string name, Options options);
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
  // Scratch, reused between solves (a camera solves every frame).
  std::vector<double> centre_, size_, candidate_;
};

}  // namespace sightline::solvers
