// BoundedViolation: a violation that can stop being computed once it no longer matters.
//
// The camera's octree searches score a candidate by summing weight x violation and drop it
// as soon as the sum reaches the best cost found so far. The body-visibility and
// future-visibility constraints count blocked sight lines (9 and K rays), so most of their
// time goes on candidates that lose anyway. A constraint with this interface is told the
// cost summed before it, the cost of the one term known to come after it in the sum (0 when
// none is known; a search that asks the constraints out of the sum's order knows some), and
// the bound, and may stop counting as soon as a lower bound v of its violation already
// gives (cost_before + weight x v) + cost_after >= bound.
//
// Exactness: when it does not stop, it returns exactly violation(values), computed the same
// way, so a candidate that survives is scored to the last bit as before. When it stops, the
// lower bound is the same expression evaluated with the rays not yet tested counted as
// clear; floating-point rounding is monotone, so the full violation (and the full sum) is
// at least as large, and the candidate would have been dropped at that constraint anyway.
#pragma once

#include <span>

namespace sightline::camera {

class BoundedViolation {
 public:
  virtual ~BoundedViolation() = default;
  // violation(values), or a lower bound v of it with
  // (cost_before + weight() x v) + cost_after >= bound.
  virtual double violation_until(std::span<const double> values, double cost_before,
                                 double bound, double cost_after) const = 0;

 protected:
  BoundedViolation() = default;
  BoundedViolation(const BoundedViolation&) = default;
  BoundedViolation& operator=(const BoundedViolation&) = default;
};

}  // namespace sightline::camera
