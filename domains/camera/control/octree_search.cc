#include "sightline/domains/camera/control/octree_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sightline::camera {

OctreeSearch::OctreeSearch(const csp::Problem& problem, const CameraProblemView& view)
    : problem_(&problem),
      view_(&view),
      orientation_(view.orientation().term()),
      facing_(orientation_.facing()) {
  const std::vector<csp::ConstraintId>& expensive = view.expensive();
  if (expensive.size() > static_cast<std::size_t>(kMaxExpensive)) return;
  expensive_count_ = static_cast<int>(expensive.size());
  for (int i = 0; i < expensive_count_; ++i) order_[i] = i;
  // On box scenes the counts stop early ray by ray and the view's order measured as fast
  // (the city with 20 movers: 2-5% slower at p99 reordered); levels answer in packets.
  if (!view.scene().packs_sight_lines()) return;
  std::stable_sort(order_, order_ + expensive_count_, [&](int a, int b) {
    return problem.constraint(expensive[static_cast<std::size_t>(a)]).query_cost() <
           problem.constraint(expensive[static_cast<std::size_t>(b)]).query_cost();
  });
}

double OctreeSearch::known_cost(double cheap_cost, int skip, double* after) const {
  double sum = cheap_cost;
  int after_count = 0;
  double after_term = 0;
  for (int i = 0; i < expensive_count_; ++i) {
    if (!known_[i]) continue;
    if (skip >= 0 && i > skip) {
      ++after_count;
      after_term = term_[i];
      continue;
    }
    sum += term_[i];
  }
  if (after != nullptr) *after = after_count == 1 ? after_term : 0.0;
  return sum;
}

Eigen::Vector3d OctreeSearch::clamp(const Eigen::Vector3d& p) const {
  Eigen::Vector3d q;
  for (int i = 0; i < 3; ++i) q[i] = problem_->domain(i).clamp(p[i]);
  return q;
}

void OctreeSearch::set_orientation_override(std::optional<double> degrees) {
  orientation_.desired_degrees = degrees ? *degrees : view_->orientation().term().desired_degrees;
}

Candidate OctreeSearch::evaluate(const Eigen::Vector3d& p, bool require_visible, double bound) {
  double cheap_cost = 0;
  if (!cheap_terms(p, require_visible, cheap_cost)) return Candidate{p, cheap_cost, false};
  return expensive_terms(p, require_visible, cheap_cost, bound);
}

bool OctreeSearch::cheap_terms(const Eigen::Vector3d& p, bool require_visible, double& cost) {
  ++evaluations_;
  values_[0] = p.x();
  values_[1] = p.y();
  values_[2] = p.z();
  const std::span<const double> x(values_, 3);
  cost = 0;
  for (csp::ConstraintId id : view_->cheap()) {
    const csp::Constraint& c = problem_->constraint(id);
    double violation;
    if (id == view_->orientation_id()) {
      // The constraint's own term (AbsTermConstraint: |term(cam_x, cam_z)|), its facing
      // taken once a search, under the override when there is one.
      const double xz[2] = {p.x(), p.z()};
      violation = std::abs(orientation_.at(facing_, xz));
    } else if (id == view_->height_id() && height_override_) {
      auto term = view_->height().term();
      term.desired = *height_override_;
      const double y = p.y();
      violation = std::abs(term(&y));
    } else {
      violation = c.violation(x);
    }
    if (c.is_hard()) {
      if (require_visible && violation > 0) return false;
      continue;  // Bourne's search ignores hard constraints
    }
    cost += c.weight() * violation;
  }
  return true;
}

Candidate OctreeSearch::expensive_terms(const Eigen::Vector3d& p, bool require_visible,
                                        double cheap_cost, double bound) {
  const std::span<const double> x(values_, 3);
  values_[0] = p.x();
  values_[1] = p.y();
  values_[2] = p.z();
  Candidate out{p, cheap_cost, false};
  if (out.cost >= bound) return out;
  if (!require_visible) {
    // Bourne's search scores only the profile's terms: no sight lines, no clearance.
    out.valid = true;
    return out;
  }
  // The sight-line tests. Ali: a candidate counts only if the look-at point is visible from
  // it (whether the profile makes that constraint hard or soft), and only if it breaks no
  // hard constraint. Asked in order_ (see the header); the soft counts stop as soon as the
  // candidate has lost (csp::Constraint::violation_until): the same candidates survive, with
  // the same sums.
  const std::vector<csp::ConstraintId>& expensive = view_->expensive();
  if (expensive_count_ > 0) {
    for (int i = 0; i < expensive_count_; ++i) known_[i] = false;
    for (int k = 0; k < expensive_count_; ++k) {
      const int i = order_[k];
      const csp::ConstraintId id = expensive[static_cast<std::size_t>(i)];
      const csp::Constraint& c = problem_->constraint(id);
      double violation;
      if (!c.is_hard()) {
        double after = 0;
        const double before = known_cost(cheap_cost, i, &after);
        violation = c.violation_until(x, before, bound, after);
      } else {
        violation = c.violation(x);
      }
      if (violation > 0 && (id == view_->look_at_id() || c.is_hard())) return out;
      if (c.is_hard()) continue;
      term_[i] = c.weight() * violation;
      known_[i] = true;
      if (known_cost(cheap_cost, -1, nullptr) >= bound) return out;
    }
    // Every soft term known: the sum in the view's order, as the loop below makes it.
    out.cost = known_cost(cheap_cost, -1, nullptr);
    if (out.cost >= bound) return out;
    out.valid = true;
    return out;
  }
  for (std::size_t i = 0; i < expensive.size(); ++i) {
    const csp::ConstraintId id = expensive[i];
    const csp::Constraint& c = problem_->constraint(id);
    const double violation =
        c.is_hard() ? c.violation(x) : c.violation_until(x, out.cost, bound, 0.0);
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
    // The octants' centres are the cube's centre +- half/2 on each axis, their cheap terms
    // first; then the sight lines, cheapest-looking octant first (see the header). The
    // pass keeps the octant the plain loop over children 0..7 keeps: the cheapest, the
    // lowest child among equals, and not one only as cheap as an earlier pass's best.
    const double q = 0.5 * half;
    std::array<Eigen::Vector3d, 8> at;
    std::array<double, 8> cheap{};
    std::array<int, 8> order{};
    int count = 0;
    for (int child = 0; child < 8; ++child) {
      const Eigen::Vector3d offset((child & 1) ? q : -q, (child & 2) ? q : -q,
                                   (child & 4) ? q : -q);
      at[child] = clamp(centre + offset);
      if (!cheap_terms(at[child], settings.require_visible, cheap[child])) continue;
      int k = count++;  // insertion by (cheap cost, child): stable, so equals keep their order
      for (; k > 0 && cheap[order[k - 1]] > cheap[child]; --k) order[k] = order[k - 1];
      order[k] = child;
    }
    int pass_best = -1;  // the child this pass has kept so far
    for (int k = 0; k < count; ++k) {
      const int child = order[k];
      // A lower child than the one kept wins a tie, as it would have come first.
      const bool tie_wins = pass_best >= 0 && child < pass_best;
      const double bound =
          tie_wins ? std::nextafter(best.cost, std::numeric_limits<double>::infinity()) : best.cost;
      const Candidate c = expensive_terms(at[child], settings.require_visible, cheap[child], bound);
      if (c.valid && c.cost < bound) {
        best = c;
        pass_best = child;
      }
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
