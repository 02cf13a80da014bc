// TriangleIndex::segments_blocked (segments from one point, traced as Embree ray packets)
// against segment_blocked asked for each segment alone and against brute force
// (triangle_brute_force.h): fans of 1 to kMaxFan segments from a random point, to random
// points, to points on triangles, to a tight cluster (a character's body seen from a camera:
// the coherent case the packets are for), to the point itself, to points closer than the
// tolerance and to non-finite points. Every bit must be segment_blocked's answer, exactly
// (the camera's choices must not depend on which of the two asked), and agree with brute
// force outside its float ambiguity band. On random soups near the origin and 2 km away,
// the 100k-triangle procedural level and a real map (oa_thor).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "sightline/domains/camera/geometry/triangle_index.h"
#include "sightline/domains/camera/level/q3_level.h"
#include "triangle_brute_force.h"
#include "triangle_test_meshes.h"

namespace sightline::camera {
namespace {

using Eigen::Vector3d;
using test_meshes::procedural_level;
using test_meshes::random_soup;
using test_meshes::scale_of;

struct FanTally {
  int fans = 0, segments = 0, blocked = 0, clear = 0, ambiguous = 0;
};

void compare_fans(const TriangleMesh& mesh, const Aabb& region, int fans, std::uint64_t seed,
                  FanTally& tally) {
  const TriangleIndex index(mesh);
  const std::vector<brute::Triangle> tris = brute::triangles_of(mesh);
  const double tol = 1e-5 * scale_of(mesh);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1), body(-0.5, 0.5);
  auto somewhere = [&] { return test_meshes::random_point_in(region, rng); };
  auto on_triangle = [&] { return test_meshes::random_point_on(mesh, rng); };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Vector3d> ends;
  for (int f = 0; f < fans; ++f) {
    const Vector3d a = f % 5 == 0 ? on_triangle() : somewhere();
    const auto n = static_cast<std::size_t>(1 + rng() % TriangleIndex::kMaxFan);
    const Vector3d cluster = somewhere();
    ends.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t kind = rng() % 16;
      Vector3d b;
      if (kind < 6) {
        b = cluster + Vector3d(body(rng), 3 * body(rng), body(rng));
      } else if (kind < 10) {
        b = on_triangle();
      } else if (kind < 13) {
        b = somewhere();
      } else if (kind == 13) {
        b = a;  // a point: blocked when it lies on a triangle
      } else if (kind == 14) {
        b = a + Vector3d(unit(rng), unit(rng), unit(rng)) * 1e-3 * tol;
      } else {
        b = Vector3d(nan, 0, 0);
      }
      ends.push_back(b);
    }
    const std::uint32_t fan = index.segments_blocked(a, ends);
    ++tally.fans;
    if (n < 32) {
      ASSERT_EQ(fan >> n, 0u) << "bits beyond the fan's " << n << " segments";
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Vector3d& b = ends[i];
      const bool got = (fan >> i & 1u) != 0;
      SCOPED_TRACE(::testing::Message() << "fan " << f << ", segment " << i << " of " << n
                                        << ": (" << a.transpose() << ") -> (" << b.transpose()
                                        << ")");
      ASSERT_EQ(got, index.segment_blocked(a, b));
      ++tally.segments;
      if (!b.allFinite()) {
        ASSERT_FALSE(got);
        continue;
      }
      const brute::SegmentVerdict v = brute::judge_segment(tris, a, b, tol);
      if (v.must) {
        ASSERT_TRUE(got);
      }
      if (!v.may) {
        ASSERT_FALSE(got);
      }
      if (v.may && !v.must) ++tally.ambiguous;
      (got ? tally.blocked : tally.clear)++;
    }
  }
}

// Both answers are exercised, and the ambiguous band (where brute force accepts either) is
// rare: below 1 in `ambiguous_one_in` (a quarter of the ends lie on triangles, so more of
// them than in triangle_index_test; 2 km out the band is 2 cm wide).
void expect_both_answers(const FanTally& tally, int ambiguous_one_in) {
  ::testing::Test::RecordProperty("segments", tally.segments);
  ::testing::Test::RecordProperty("blocked", tally.blocked);
  ::testing::Test::RecordProperty("ambiguous", tally.ambiguous);
  EXPECT_GT(tally.blocked, tally.segments / 8);
  EXPECT_GT(tally.clear, tally.segments / 8);
  EXPECT_LT(tally.ambiguous, tally.segments / ambiguous_one_in) << tally.ambiguous << " ambiguous";
}

TEST(TriangleIndexPackets, AnswerAsSegmentBlockedAndBruteForceOnRandomSoups) {
  std::mt19937_64 rng(21);
  FanTally tally;
  for (int trial = 0; trial < 2; ++trial) {
    const TriangleMesh mesh = random_soup(rng, 1500, Vector3d::Zero());
    compare_fans(mesh, {Vector3d::Constant(-13), Vector3d::Constant(13)}, 400, 300 + trial,
                 tally);
    if (HasFatalFailure()) return;
  }
  expect_both_answers(tally, 25);
}

TEST(TriangleIndexPackets, AnswerAsSegmentBlockedFarFromTheOrigin) {
  std::mt19937_64 rng(22);
  const Vector3d offset(1500, 40, -2000);
  FanTally tally;
  compare_fans(random_soup(rng, 1500, offset),
               {offset - Vector3d::Constant(13), offset + Vector3d::Constant(13)}, 400, 8, tally);
  expect_both_answers(tally, 10);
}

TEST(TriangleIndexPackets, AnswerAsSegmentBlockedOnALargeProceduralLevel) {
  FanTally tally;
  compare_fans(procedural_level(), {Vector3d(-85, -5, -85), Vector3d(85, 12, 85)}, 60, 9, tally);
  expect_both_answers(tally, 25);
}

TEST(TriangleIndexPackets, AnswerAsSegmentBlockedOnARealQuake3Map) {
  LevelSpec spec;
  spec.file = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3";
  spec.map = "oa_thor";
  const Level level = load_quake3_level(spec, LevelTransform{0.03125, UpAxis::kZ});
  ASSERT_GT(level.mesh.size(), 1000u);
  FanTally tally;
  compare_fans(level.mesh, level.mesh.bounds(), 80, 10, tally);
  expect_both_answers(tally, 25);
}

TEST(TriangleIndexPackets, RefuseMoreThanKMaxFanSegmentsAndAnswerNothingFromABadPoint) {
  std::mt19937_64 rng(23);
  const TriangleIndex index(random_soup(rng, 200, Vector3d::Zero()));
  const std::vector<Vector3d> too_many(TriangleIndex::kMaxFan + 1, Vector3d(1, 2, 3));
  EXPECT_THROW(index.segments_blocked(Vector3d::Zero(), too_many), std::invalid_argument);
  const std::vector<Vector3d> ends(5, Vector3d(1, 2, 3));
  EXPECT_EQ(index.segments_blocked(Vector3d(std::nan(""), 0, 0), ends), 0u);
  EXPECT_EQ(index.segments_blocked(Vector3d::Zero(), {}), 0u);
  EXPECT_EQ(TriangleIndex().segments_blocked(Vector3d::Zero(), ends), 0u);
}

}  // namespace
}  // namespace sightline::camera
