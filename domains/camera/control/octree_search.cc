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
  // The sight-line tests, cheapest first (the view's order). Ali: a candidate counts only if
  // the look-at point is visible from it (whether the profile makes that constraint hard or
  // soft), and only if it breaks no hard constraint. The soft counts stop as soon as the
  // candidate has lost (BoundedViolation): the same candidates survive, with the same sums.
  const std::vector<csp::ConstraintId>& expensive = view_->expensive();
  for (std::size_t i = 0; i < expensive.size(); ++i) {
    const csp::ConstraintId id = expensive[i];
    const csp::Constraint& c = problem_->constraint(id);
    const BoundedViolation* bounded = view_->expensive_bounded()[i];
    const double violation = bounded && !c.is_hard() ? bounded->violation_until(x, out.cost, bound)
                                                     : c.violation(x);
    if (violation > 0 && (id == view_->look_at_id() || c.is_hard())) return out;
    if (c.is_hard()) continue;
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
