// ShotSearch (`shot-search`): the composition solver `compose` uses by default.
//
// A shot's cost is flat almost everywhere a generic method starts (a target off screen
// scores 0 whatever the small moves), so the search starts where the properties point:
//   1. candidate positions: around each target at the distance its `distance` or `size`
//      properties ask for (size: the body's height over the image height the fov gives),
//      at the vantage its angle properties ask for (or eight bearings and two elevations
//      when they ask none), around the group's centre likewise, plus a Halton sample of the
//      region and the start; each clamped into the region; with two subjects at screen
//      points, the best exact two-subject pose too (toric_framing.h, on a coarse grid);
//      the vantages' distances first (the group's ring, then each person's), then 15%
//      nearer, then 20% farther, each ring of bearings whole before the next elevation;
//      with a time limit the candidates stop at 40% of it;
//   2. at each, the view aims at the targets (their aim points' centre, then a few Newton
//      steps putting `screen_position` targets at their points), the lens at its mid value;
//      when someone the shot keeps out is on screen there, the view also turned just enough
//      to take them off each edge (a group with someone among them may do best giving up
//      the wanted person on that side);
//   3. the best few are refined by a compass search in (position, aim offset, fov, roll),
//      where the aim offset is relative to the targets' direction, so a step of the camera
//      keeps its framing, with Hooke and Jeeves' pattern move; steps halve until
//      `min_step`, or the budget ends (the coarse refinements stop at 70% of a time limit);
//      the best's fine refinement also polls random directions before halving (the optimum
//      of a shot often lies where two properties' ranges end, a ridge no axis step climbs),
//      every other one turned back so that one person placed on screen stays where they are
//      (the rim of one's screen_position flat zone, followed while another's point is
//      approached); a clear leader among the candidates (at most 3/4 of the runner-up's
//      cost) is refined finely straight after coarsely, before the others; a fine
//      refinement also takes a step that scores the same when it brings a person partly
//      framed nearer the next sample in or out of their rect (Framing::framed_gap): a
//      count is flat between its steps, and the best pose is often one sample away;
//      with a time limit the other candidates follow, then restarts from the best pose
//      shaken.
// Every candidate is scored by the problem itself (the problem's own score, computed with
// one view shared by the properties, and the terms that read the camera's position only
// kept while a step only turns the view), so the result is the problem's optimum as far
// as the search found it, hard constraints first. A point that only has to be compared
// (a step against the pose it would replace, a candidate once `keep` are scored against
// the keep-th best) asks its sight lines and clearance only when the other terms leave it
// able to win (Framing::score_below): the same decisions, fewer queries.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::camera {

struct ShotSearchScratch;
class ToricFraming;

class ShotSearch : public solvers::Solver {
 public:
  struct Options {
    std::int64_t samples = 32;  // Halton positions in the region
    std::int64_t keep = 8;      // candidates refined (coarsely; then the best finely)
    double min_step = 0.005;    // metres and degrees: where the refinement stops
    // false: only refine the start, with steps a quarter of the global ones (a tracking
    // camera's frame: the last pose is nearly right).
    bool global = true;
    // true (with global false): the camera stays where the start is; only the aim offsets,
    // fov and roll are refined (a tracking camera's look from where it is on its way).
    bool hold_position = false;

    static const solvers::OptionSchema<Options>& schema();
    std::string validate() const;
  };

  ShotSearch(std::string name, Options options);
  ~ShotSearch() override;
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const solvers::SolveContext& context, solvers::SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
  solvers::SolverResult toric_result_;  // reused between solves
  std::unique_ptr<ToricFraming> toric_;  // made by the first global solve
  const csp::Problem* toric_checked_ = nullptr;  // the problem toric_suits_ is about
  bool toric_suits_ = false;
  std::unique_ptr<ShotSearchScratch> scratch_;
};

}  // namespace sightline::camera
