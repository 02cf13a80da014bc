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

#include <array>
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


// ---- a closed box: watertight edges and corners, exact contacts ------------------------

const Vector3d kLo(-1.3, 0.2, 2.7), kHi(0.9, 2.5, 4.1);

// The box's corners as the index sees them (float-rounded).
Vector3d corner(const TriangleMesh& box, int k) { return box.vertices[k].cast<double>(); }

TEST(TriangleIndex, ClosedBoxIsWatertightThroughSharedEdgesAndCorners) {
  const TriangleMesh box = box_mesh(kLo, kHi);
  const TriangleIndex index(box);
  const Vector3d lo = corner(box, 0), hi = corner(box, 7);
  // Every edge of every triangle: the 12 box edges (shared by two faces at right angles) and
  // the 6 face diagonals (shared by the two triangles of a face).
  std::vector<std::pair<Vector3d, Vector3d>> edges;
  for (const auto& t : box.triangles) {
    for (int k = 0; k < 3; ++k) {
      edges.emplace_back(corner(box, t[k]), corner(box, t[(k + 1) % 3]));
    }
  }
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  const double tol = 1e-5 * scale_of(box);
  int checked = 0;
  for (int i = 0; i < 6000; ++i) {
    // A point E on an edge (a third of them on a corner), a point Q well inside, and the
    // segment from outside through E to a point between E and Q: it enters the box at E, so
    // it must be blocked there whichever of the triangles around E takes it.
    Vector3d e;
    if (i % 3 == 0) {
      e = corner(box, static_cast<int>(rng() % 8));
    } else {
      const auto& [u, v] = edges[rng() % edges.size()];
      e = u + unit(rng) * (v - u);
    }
    const Vector3d margin = Vector3d::Constant(0.05);
    const Vector3d q = lo + margin +
                       (hi - lo - 2 * margin).cwiseProduct(Vector3d(unit(rng), unit(rng), unit(rng)));
    const double before = 0.05 + 3 * unit(rng), after = 0.05 + unit(rng);
    const Vector3d a = e - before * (q - e);
    const Vector3d b = e + after * (q - e);
    SCOPED_TRACE(::testing::Message() << "through (" << e.transpose() << ") from ("
                                      << a.transpose() << ")");
    ASSERT_TRUE(index.segment_blocked(a, b));
    ASSERT_TRUE(index.segment_blocked(b, a));  // leaving the box through E
    const std::optional<TriangleIndex::Hit> hit = index.first_hit(a, b);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR((a + hit->t * (b - a) - e).norm(), 0.0, tol);
    ++checked;
  }
  EXPECT_EQ(checked, 6000);
}

// A point on face `axis`/`side` (0: the min face, 1: the max face) of the box, with its
// coordinate on that axis exactly the face's float coordinate.
Vector3d point_on_face(const TriangleMesh& box, int axis, int side, std::mt19937_64& rng) {
  const Vector3d lo = corner(box, 0), hi = corner(box, 7);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  Vector3d p = lo + (hi - lo).cwiseProduct(Vector3d(unit(rng), unit(rng), unit(rng)));
  p[axis] = side == 0 ? lo[axis] : hi[axis];
  return p;
}

TEST(TriangleIndex, SegmentsEndingOrStartingOnAFaceTouchIt) {
  const TriangleMesh box = box_mesh(kLo, kHi);
  const TriangleIndex index(box);
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> unit(0, 1), spread(-1, 1);
  const double tol = 1e-5 * scale_of(box);
  for (int i = 0; i < 3000; ++i) {
    const int axis = i % 3, side = (i / 3) % 2;
    const Vector3d f = point_on_face(box, axis, side, rng);
    Vector3d outward = Vector3d::Zero();
    outward[axis] = side == 0 ? -1 : 1;
    // From outside, at least 17 degrees from grazing, ending exactly on the face.
    Vector3d away = outward * (0.3 + unit(rng)) + Vector3d(spread(rng), spread(rng), spread(rng));
    away[axis] = outward[axis] * std::max(std::abs(away[axis]), 0.3 * away.norm());
    const Vector3d a = f + (0.01 + 5 * unit(rng)) * away;
    SCOPED_TRACE(::testing::Message() << "face point (" << f.transpose() << ") from ("
                                      << a.transpose() << ")");
    ASSERT_TRUE(index.segment_blocked(a, f));
    std::optional<TriangleIndex::Hit> hit = index.first_hit(a, f);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t * (f - a).norm(), (f - a).norm(), tol);
    EXPECT_NEAR(hit->normal.dot(outward), 1.0, 1e-12);  // front faces face outward
    // Starting on the face, going out or going in: touching at t = 0.
    for (const Vector3d& b : {a, Vector3d(2 * f - a)}) {
      ASSERT_TRUE(index.segment_blocked(f, b));
      hit = index.first_hit(f, b);
      ASSERT_TRUE(hit.has_value());
      EXPECT_LE(hit->t * (b - f).norm(), tol);
    }
  }
}

TEST(TriangleIndex, ZeroLengthSegmentsArePoints) {
  const TriangleMesh box = box_mesh(kLo, kHi);
  const TriangleIndex index(box);
  std::mt19937_64 rng(8);
  for (int i = 0; i < 600; ++i) {
    const Vector3d f = point_on_face(box, i % 3, (i / 3) % 2, rng);
    ASSERT_TRUE(index.segment_blocked(f, f)) << f.transpose();
    const std::optional<TriangleIndex::Hit> hit = index.first_hit(f, f);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->t, 0.0);
    EXPECT_NEAR(std::abs(hit->normal[i % 3]), 1.0, 1e-12);
  }
  for (int k = 0; k < 8; ++k) EXPECT_TRUE(index.segment_blocked(corner(box, k), corner(box, k)));
  // Triangles have no inside: a point in the box's interior touches nothing, nor one outside.
  const Vector3d centre = (kLo + kHi) / 2;
  EXPECT_FALSE(index.segment_blocked(centre, centre));
  EXPECT_FALSE(index.first_hit(centre, centre).has_value());
  const Vector3d near_face = Vector3d(kHi.x() + 1e-3, centre.y(), centre.z());
  EXPECT_FALSE(index.segment_blocked(near_face, near_face));
}

TEST(TriangleIndex, SegmentsInAFacePlaneCrossingTheBoxAreBlocked) {
  const TriangleMesh box = box_mesh(kLo, kHi);
  const TriangleIndex index(box);
  const Vector3d lo = corner(box, 0), hi = corner(box, 7);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  for (int i = 0; i < 600; ++i) {
    // In the plane of face (axis, side), along axis2, through the whole box.
    const int axis = i % 3, side = (i / 3) % 2, along = (axis + 1 + (i / 6) % 2) % 3;
    Vector3d a = lo + (hi - lo).cwiseProduct(Vector3d(unit(rng), unit(rng), unit(rng)));
    a[axis] = side == 0 ? lo[axis] : hi[axis];
    Vector3d b = a;
    a[along] = lo[along] - 1;
    b[along] = hi[along] + 1;
    EXPECT_TRUE(index.segment_blocked(a, b)) << a.transpose() << " -> " << b.transpose();
    EXPECT_TRUE(index.first_hit(a, b).has_value());
  }
}


TEST(TriangleIndex, ASegmentInsideOneTrianglesPlaneDoesNotMeetIt) {
  // The documented limit: a lone triangle is not met by a segment lying in its plane (the
  // determinant is 0); closed geometry is still blocked (the test above).
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  mesh.triangles = {{0, 1, 2}};
  const TriangleIndex index(mesh);
  EXPECT_FALSE(index.segment_blocked(Vector3d(0.5, 0.5, 0), Vector3d(1.5, 1, 0)));
  EXPECT_TRUE(index.segment_blocked(Vector3d(0.5, 0.5, 0), Vector3d(1.5, 1, 0.01)));
}

// ---- normals, nearest points, and the index's own contract -----------------------------

TEST(TriangleIndex, NormalIsTheTrianglesFrontSideSeenFromEitherSide) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};  // (v1 - v0) x (v2 - v0) = +z
  mesh.triangles = {{0, 1, 2}};
  const TriangleIndex index(mesh);
  for (double z : {2.0, -2.0}) {
    const std::optional<TriangleIndex::Hit> hit =
        index.first_hit(Vector3d(0.2, 0.3, z), Vector3d(0.25, 0.2, -z));
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 0.5, 1e-6);
    EXPECT_EQ(hit->triangle, 0u);
    EXPECT_NEAR((hit->normal - Vector3d(0, 0, 1)).norm(), 0.0, 1e-12);
  }
  mesh.triangles = {{0, 2, 1}};  // the other winding: -z
  const TriangleIndex flipped(mesh);
  const auto hit = flipped.first_hit(Vector3d(0.2, 0.3, 1), Vector3d(0.2, 0.3, -1));
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR((hit->normal - Vector3d(0, 0, -1)).norm(), 0.0, 1e-12);
}

TEST(TriangleIndex, NearestOnABoxFromOnInsideAndFarAway) {
  const TriangleMesh box = box_mesh(kLo, kHi);
  const TriangleIndex index(box);
  std::mt19937_64 rng(10);
  for (int i = 0; i < 600; ++i) {
    const Vector3d f = point_on_face(box, i % 3, (i / 3) % 2, rng);
    const std::optional<TriangleIndex::Nearest> near = index.nearest(f, 0.2);
    ASSERT_TRUE(near.has_value());
    EXPECT_LE(near->distance, 1e-12);
    EXPECT_LE((near->point - f).norm(), 1e-12);
  }
  // Inside, the nearest surface is the nearest face (triangles have no inside).
  const Vector3d lo = corner(box, 0), hi = corner(box, 7);
  const Vector3d centre = (lo + hi) / 2;
  const std::optional<TriangleIndex::Nearest> inside = index.nearest(centre);
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->distance, ((hi - lo) / 2).minCoeff(), 1e-12);
  EXPECT_FALSE(index.nearest(centre, 0.2).has_value());
  // Far away: nothing within a finite limit; the corner without one.
  const Vector3d far = hi + Vector3d(30, 40, 120);
  EXPECT_FALSE(index.nearest(far, 0.2).has_value());
  EXPECT_FALSE(index.nearest(far, 129.9).has_value());  // the corner is 130 m away
  const std::optional<TriangleIndex::Nearest> any = index.nearest(far);
  ASSERT_TRUE(any.has_value());
  EXPECT_NEAR(any->distance, 130.0, 1e-9);
  EXPECT_NEAR((any->point - hi).norm(), 0.0, 1e-9);
  EXPECT_TRUE(index.nearest(far, 130.1).has_value());
}

TEST(TriangleIndex, AnEmptyIndexMeetsNothing) {
  for (const TriangleIndex& index : {TriangleIndex(), TriangleIndex(TriangleMesh{})}) {
    EXPECT_TRUE(index.empty());
    EXPECT_EQ(index.triangle_count(), 0u);
    EXPECT_FALSE(index.segment_blocked(Vector3d::Zero(), Vector3d::Ones()));
    EXPECT_FALSE(index.first_hit(Vector3d::Zero(), Vector3d::Ones()).has_value());
    EXPECT_FALSE(index.nearest(Vector3d::Zero()).has_value());
    EXPECT_GT(index.bounds().min.x(), index.bounds().max.x());
  }
}

TEST(TriangleIndex, KeepsTheMeshBoundsAndCountAndMovesWithIt) {
  const TriangleMesh box = box_mesh(kLo, kHi);
  TriangleIndex index(box);
  EXPECT_EQ(index.triangle_count(), 12u);
  EXPECT_EQ(index.bounds().min, box.bounds().min);
  EXPECT_EQ(index.bounds().max, box.bounds().max);
  const Vector3d out(5, 5, 5), in = (kLo + kHi) / 2;
  TriangleIndex moved(std::move(index));
  EXPECT_TRUE(moved.segment_blocked(out, in));
  TriangleIndex assigned;
  assigned = std::move(moved);
  EXPECT_TRUE(assigned.segment_blocked(out, in));
  EXPECT_EQ(assigned.triangle_count(), 12u);
}

TEST(TriangleIndex, RejectsATriangleNamingAMissingVertex) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 3}};
  EXPECT_THROW(TriangleIndex{mesh}, std::invalid_argument);
}

TEST(TriangleIndex, NonFiniteQueriesMeetNothing) {
  const TriangleIndex index(box_mesh(kLo, kHi));
  const Vector3d nan = Vector3d::Constant(std::nan("")), in = (kLo + kHi) / 2;
  EXPECT_FALSE(index.segment_blocked(nan, in));
  EXPECT_FALSE(index.first_hit(in, nan).has_value());
  EXPECT_FALSE(index.nearest(nan).has_value());
  EXPECT_FALSE(index.nearest(in, std::nan("")).has_value());
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
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_GT(sink, 0);
}

}  // namespace
}  // namespace sightline::camera
