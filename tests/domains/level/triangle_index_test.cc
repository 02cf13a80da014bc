// TriangleIndex (Embree) against brute force (triangle_brute_force.h, in double, sharing no
// code with the index): random triangle soups (near the origin and 2 km away), a large
// procedural level (a 100k-triangle terrain with walls) and a real map (OpenArena's oa_thor,
// from Debian's openarena-088-data, through the Quake III loader). Embree works in float, so
// a segment that passes within 1e-5 of the scene's scale of a triangle's boundary may go
// either way; such cases are counted and must be rare, every other answer must agree
// exactly. Also: queries from several threads, and queries allocate nothing (this program
// counts operator new). The box and edge cases are in triangle_index_contact_test.cc, the
// ray packets (segments_blocked) in triangle_index_packet_test.cc.
#include <gtest/gtest.h>

#include <array>
#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdlib>
#include <new>
#include <random>
#include <thread>

#include "sightline/domains/camera/geometry/triangle_index.h"
#include "sightline/domains/camera/level/q3_level.h"
#include "triangle_brute_force.h"
#include "triangle_test_meshes.h"

// Counting allocations: the queries must not allocate (the camera calls them per frame).
#include "tests/count_allocations.h"

namespace sightline::camera {
namespace {

using Eigen::Vector3d;
using test_meshes::procedural_level;
using test_meshes::random_soup;
using test_meshes::scale_of;

// ---- comparing with brute force --------------------------------------------------------

Vector3d unit_normal(const brute::Triangle& t) {
  return (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]).normalized();
}

struct Tally {
  int segments = 0, blocked = 0, ambiguous = 0;
  int points = 0, within_limit = 0;
  // Kept in the test's XML report (--gtest_output=xml), for reading the ambiguity rate.
  void record() const {
    ::testing::Test::RecordProperty("segments", segments);
    ::testing::Test::RecordProperty("blocked", blocked);
    ::testing::Test::RecordProperty("ambiguous", ambiguous);
    ::testing::Test::RecordProperty("points", points);
    ::testing::Test::RecordProperty("within_limit", within_limit);
  }
};

// One segment: segment_blocked and first_hit against the brute-force verdict.
void check_segment(const TriangleIndex& index, const std::vector<brute::Triangle>& tris,
                   const Vector3d& a, const Vector3d& b, double tol, Tally& tally) {
  const brute::SegmentVerdict v = brute::judge_segment(tris, a, b, tol);
  const bool blocked = index.segment_blocked(a, b);
  const std::optional<TriangleIndex::Hit> hit = index.first_hit(a, b);
  ++tally.segments;
  if (v.must) ++tally.blocked;
  if (v.may && !v.must) ++tally.ambiguous;
  SCOPED_TRACE(::testing::Message() << "segment (" << a.transpose() << ") -> (" << b.transpose()
                                    << ")");
  if (v.must) {
    ASSERT_TRUE(blocked);
    ASSERT_TRUE(hit.has_value());
  }
  if (!v.may) {
    ASSERT_FALSE(blocked);
    ASSERT_FALSE(hit.has_value());
  }
  if (!hit) return;
  const double length = (b - a).norm();
  ASSERT_GE(hit->t, 0.0);
  ASSERT_LE(hit->t, 1.0);
  ASSERT_LT(hit->triangle, tris.size());
  const brute::Triangle& t = tris[hit->triangle];
  // The hit is a real contact: its point lies on the triangle reported...
  const Vector3d at = a + hit->t * (b - a);
  EXPECT_LE(brute::point_triangle_distance(at, t), tol);
  // ... and it is the first: no definite crossing comes before it.
  if (v.must) {
    EXPECT_LE(hit->t * length, v.first_must_t * length + tol);
    if (hit->triangle == v.first_must_triangle) {
      EXPECT_NEAR(hit->t * length, v.first_must_t * length, tol);
    }
  }
  EXPECT_NEAR((hit->normal - unit_normal(t)).norm(), 0.0, 1e-9);
}

// One point: nearest (unlimited and with a limit) against brute force.
void check_point(const TriangleIndex& index, const std::vector<brute::Triangle>& tris,
                 const Vector3d& p, double limit, double scale, Tally& tally) {
  const brute::NearestVerdict truth = brute::nearest_triangle(tris, p);
  const double eps = 1e-9 * scale;
  SCOPED_TRACE(::testing::Message() << "point (" << p.transpose() << ")");
  ++tally.points;
  const std::optional<TriangleIndex::Nearest> all = index.nearest(p);
  ASSERT_TRUE(all.has_value());
  EXPECT_NEAR(all->distance, truth.distance, eps);
  ASSERT_LT(all->triangle, tris.size());
  const brute::Triangle& t = tris[all->triangle];
  EXPECT_NEAR(brute::point_triangle_distance(p, t), all->distance, eps);
  EXPECT_NEAR((all->point - p).norm(), all->distance, eps);
  EXPECT_LE(brute::point_triangle_distance(all->point, t), eps);

  const std::optional<TriangleIndex::Nearest> near = index.nearest(p, limit);
  if (truth.distance < limit - eps) {
    ++tally.within_limit;
    ASSERT_TRUE(near.has_value());
    EXPECT_NEAR(near->distance, truth.distance, eps);
    EXPECT_NEAR(brute::point_triangle_distance(p, tris[near->triangle]), near->distance, eps);
  } else if (truth.distance > limit + eps) {
    EXPECT_FALSE(near.has_value());
  }
}

// Segments of every length between random points of `box` (scaled around its centre),
// half of them ending on a random triangle (exactly on it, up to double rounding: such a
// closed segment touches it); and points, a third of them on triangles, a third just off.
void compare_with_brute_force(const TriangleMesh& mesh, const Aabb& region, int segments,
                              int points, std::uint64_t seed, Tally& tally) {
  const TriangleIndex index(mesh);
  ASSERT_EQ(index.triangle_count(), mesh.size());
  const std::vector<brute::Triangle> tris = brute::triangles_of(mesh);
  const double scale = scale_of(mesh);
  const double tol = 1e-5 * scale;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  auto somewhere = [&] { return test_meshes::random_point_in(region, rng); };
  auto on_triangle = [&] { return test_meshes::random_point_on(mesh, rng); };
  for (int i = 0; i < segments; ++i) {
    const Vector3d a = somewhere();
    Vector3d b = i % 2 == 0 ? on_triangle() : somewhere();
    if (i % 3 == 0) b = a + (b - a) * std::pow(10.0, -3 * unit(rng));  // short ones too
    check_segment(index, tris, a, b, tol, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::normal_distribution<double> gauss;
  for (int i = 0; i < points; ++i) {
    Vector3d p = i % 3 == 0 ? somewhere() : on_triangle();
    if (i % 3 == 2) p += 0.3 * unit(rng) * Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
    check_point(index, tris, p, 0.2, scale, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// ---- random soups and the procedural level ---------------------------------------------

TEST(TriangleIndex, AgreesWithBruteForceOnRandomSoups) {
  std::mt19937_64 rng(1);
  Tally tally;
  for (int trial = 0; trial < 3; ++trial) {
    const TriangleMesh mesh = random_soup(rng, 1500, Vector3d::Zero());
    compare_with_brute_force(mesh, {Vector3d::Constant(-13), Vector3d::Constant(13)}, 6000, 2000,
                             100 + trial, tally);
    if (HasFatalFailure()) return;
  }
  tally.record();
  // Most segments meet something, many do not: both sides are exercised.
  EXPECT_GT(tally.blocked, tally.segments / 4);
  EXPECT_LT(tally.blocked, tally.segments * 9 / 10);
  EXPECT_LT(tally.ambiguous, tally.segments / 200) << tally.ambiguous << " ambiguous";
  EXPECT_GT(tally.within_limit, tally.points / 3);
}

TEST(TriangleIndex, AgreesWithBruteForceFarFromTheOrigin) {
  // 2 km out, float vertices are 1.2e-4 m apart: the tolerance scales with the coordinates.
  std::mt19937_64 rng(2);
  const Vector3d offset(1500, 40, -2000);
  const TriangleMesh mesh = random_soup(rng, 1500, offset);
  Tally tally;
  compare_with_brute_force(mesh, {offset - Vector3d::Constant(13), offset + Vector3d::Constant(13)},
                           6000, 2000, 7, tally);
  tally.record();
  EXPECT_GT(tally.blocked, tally.segments / 4);
  // The band is 2 cm wide here (1e-5 of 2 km) around triangles of about 2 m: wider, so more
  // segments fall in it than near the origin (about 2.7%).
  EXPECT_LT(tally.ambiguous, tally.segments / 25) << tally.ambiguous << " ambiguous";
}

TEST(TriangleIndex, AgreesWithBruteForceOnALargeProceduralLevel) {
  const TriangleMesh mesh = procedural_level();
  ASSERT_GT(mesh.size(), 99000u);
  Tally tally;
  // Sight lines from above the terrain (cameras) to points near it (characters), and
  // points near the ground and walls.
  compare_with_brute_force(mesh, {Vector3d(-85, -5, -85), Vector3d(85, 12, 85)}, 1200, 600, 3,
                           tally);
  tally.record();
  EXPECT_GT(tally.blocked, tally.segments / 4);
  EXPECT_LT(tally.ambiguous, tally.segments / 100) << tally.ambiguous << " ambiguous";
  EXPECT_GT(tally.within_limit, tally.points / 3);
}

TEST(TriangleIndex, AgreesWithBruteForceOnARealQuake3Map) {
  LevelSpec spec;
  spec.file = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3";
  spec.map = "oa_thor";
  // load_level's defaults for .pk3 (FORMATS.md): 32 units to the metre, z up.
  const Level level = load_quake3_level(spec, LevelTransform{0.03125, UpAxis::kZ});
  ASSERT_GT(level.mesh.size(), 1000u);
  Tally tally;
  compare_with_brute_force(level.mesh, level.mesh.bounds(), 1500, 600, 4, tally);
  RecordProperty("triangles", static_cast<int>(level.mesh.size()));
  tally.record();
  EXPECT_GT(tally.blocked, tally.segments / 4);
  EXPECT_LT(tally.ambiguous, tally.segments / 100) << tally.ambiguous << " ambiguous";
  EXPECT_GT(tally.within_limit, tally.points / 3);
}

TEST(TriangleIndex, QueriesFromSeveralThreadsAgreeWithOneThread) {
  std::mt19937_64 rng(11);
  const TriangleIndex index(random_soup(rng, 3000, Vector3d::Zero()));
  std::uniform_real_distribution<double> pos(-12, 12);
  std::vector<std::pair<Vector3d, Vector3d>> segments(4000);
  for (auto& [a, b] : segments) {
    a = Vector3d(pos(rng), pos(rng), pos(rng));
    b = Vector3d(pos(rng), pos(rng), pos(rng));
  }
  // One answer per query: blocked, first-hit triangle, nearest triangle within 1 m.
  auto answer = [&](std::size_t i) {
    const auto& [a, b] = segments[i];
    const auto hit = index.first_hit(a, b);
    const auto near = index.nearest(a, 1.0);
    return std::array<long, 3>{index.segment_blocked(a, b) ? 1 : 0,
                               hit ? static_cast<long>(hit->triangle) : -1,
                               near ? static_cast<long>(near->triangle) : -1};
  };
  std::vector<std::array<long, 3>> alone(segments.size()), together(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) alone[i] = answer(i);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      for (std::size_t i = k; i < segments.size(); i += 4) together[i] = answer(i);
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(alone, together);
}

TEST(TriangleIndex, QueriesDoNotAllocate) {
  std::mt19937_64 rng(12);
  const TriangleIndex index(random_soup(rng, 2000, Vector3d::Zero()));
  std::uniform_real_distribution<double> pos(-12, 12);
  std::vector<Vector3d> points(2000);
  for (auto& p : points) p = Vector3d(pos(rng), pos(rng), pos(rng));
  double sink = 0;
  index.segment_blocked(points[0], points[1]);  // first use on this thread
  const long before = g_allocations.load();
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    sink += index.segment_blocked(points[i], points[i + 1]) ? 1 : 0;
    if (const auto hit = index.first_hit(points[i], points[i + 1])) sink += hit->t;
    if (const auto near = index.nearest(points[i], 0.2)) sink += near->distance;
    if (const auto near = index.nearest(points[i])) sink += near->distance;
    sink += index.segment_blocked(points[i], points[i]) ? 1 : 0;
    const std::size_t fan = std::min<std::size_t>(TriangleIndex::kMaxFan, points.size() - i - 1);
    sink += std::popcount(index.segments_blocked(
        points[i], std::span<const Vector3d>(points.data() + i + 1, fan)));
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_GT(sink, 0);
}

}  // namespace
}  // namespace sightline::camera
