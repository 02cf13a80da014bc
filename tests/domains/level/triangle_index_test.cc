// TriangleIndex (Embree) against brute force (triangle_brute_force.h, in double, sharing no
// code with the index): random triangle soups (near the origin and 2 km away), a closed box
// of 12 triangles (watertight edges and vertices, faces touched exactly, zero-length
// segments), and a large procedural level (a 100k-triangle terrain with walls). Embree
// works in float, so a segment that passes within 1e-5 of the scene's scale of a triangle's
// boundary may go either way; such cases are counted and must be rare, every other answer
// must agree exactly.
//
// The real-map check (oa_thor from OpenArena through load_level) waits for the Quake III
// loader; the procedural level stands in for it meanwhile.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>
#include <thread>

#include "domains/camera/geometry/triangle_index.h"
#include "triangle_brute_force.h"

// Counting allocations: the queries must not allocate (the camera calls them per frame).
namespace {
std::atomic<long> g_allocations{0};
}
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace sightline::camera {
namespace {

using Eigen::Vector3d;

// ---- meshes ----------------------------------------------------------------------------

// n random triangles in the cube [-10, 10]^3 + offset, sides up to ~4 m; every 100th is
// degenerate (two equal corners, or three collinear), which must never be hit by a ray but
// still has a distance.
TriangleMesh random_soup(std::mt19937_64& rng, int n, const Vector3d& offset) {
  std::uniform_real_distribution<double> pos(-10, 10);
  std::uniform_real_distribution<double> spread(-2, 2);
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i) {
    const Vector3d c(pos(rng), pos(rng), pos(rng));
    Vector3d v[3];
    for (auto& x : v) x = c + Vector3d(spread(rng), spread(rng), spread(rng));
    if (i % 100 == 1) v[2] = v[1];
    if (i % 100 == 2) v[2] = v[0] + 0.5 * (v[1] - v[0]);
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const auto& x : v) mesh.vertices.push_back((x + offset).cast<float>());
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

// A closed box: 8 shared corners, 12 triangles, front faces outward.
TriangleMesh box_mesh(const Vector3d& lo, const Vector3d& hi) {
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k) {
    mesh.vertices.emplace_back(Vector3d((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                        (k & 4) ? hi.z() : lo.z())
                                   .cast<float>());
  }
  // Each face as a quad (corner bits) counter-clockwise seen from outside.
  const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5},   // -x, +x
                                     {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
                                     {0, 2, 3, 1}, {4, 5, 7, 6}};  // -z, +z
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

// A 100k-triangle level: a 224 x 224 heightfield over 160 m x 160 m (hills and ripples), and
// 40 walls and pillars (closed boxes) standing on it.
TriangleMesh procedural_level() {
  TriangleMesh mesh;
  const int n = 224;
  const double extent = 80;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = -extent + 2 * extent * i / (n - 1);
      const double z = -extent + 2 * extent * j / (n - 1);
      const double y = 3 * std::sin(x / 7) * std::cos(z / 11) + 0.5 * std::sin(x / 1.3 + z / 2.1) +
                       noise(rng);
      mesh.vertices.emplace_back(Vector3d(x, y, z).cast<float>());
    }
  }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(i * n + j); };
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      mesh.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  std::uniform_real_distribution<double> pos(-70, 70);
  std::uniform_real_distribution<double> size(0.3, 12);
  for (int k = 0; k < 40; ++k) {
    const Vector3d lo(pos(rng), -4, pos(rng));
    mesh.append(box_mesh(lo, lo + Vector3d(size(rng), 2 + size(rng) / 2, size(rng))));
  }
  return mesh;
}

// ---- comparing with brute force --------------------------------------------------------

double scale_of(const TriangleMesh& mesh) {
  const Aabb b = mesh.bounds();
  return std::max({1.0, b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff()});
}

Vector3d unit_normal(const brute::Triangle& t) {
  return (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]).normalized();
}

struct Tally {
  int segments = 0, blocked = 0, ambiguous = 0;
  int points = 0, within_limit = 0;
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
  auto somewhere = [&] {
    return Vector3d(region.min + region.size().cwiseProduct(
                                     Vector3d(unit(rng), unit(rng), unit(rng))));
  };
  auto on_triangle = [&] {
    const brute::Triangle& t = tris[rng() % tris.size()];
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    return Vector3d(t.v[0] + u * (t.v[1] - t.v[0]) + v * (t.v[2] - t.v[0]));
  };
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
  // Most segments meet something, many do not: both sides are exercised.
  EXPECT_GT(tally.blocked, tally.segments / 4);
  EXPECT_LT(tally.blocked, tally.segments * 9 / 10);
  EXPECT_LT(tally.ambiguous, tally.segments / 200) << tally.ambiguous << " ambiguous";
  EXPECT_GT(tally.within_limit, tally.points / 3);
  RecordProperty("ambiguous", tally.ambiguous);
}

TEST(TriangleIndex, AgreesWithBruteForceFarFromTheOrigin) {
  // 2 km out, float vertices are 1.2e-4 m apart: the tolerance scales with the coordinates.
  std::mt19937_64 rng(2);
  const Vector3d offset(1500, 40, -2000);
  const TriangleMesh mesh = random_soup(rng, 1500, offset);
  Tally tally;
  compare_with_brute_force(mesh, {offset - Vector3d::Constant(13), offset + Vector3d::Constant(13)},
                           6000, 2000, 7, tally);
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
  EXPECT_GT(tally.blocked, tally.segments / 4);
  EXPECT_LT(tally.ambiguous, tally.segments / 100) << tally.ambiguous << " ambiguous";
  EXPECT_GT(tally.within_limit, tally.points / 3);
}

}  // namespace
}  // namespace sightline::camera
