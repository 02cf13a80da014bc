// The independent triangle check: its grid must never change an answer, so every query is
// compared with a loop over all triangles (the same exact predicates, no grid), on random
// soups; and the predicates themselves on hand-made cases with known answers.
#include "sightline/experiments/runs/independent_triangles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sightline::experiments {
namespace {

camera::TriangleMesh random_soup(std::mt19937& rng, int n, double extent, double size) {
  std::uniform_real_distribution<double> where(-extent, extent), jitter(-size, size);
  camera::TriangleMesh mesh;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d c(where(rng), where(rng) * 0.3, where(rng));
    for (int k = 0; k < 3; ++k) {
      mesh.vertices.push_back((c + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng))).cast<float>());
    }
    const auto b = static_cast<std::uint32_t>(3 * i);
    mesh.triangles.push_back({b, b + 1, b + 2});
  }
  return mesh;
}

TEST(IndependentTriangles, TheGridAgreesWithALoopOverEveryTriangle) {
  std::mt19937 rng(7);
  const camera::TriangleMesh mesh = random_soup(rng, 2000, 30, 2);
  const IndependentTriangles grid(mesh);
  std::uniform_real_distribution<double> where(-35, 35);
  int blocked = 0;
  for (int q = 0; q < 3000; ++q) {
    const Eigen::Vector3d a(where(rng), where(rng) * 0.3, where(rng));
    const Eigen::Vector3d b = a + Eigen::Vector3d(where(rng), where(rng), where(rng)) * 0.2;
    bool expected = false;
    double nearest = 1.5, unlimited = INFINITY;
    // Far points too: the unlimited search grows its cube until it holds the answer.
    const Eigen::Vector3d far = a * 3;
    double far_nearest = INFINITY;
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
      expected = expected || segment_meets_triangle(a, b, mesh.vertex(i, 0), mesh.vertex(i, 1), mesh.vertex(i, 2));
      const double d = point_triangle_distance(a, mesh.vertex(i, 0), mesh.vertex(i, 1), mesh.vertex(i, 2));
      nearest = std::min(nearest, d);
      unlimited = std::min(unlimited, d);
      far_nearest = std::min(far_nearest, point_triangle_distance(far, mesh.vertex(i, 0), mesh.vertex(i, 1), mesh.vertex(i, 2)));
    }
    ASSERT_DOUBLE_EQ(grid.distance(a, INFINITY), unlimited) << "query " << q;
    ASSERT_DOUBLE_EQ(grid.distance(far, INFINITY), far_nearest) << "query " << q;
    blocked += expected;
    ASSERT_EQ(grid.segment_blocked(a, b), expected) << "query " << q;
    ASSERT_DOUBLE_EQ(grid.distance(a, 1.5), nearest) << "query " << q;
  }
  EXPECT_GT(blocked, 100);  // the queries exercise both answers
  EXPECT_LT(blocked, 2900);
}

TEST(IndependentTriangles, PredicatesGiveKnownAnswers) {
  const Eigen::Vector3d p(0, 0, 0), q(1, 0, 0), r(0, 0, 1);
  EXPECT_TRUE(segment_meets_triangle({0.2, 1, 0.2}, {0.2, -1, 0.2}, p, q, r));
  EXPECT_FALSE(segment_meets_triangle({0.8, 1, 0.8}, {0.8, -1, 0.8}, p, q, r));  // beyond the hypotenuse
  EXPECT_TRUE(segment_meets_triangle({0.5, 1, 0.5}, {0.5, -1, 0.5}, p, q, r));   // on the hypotenuse
  EXPECT_TRUE(segment_meets_triangle({0, 1, 0}, {0, -1, 0}, p, q, r));           // through a vertex
  EXPECT_TRUE(segment_meets_triangle({0.2, 1, 0.2}, {0.2, 0, 0.2}, p, q, r));    // ends on it
  EXPECT_FALSE(segment_meets_triangle({0.2, 1, 0.2}, {0.2, 0.01, 0.2}, p, q, r));  // stops short
  EXPECT_DOUBLE_EQ(point_triangle_distance({0.2, 3, 0.2}, p, q, r), 3);
  EXPECT_DOUBLE_EQ(point_triangle_distance({-1, 0, 0}, p, q, r), 1);
  EXPECT_NEAR(point_triangle_distance({1, 0, 1}, p, q, r), std::sqrt(0.5), 1e-12);
  const IndependentTriangles none{camera::TriangleMesh{}};
  EXPECT_FALSE(none.segment_blocked({0, 0, 0}, {1, 1, 1}));
  EXPECT_EQ(none.distance({0, 0, 0}, 2.0), 2.0);
}

}  // namespace
}  // namespace sightline::experiments
