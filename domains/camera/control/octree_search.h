// OctreeSearch: the sliding-octree passes shared by the camera's two octree solvers.
//
// Bourne's Sliding Octree Solver (thesis table 8): split the current cube into its 8
// octants, score each octant's centre, keep the best candidate seen, shrink the cube by the
// scale factor and slide its centre onto the best candidate, for a fixed number of passes.
// What differs between Bourne's and Ali's versions is which candidates count and how they
// are scored, so this class takes both as settings:
//   - desired orientation and height overrides (Ali sweeps the orientation; Bourne raises
//     the height when his top ray is blocked),
//   - `require_visible`: a candidate counts only if the look-at point is visible from it and
//     it holds every hard constraint (Ali: "evaluate octree node ... if character is visible
//     from the node"); otherwise hard constraints are ignored (Bourne: occlusion is only
//     handled nominally).
// Scoring evaluates the cheap constraints first and stops as soon as a candidate cannot beat
// the best one, so the sight-line queries run only for candidates that matter; the body and
// future visibility counts stop mid-way too (csp::Constraint::violation_until).
// On a level (sight lines answered as Embree ray packets), the expensive constraints are
// asked in the order that drops losing candidates soonest, not in the problem's order: by
// what each says it costs (csp::Constraint::query_cost): the look-at sight line (one ray,
// hard), then the future visibility (K rays in a packet), the body visibility (9 rays),
// and clearance (a point query and the map's solid volume) last. On box
// scenes the view's order stays (reordered, the city with 20 movers measured 2-5% slower).
// In the slowest 2% of frames on oa_thor-walk4, asked in the problem's order, 44% of the
// candidates that reach these tests were dropped by the future visibility, after paying for
// the body's rays and clearance; 23% by the body, 7% by the look-at, 5% by clearance
// (docs/studies/2026-11-24-anticipating-frame-cost.md). The order changes nothing but the
// time: a candidate is dropped only when a lower bound of its cost, the problem-order sum
// with the terms not yet known counted as 0 (floating-point addition is monotone, so that is
// never above the full sum), reaches the bound, and a survivor's cost is summed in the
// problem's order, bit for bit the plain loop's.
// Within a pass, the 8 octants' cheap terms come first, and their sight lines are asked
// cheapest-looking octant first: the likely winner sets the bound before the others pay for
// their rays (in the slowest 1% of frames on a level, 50 of a frame's 67 candidates had
// paid for the body's nine sight lines, asked in child order). The pass keeps the octant
// the loop over children 0..7 would: the cheapest, among equals the lowest child (a lower
// child asked after an equal one is bounded one ulp above it, so it still wins the tie),
// and not one only as cheap as an earlier pass's best. Level walks and box scenes film the
// same traces to the bit; frames take 8-17% less at the median.
// No allocation per candidate.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/control/camera_problem_view.h"

namespace sightline::camera {

struct OctreeSettings {
  int passes = 8;
  double initial_half_size = 0;  // metres; 0 = half the smallest domain width
  double scale = 0.6;            // the cube's size is multiplied by this after each pass
  bool require_visible = true;
};

struct Candidate {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double cost = 0;  // soft cost under the search's overrides
  bool valid = false;
};

class OctreeSearch {
 public:
  OctreeSearch(const csp::Problem& problem, const CameraProblemView& view);

  // A search lives within one solve: the frame's parameters (the character's facing) are
  // read when it is made.
  // Per-search overrides of desired values (nullopt = the problem's own).
  void set_orientation_override(std::optional<double> degrees);
  void set_height_override(std::optional<double> metres) { height_override_ = metres; }

  // Scores one position. With require_visible, invalid candidates (hidden look-at or a
  // broken hard constraint) come back with valid = false. `bound`: stop early once the soft
  // cost reaches it (the result is then only a lower bound, marked invalid).
  Candidate evaluate(const Eigen::Vector3d& p, bool require_visible, double bound);
  // Runs the passes from `centre`; returns the best valid candidate (valid = false if none).
  Candidate run(const Eigen::Vector3d& centre, const OctreeSettings& settings);
  // Half-size of the first cube: `requested` when > 0, else half the smallest domain width
  // (the problem's search box).
  double first_half_size(double requested) const;
  // Clamps a point into the variables' domains.
  Eigen::Vector3d clamp(const Eigen::Vector3d& p) const;

  std::uint64_t evaluations() const { return evaluations_; }

 private:
  // The sum of the soft terms known so far in the view's order (unknown ones are 0): with
  // `skip` >= 0 the terms before `skip` only, into *before, and the single known term after
  // it into *after (0 when there are none or several: then a weaker, still lower, bound).
  double known_cost(double cheap_cost, int skip, double* after) const;
  // evaluate()'s two halves: the constraints without queries (false: a hard one broken,
  // with require_visible), summed into `cost`; then, from that sum, the sight lines and
  // clearance, stopping once the cost reaches `bound`.
  bool cheap_terms(const Eigen::Vector3d& p, bool require_visible, double& cost);
  Candidate expensive_terms(const Eigen::Vector3d& p, bool require_visible, double cheap_cost,
                            double bound);

  static constexpr int kMaxExpensive = 8;
  const csp::Problem* problem_;
  const CameraProblemView* view_;
  // The order the expensive constraints are asked in (indices into view_->expensive()), or
  // none (expensive_count_ = 0: more than kMaxExpensive, asked in the view's order).
  int order_[kMaxExpensive] = {};
  int expensive_count_ = 0;
  // Per candidate: the soft terms (weight x violation) known so far, by view index.
  double term_[kMaxExpensive] = {};
  bool known_[kMaxExpensive] = {};
  std::optional<double> height_override_;
  // The orientation term of this search (the problem's, under the override), with the
  // character's facing computed once, not once a candidate.
  terms::OrientationTerm orientation_;
  terms::OrientationTerm::Facing facing_;
  double values_[3] = {0, 0, 0};
  std::uint64_t evaluations_ = 0;
};

}  // namespace sightline::camera
