// TriangleIndex on exact geometry: a closed box of 12 triangles (watertight through shared
// edges and corners, faces touched exactly by segment ends, zero-length and in-plane
// segments), normals, nearest points, and the index's contract (empty, moves, bad input).
#include <gtest/gtest.h>

#include <random>

#include "sightline/domains/camera/geometry/triangle_index.h"
#include "triangle_test_meshes.h"

namespace sightline::camera {
namespace {

using Eigen::Vector3d;
using test_meshes::box_mesh;
using test_meshes::scale_of;

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

}  // namespace
}  // namespace sightline::camera
