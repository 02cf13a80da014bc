// FloorProbe against brute force written here (signed volumes over every triangle): random
// triangle soups of small and large triangles, random segments and vertical rays.
#include "sightline/experiments/sources/floor_probe.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

namespace sightline::experiments {
namespace {

using Eigen::Vector3d;

double orient(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
  return (b - a).cross(c - a).dot(d - a);
}
// Where the segment p-q meets triangle a-b-c, as a parameter in [0, 1], if it does.
std::optional<double> meet(const Vector3d& p, const Vector3d& q, const Vector3d& a,
                           const Vector3d& b, const Vector3d& c) {
  const double sp = orient(a, b, c, p), sq = orient(a, b, c, q);
  if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0) || sp == sq) return std::nullopt;
  const double e1 = orient(p, q, a, b), e2 = orient(p, q, b, c), e3 = orient(p, q, c, a);
  if (!((e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0))) return std::nullopt;
  return sp / (sp - sq);
}

camera::TriangleMesh soup(std::mt19937_64& rng, int n, double size) {
  std::uniform_real_distribution<double> at(0, 20), off(-size, size);
  camera::TriangleMesh mesh;
  for (int i = 0; i < n; ++i) {
    const Vector3d c(at(rng), at(rng) / 4, at(rng));
    for (int k = 0; k < 3; ++k) {
      mesh.vertices.push_back((c + Vector3d(off(rng), off(rng), off(rng))).cast<float>());
    }
    const auto b = static_cast<std::uint32_t>(3 * i);
    mesh.triangles.push_back({b, b + 1, b + 2});
  }
  return mesh;
}

struct Soup {
  int triangles;
  double size;  // half the spread of a triangle's corners, metres
};
class FloorProbeAgainstBruteForce : public ::testing::TestWithParam<Soup> {};

TEST_P(FloorProbeAgainstBruteForce, AnswersEverySegmentAndRayAlike) {
  std::mt19937_64 rng(7);
  const camera::TriangleMesh mesh = soup(rng, GetParam().triangles, GetParam().size);
  const FloorProbe probe(mesh, 1.8);
  std::uniform_real_distribution<double> at(-1, 21), leg(-3, 3);
  int blocked = 0, floors = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vector3d p(at(rng), at(rng) / 4, at(rng));
    const Vector3d q = p + Vector3d(leg(rng), leg(rng), leg(rng));
    bool expected = false;
    for (std::uint32_t t = 0; t < mesh.size() && !expected; ++t) {
      expected = meet(p, q, mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2)).has_value();
    }
    EXPECT_EQ(probe.segment_blocked(p, q), expected) << p.transpose() << " -> " << q.transpose();
    blocked += expected;
    // Straight down from p, 4 m: the highest surface met.
    const Vector3d low = p - Vector3d(0, 4, 0);
    std::optional<double> first;
    for (std::uint32_t t = 0; t < mesh.size(); ++t) {
      const auto s = meet(p, low, mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2));
      if (s && (!first || *s < *first)) first = s;
    }
    const auto got = probe.floor_below(p.x(), p.z(), p.y(), low.y());
    ASSERT_EQ(got.has_value(), first.has_value()) << p.transpose();
    if (got) {
      EXPECT_NEAR(*got, p.y() - 4 * *first, 1e-4);  // Embree works in float
    }
    floors += first.has_value();
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(blocked, 200);
  EXPECT_LT(blocked, 2800);
  EXPECT_GT(floors, 200);
}

INSTANTIATE_TEST_SUITE_P(SmallAndLargeTriangles, FloorProbeAgainstBruteForce,
                         ::testing::Values(Soup{3000, 0.5}, Soup{300, 4.0}, Soup{30, 15.0}));

TEST(FloorProbe, HeadroomAndBodyLinesSeeACeilingAndABar) {
  camera::TriangleMesh mesh;
  const auto quad = [&](Vector3d a, Vector3d b, Vector3d c, Vector3d d) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const Vector3d& v : {a, b, c, d}) mesh.vertices.push_back(v.cast<float>());
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
  };
  quad({0, 1.7, 0}, {2, 1.7, 0}, {2, 1.7, 2}, {0, 1.7, 2});  // a ceiling at 1.7 m
  quad({5, 0, 0}, {5, 0, 4}, {5, 1.3, 4}, {5, 1.3, 0});      // a wall up to 1.3 m at x = 5
  const FloorProbe probe(mesh, 1.8);
  EXPECT_FALSE(probe.has_headroom({1, 0, 1}));
  EXPECT_TRUE(probe.has_headroom({3, 0, 1}));
  EXPECT_TRUE(probe.has_headroom({1, 1.75, 1}));
  EXPECT_FALSE(probe.body_clear({4, 0, 1}, {6, 0, 1}));     // knees and waist hit the wall
  EXPECT_TRUE(probe.body_clear({4, 0.9, 1}, {6, 0.9, 1}));  // all lines pass above it
  EXPECT_TRUE(probe.body_clear({4, 0, 5}, {6, 0, 5}));      // beside it
}

}  // namespace
}  // namespace sightline::experiments
