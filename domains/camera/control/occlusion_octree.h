// OcclusionOctreeSolver ("occlusion-octree"): Ali's occlusion-aware sliding octree (thesis
// table 9, section 3.3), the solver that keeps the character in view.
//
//   1. Sliding-octree passes from the current camera position in which a candidate counts
//      only if the look-at point is visible from it (one ray, character -> candidate) and it
//      breaks no hard constraint (clearance).
//   2. If no candidate is visible, the desired orientation is changed in steps of
//      `sweep_step` degrees, alternately above and below the profile's value (the angle is
//      unsigned, 0..180, so both sides of the character are covered), and the search is
//      repeated, until a visible candidate is found.
//   3. The points `probe_distance` in front of and behind the best (along the horizontal
//      camera -> character direction) are tried, and kept if cheaper and visible.
// The smooth move toward the result, the cuts and the area adaptation are the controller's
// job (ChaseCamera), as they are for every solver. Only works on camera problems.
//
// Alternatives (only when a later pipeline stage asks, SolveContext::alternatives_wanted;
// the chase camera's per-frame path never does, so it pays nothing): the passes above are
// greedy, they commit to the best octant of the first cube after 8 candidates, and the
// camera's cost landscape is cut by occluders into basins a local refiner cannot cross
// (bench/solver_quality: on the frames the pipeline missed, the optimum lay on another side
// of an occluder). So the search is also run from each octant of the first cube (half its
// size, under the orientation the main search settled on), and every run's best is a
// candidate, as is the main search's result (after its probes). The cheapest becomes
// `best`, so asking never makes it worse; the next cheapest ones, skipping any closer than a
// quarter of the first cube's half-size to the best or to one already chosen (the same
// basin), are the alternatives. 8 more runs of `passes` x 8 candidates each: about 9 times
// the work of a plain solve.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sightline/domains/camera/control/camera_problem_view.h"
#include "sightline/domains/camera/control/octree_search.h"
#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::camera {

class OcclusionOctreeSolver : public solvers::Solver {
 public:
  struct Options {
    std::int64_t passes = 8;
    double initial_size = 0;   // half-size of the first cube, metres; 0 = the search box
    double scale = 0.6;        // cube shrink per pass, (0, 1)
    double sweep_step = 10;    // degrees
    double probe_distance = 1; // metres
    bool include_start = true; // also score the current position (keeps a good shot still)
    static const solvers::OptionSchema<Options>& schema();
    std::string validate() const;
  };

  OcclusionOctreeSolver(std::string name, Options options)
      : name_(std::move(name)), options_(options) {}
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const solvers::SolveContext& context, solvers::SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
  CameraProblemViewCache views_;
  std::vector<Candidate> explored_;  // scratch: the runs' bests when alternatives are asked
};

}  // namespace sightline::camera
