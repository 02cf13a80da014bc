// sightline::World's default queries (sightline/world.h), built on first_hit and clearance.
// They live with the camera, which asks them, so the program and the runtime library share
// one definition of the interface.
#include "sightline/world.h"

#include <cmath>

namespace sightline {

bool World::line_of_sight(const Vec3& a, const Vec3& b, double t) const {
  return !first_hit(a, b, t);
}

std::optional<NearestSurface> World::nearest_surface(const Vec3& p, double limit,
                                                     double t) const {
  const double d = clearance(p, limit, t);
  if (!(d < limit)) return std::nullopt;
  // Central differences with a step well under a camera's clearance radius; the distance is
  // asked uncapped (limit + h bounds it) so that no sample is clipped.
  constexpr double h = 1e-4;
  const double cap = std::isfinite(limit) ? limit + 2 * h : limit;
  auto at = [&](double dx, double dy, double dz) {
    return clearance(Vec3{p.x + dx, p.y + dy, p.z + dz}, cap, t);
  };
  Vec3 g{(at(h, 0, 0) - at(-h, 0, 0)) / (2 * h), (at(0, h, 0) - at(0, -h, 0)) / (2 * h),
         (at(0, 0, h) - at(0, 0, -h)) / (2 * h)};
  const double norm = std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
  if (norm > 0) g = Vec3{g.x / norm, g.y / norm, g.z / norm};
  return NearestSurface{d, g};
}

bool World::open_at(const Vec3& p, double t) const { return clearance(p, 0.0, t) >= 0; }

}  // namespace sightline
