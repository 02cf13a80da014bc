// sightline::World: sightline's geometry world against the test's brute-force oracle, and the
// interface's default queries (gradient by differences, open_at) against known answers.
#include "sightline/world.h"

#include <gtest/gtest.h>

#include <random>

#include "box_oracle.h"

namespace {

using sightline::Vec3;

std::vector<sightline::Box> random_boxes(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> at(-10, 10), size(0.2, 3);
  std::vector<sightline::Box> boxes;
  for (int i = 0; i < n; ++i) {
    const Vec3 lo{at(rng), at(rng) * 0.3, at(rng)};
    boxes.push_back({lo, {lo.x + size(rng), lo.y + size(rng), lo.z + size(rng)}});
  }
  return boxes;
}

TEST(GeometryWorld, SightLinesAndClearanceMatchBruteForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> at(-12, 12);
  for (int scene = 0; scene < 5; ++scene) {
    sightline::WorldGeometry g;
    g.boxes = random_boxes(rng, 40);
    const auto world = sightline::make_geometry_world(g);
    for (int i = 0; i < 400; ++i) {
      const Vec3 a{at(rng), at(rng) * 0.3, at(rng)}, b{at(rng), at(rng) * 0.3, at(rng)};
      EXPECT_EQ(world->line_of_sight(a, b, 0), box_oracle::clear(g.boxes, a, b));
      EXPECT_EQ(world->first_hit(a, b, 0).has_value(), !box_oracle::clear(g.boxes, a, b));
      double d = 1e9;
      for (const auto& box : g.boxes) d = std::min(d, box_oracle::distance(a, box));
      EXPECT_NEAR(world->clearance(a, 1e9, 0), d, 1e-9);
      EXPECT_EQ(world->open_at(a, 0), d >= 0);
    }
  }
}

// A world whose only surface is the ground plane y = 0 (solid below): clearance is y.
class Ground : public sightline::World {
 public:
  std::optional<sightline::WorldHit> first_hit(const Vec3& a, const Vec3& b, double) const override {
    if (a.y > 0 && b.y > 0) return std::nullopt;
    const double f = a.y <= 0 ? 0 : a.y / (a.y - b.y);
    return sightline::WorldHit{f, {0, 1, 0}};
  }
  double clearance(const Vec3& p, double limit, double) const override { return std::min(p.y, limit); }
};

TEST(WorldDefaults, GradientByDifferencesPointsAwayFromTheSurface) {
  Ground g;
  const auto s = g.nearest_surface(Vec3{1, 0.3, 2}, 1.0, 0);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->signed_distance, 0.3, 1e-12);
  EXPECT_NEAR(s->gradient.x, 0, 1e-9);
  EXPECT_NEAR(s->gradient.y, 1, 1e-9);
  EXPECT_NEAR(s->gradient.z, 0, 1e-9);
  EXPECT_FALSE(g.nearest_surface(Vec3{0, 2, 0}, 1.0, 0).has_value());  // farther than the limit
  // Just under the limit: the differences must not be clipped by it.
  const auto near_limit = g.nearest_surface(Vec3{0, 0.99999, 0}, 1.0, 0);
  ASSERT_TRUE(near_limit.has_value());
  EXPECT_NEAR(near_limit->gradient.y, 1, 1e-9);
}

TEST(WorldDefaults, OpenAtAndLineOfSightFollowTheRequiredQueries) {
  Ground g;
  EXPECT_TRUE(g.open_at(Vec3{0, 0.5, 0}, 0));
  EXPECT_TRUE(g.open_at(Vec3{0, 0, 0}, 0));  // on the surface
  EXPECT_FALSE(g.open_at(Vec3{0, -0.5, 0}, 0));
  EXPECT_TRUE(g.line_of_sight(Vec3{0, 1, 0}, Vec3{5, 2, 0}, 0));
  EXPECT_FALSE(g.line_of_sight(Vec3{0, 1, 0}, Vec3{5, -1, 0}, 0));
}

TEST(GeometryWorld, RefusesBadGeometry) {
  sightline::WorldGeometry g;
  g.boxes.push_back({{0, 0, 0}, {1, std::nan(""), 1}});
  EXPECT_THROW(sightline::make_geometry_world(g), sightline::Error);
  g.boxes = {{{0, 0, 0}, {1, 0, 1}}};  // flat
  EXPECT_THROW(sightline::make_geometry_world(g), sightline::Error);
  g.boxes.clear();
  g.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  g.triangle_indices = {0, 1};
  EXPECT_THROW(sightline::make_geometry_world(g), sightline::Error);
}

}  // namespace
