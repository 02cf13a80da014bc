// An independent oracle for worlds of boxes, written for the public API's tests: segment
// against box by the slab method and the distance to a box, sharing no code with sightline.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "sightline/world.h"

namespace box_oracle {

inline bool segment_touches(const sightline::Vec3& a, const sightline::Vec3& b,
                            const sightline::Box& box) {
  const double p[3] = {a.x, a.y, a.z}, q[3] = {b.x, b.y, b.z};
  const double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
  double t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const double d = q[k] - p[k];
    if (d == 0) {
      if (p[k] < lo[k] || p[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - p[k]) / d, tb = (hi[k] - p[k]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Signed distance: negative inside.
inline double distance(const sightline::Vec3& p, const sightline::Box& box) {
  const double c[3] = {p.x, p.y, p.z};
  const double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
  double outside = 0, inside = -1e300;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max(lo[k] - c[k], c[k] - hi[k]);
    outside += std::max(d, 0.0) * std::max(d, 0.0);
    inside = std::max(inside, d);
  }
  return inside > 0 ? std::sqrt(outside) : inside;
}

inline bool clear(const std::vector<sightline::Box>& boxes, const sightline::Vec3& a,
                  const sightline::Vec3& b) {
  for (const auto& box : boxes) {
    if (segment_touches(a, b, box)) return false;
  }
  return true;
}

// A World answered by brute force over the boxes (and optionally a box that moves along x
// with time), as a game's own physics would answer: no sightline code.
class BruteForceWorld : public sightline::World {
 public:
  explicit BruteForceWorld(std::vector<sightline::Box> boxes) : boxes_(std::move(boxes)) {}
  std::optional<sightline::WorldHit> first_hit(const sightline::Vec3& a, const sightline::Vec3& b,
                                               double) const override {
    // Bisection on the first touching box along the segment (good to a micrometre).
    if (clear(boxes_, a, b)) return std::nullopt;
    double lo = 0, hi = 1;
    auto at = [&](double u) {
      return sightline::Vec3{a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), a.z + u * (b.z - a.z)};
    };
    if (!clear(boxes_, a, a)) return sightline::WorldHit{0, {}};
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      (clear(boxes_, a, at(mid)) ? lo : hi) = mid;
    }
    return sightline::WorldHit{hi, {}};
  }
  double clearance(const sightline::Vec3& p, double limit, double) const override {
    ++calls;
    double d = limit;
    for (const auto& box : boxes_) d = std::min(d, distance(p, box));
    return d;
  }
  mutable long calls = 0;

 private:
  std::vector<sightline::Box> boxes_;
};

}  // namespace box_oracle
