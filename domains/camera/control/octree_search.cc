#include "domains/camera/control/octree_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline::camera {

OctreeSearch::OctreeSearch(const csp::Problem& problem, const CameraProblemView& view)
    : problem_(&problem), view_(&view) {}

Eigen::Vector3d OctreeSearch::clamp(const Eigen::Vector3d& p) const {
  Eigen::Vector3d q;
  for (int i = 0; i < 3; ++i) q[i] = problem_->domain(i).clamp(p[i]);
  return q;
}

Candidate OctreeSearch::evaluate(const Eigen::Vector3d& p, bool require_visible, double bound) {
  ++evaluations_;
  values_[0] = p.x();
  values_[1] = p.y();
  values_[2] = p.z();
  const std::span<const double> x(values_, 3);
  Candidate out{p, 0, false};
  for (csp::ConstraintId id : view_->cheap()) {
    const csp::Constraint& c = problem_->constraint(id);
    double violation;
    if (id == view_->orientation_id() && orientation_override_) {
      auto term = view_->orientation().term();
      term.desired_degrees = *orientation_override_;
      const double xz[2] = {p.x(), p.z()};
      violation = std::abs(term(xz));
    } else if (id == view_->height_id() && height_override_) {
      auto term = view_->height().term();
      term.desired = *height_override_;
      const double y = p.y();
      violation = std::abs(term(&y));
    } else {
      violation = c.violation(x);
    }
    if (c.is_hard()) {
      if (require_visible && violation > 0) return out;
      continue;  // Bourne's search ignores hard constraints
    }
    out.cost += c.weight() * violation;
  }
  if (out.cost >= bound) return out;
  if (!require_visible) {
    // Bourne's search scores only the profile's terms: no sight lines, no clearance.
    out.valid = true;
    return out;
  }
  // The sight-line tests, in two rounds that decide exactly what one loop over
  // expensive() in order would (a candidate is dropped by the first failure, whichever
  // comes first, and a survivor's cost is the same sum in the same order), but cheapest to
  // fail first. Ali: a candidate counts only if the look-at point is visible from it
  // (whether the profile makes that constraint hard or soft), and only if it breaks no hard
  // constraint.
  const std::vector<csp::ConstraintId>& expensive = view_->expensive();
  const csp::ConstraintId look_at = view_->look_at_id();
  //   1. The look-at sight line (one ray) and the other hard ones (clearance: one nearest
  //      query), before any soft count of 5 to 9 rays is paid for a candidate that fails.
  if (problem_->constraint(look_at).violation(x) > 0) return out;
  for (csp::ConstraintId id : expensive) {
    const csp::Constraint& c = problem_->constraint(id);
    if (id != look_at && c.is_hard() && c.violation(x) > 0) return out;
  }
  //   2. The soft ones in the view's order, each stopping as soon as the candidate has lost
  //      (BoundedViolation; a soft look-at term adds weight x 0 here and is skipped).
  for (std::size_t i = 0; i < expensive.size(); ++i) {
    const csp::ConstraintId id = expensive[i];
    const csp::Constraint& c = problem_->constraint(id);
    if (id == look_at || c.is_hard()) continue;
    const BoundedViolation* bounded = view_->expensive_bounded()[i];
    const double violation = bounded ? bounded->violation_until(x, out.cost, bound)
                                     : c.violation(x);
    out.cost += c.weight() * violation;
    if (out.cost >= bound) return out;
  }
  out.valid = true;
  return out;
}

double OctreeSearch::first_half_size(double requested) const {
  if (requested > 0) return requested;
  double half = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const auto& d = problem_->domain(i);
    half = std::min(half, 0.5 * (d.upper() - d.lower()));
  }
  return half;
}

Candidate OctreeSearch::run(const Eigen::Vector3d& start, const OctreeSettings& settings) {
  double half = first_half_size(settings.initial_half_size);
  Eigen::Vector3d centre = clamp(start);
  Candidate best;
  best.cost = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass < settings.passes; ++pass) {
    // The octants' centres are the cube's centre +- half/2 on each axis.
    const double q = 0.5 * half;
    for (int child = 0; child < 8; ++child) {
      const Eigen::Vector3d offset((child & 1) ? q : -q, (child & 2) ? q : -q,
                                   (child & 4) ? q : -q);
      const Candidate c = evaluate(clamp(centre + offset), settings.require_visible, best.cost);
      if (c.valid && c.cost < best.cost) best = c;
    }
    // Table 9: "if current calculated best solution is occluded then try next desired
    // orientation value": without a valid candidate the caller moves on.
    if (!best.valid) break;
    half *= settings.scale;
    centre = best.position;  // slide onto the selected region
  }
  return best;
}

}  // namespace sightline::camera
