// The slab test against an exact reference on random integer segments and boxes.
//
// With integer coordinates every candidate entry parameter is a ratio of small integers, so
// the reference below can decide hits exactly; and integer inputs make parallel segments,
// segments grazing faces, edges and corners, and segments starting inside or on a box common
// rather than rare. The reference does not use slabs: the part of a segment inside a convex
// box is an interval [t0, t1], and t0 is either 0 or a parameter where the segment crosses
// one of the six face planes, so t0 is the smallest such candidate whose point is in the box.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "sightline/domains/camera/geometry/segment_box.h"

namespace sightline::camera {
namespace {

using I3 = std::array<std::int64_t, 3>;

struct Fraction {
  std::int64_t num, den;  // den > 0
  bool operator<(const Fraction& o) const { return num * o.den < o.num * den; }
  double value() const { return static_cast<double>(num) / static_cast<double>(den); }
};

// Is origin + (num/den) * delta inside the closed box lo..hi? Exact in integers.
bool inside_at(const I3& o, const I3& d, const I3& lo, const I3& hi, const Fraction& t) {
  for (int i = 0; i < 3; ++i) {
    const std::int64_t scaled = o[i] * t.den + t.num * d[i];  // coordinate x den
    if (scaled < lo[i] * t.den || scaled > hi[i] * t.den) return false;
  }
  return true;
}

std::optional<Fraction> reference_entry(const I3& o, const I3& d, const I3& lo, const I3& hi,
                                        std::int64_t t_max) {
  std::vector<Fraction> candidates = {{0, 1}, {t_max, 1}};
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0) continue;
    for (std::int64_t bound : {lo[i], hi[i]}) {
      Fraction t{bound - o[i], d[i]};
      if (t.den < 0) t = {-t.num, -t.den};
      if (t.num >= 0 && t.num <= t_max * t.den) candidates.push_back(t);
    }
  }
  std::optional<Fraction> best;
  for (const Fraction& t : candidates) {
    if (inside_at(o, d, lo, hi, t) && (!best || t < *best)) best = t;
  }
  return best;
}

Eigen::Vector3d vec(const I3& v) {
  return {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
}

TEST(SegmentBox, AgreesWithAnExactReferenceOnRandomIntegerSegments) {
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<int> coord(-6, 6);
  std::uniform_int_distribution<int> corner(-4, 3);
  std::uniform_int_distribution<int> extent(1, 4);
  std::uniform_int_distribution<int> pick(0, 9);
  int hits = 0, parallel = 0, starts_inside = 0, grazing = 0;
  for (int trial = 0; trial < 300000; ++trial) {
    I3 lo, hi, o, d;
    for (int i = 0; i < 3; ++i) {
      lo[i] = corner(rng);
      hi[i] = lo[i] + extent(rng);
      o[i] = coord(rng);
      // Zero components often, to exercise parallel segments.
      d[i] = pick(rng) < 3 ? 0 : coord(rng) * 2;
    }
    const std::int64_t t_max = pick(rng) < 7 ? 1 : 3;
    const auto expected = reference_entry(o, d, lo, hi, t_max);
    const Aabb box{vec(lo), vec(hi)};
    SegmentClip clip;
    const bool hit = clip_segment_to_box(vec(o), vec(d), box, static_cast<double>(t_max), clip);
    ASSERT_EQ(hit, expected.has_value())
        << "origin " << vec(o).transpose() << " delta " << vec(d).transpose() << " box "
        << box.min.transpose() << " / " << box.max.transpose() << " t_max " << t_max;
    if (hit) {
      ++hits;
      ASSERT_EQ(clip.enter, expected->value()) << "origin " << vec(o).transpose() << " delta "
                                               << vec(d).transpose();
      ASSERT_LE(clip.enter, clip.exit);
      if (clip.enter == clip.exit) ++grazing;
      if (expected->num == 0) ++starts_inside;
    }
    if (d[0] == 0 || d[1] == 0 || d[2] == 0) ++parallel;
  }
  // The random cases really cover the special situations.
  EXPECT_GT(hits, 10000);
  EXPECT_GT(parallel, 100000);
  EXPECT_GT(starts_inside, 5000);
  EXPECT_GT(grazing, 1000);
}

const Aabb kUnit{{0, 0, 0}, {1, 1, 1}};

bool hits(Eigen::Vector3d a, Eigen::Vector3d b) { return segment_hits_box(a, b, kUnit); }

TEST(SegmentBox, ParallelSegmentHitsOnlyWithinTheSlab) {
  EXPECT_TRUE(hits({-1, 0.5, 0.5}, {2, 0.5, 0.5}));   // along x through the middle
  EXPECT_FALSE(hits({-1, 1.5, 0.5}, {2, 1.5, 0.5}));  // above the box
  EXPECT_FALSE(hits({-1, 0.5, -0.1}, {2, 0.5, -0.1}));
}

TEST(SegmentBox, TouchingAFaceAnEdgeOrACornerCountsAsAHit) {
  EXPECT_TRUE(hits({-1, 1, 0.5}, {2, 1, 0.5}));   // slides along the top face
  EXPECT_TRUE(hits({-1, 1, 1}, {2, 1, 1}));       // along a top edge
  EXPECT_TRUE(hits({-1, 0, 0.5}, {1, 2, 0.5}));   // diagonal, touching the top-left edge only
  EXPECT_TRUE(hits({2, 2, 2}, {1, 1, 1}));        // ends on a corner
  EXPECT_TRUE(hits({-1, -1, -1}, {0, 0, 0}));     // ... or on the opposite corner
  EXPECT_FALSE(hits({-1, 0.0001, 0.5}, {1, 2.0001, 0.5}));  // just misses the edge
  EXPECT_FALSE(hits({2, 2, 2}, {1.0001, 1.0001, 1.0001}));  // stops just short of the corner
}

TEST(SegmentBox, SegmentStartingInsideHitsAtZero) {
  SegmentClip clip;
  ASSERT_TRUE(clip_segment_to_box({0.5, 0.5, 0.5}, {3, 0, 0}, kUnit, 1.0, clip));
  EXPECT_EQ(clip.enter, 0.0);
  EXPECT_DOUBLE_EQ(clip.exit, 0.5 / 3);
  // On the boundary, leaving: still a hit at 0 (closed box).
  ASSERT_TRUE(clip_segment_to_box({1, 0.5, 0.5}, {3, 0, 0}, kUnit, 1.0, clip));
  EXPECT_EQ(clip.enter, 0.0);
  EXPECT_EQ(clip.exit, 0.0);
}

TEST(SegmentBox, ZeroLengthSegmentIsAPointTest) {
  EXPECT_TRUE(hits({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}));
  EXPECT_TRUE(hits({1, 1, 1}, {1, 1, 1}));
  EXPECT_FALSE(hits({1.5, 0.5, 0.5}, {1.5, 0.5, 0.5}));
}

TEST(SegmentBox, SegmentStoppingShortOfTheBoxMisses) {
  EXPECT_FALSE(hits({-2, 0.5, 0.5}, {-0.001, 0.5, 0.5}));
  EXPECT_TRUE(hits({-2, 0.5, 0.5}, {0, 0.5, 0.5}));
  // As a longer ray (t_max = 2) it reaches the box at t = 1.
  SegmentClip clip;
  ASSERT_TRUE(clip_segment_to_box({-2, 0.5, 0.5}, {2, 0, 0}, kUnit, 2.0, clip));
  EXPECT_EQ(clip.enter, 1.0);
  EXPECT_EQ(clip.exit, 1.5);
}

TEST(SegmentBox, TinyDirectionComponentsDoNotProduceNaN) {
  SegmentClip clip;
  const double tiny = 1e-310;  // subnormal
  ASSERT_TRUE(clip_segment_to_box({0.5, 0.5, 0.5}, {tiny, 1, -tiny}, kUnit, 1.0, clip));
  EXPECT_EQ(clip.enter, 0.0);
  EXPECT_EQ(clip.exit, 0.5);
  EXPECT_FALSE(clip_segment_to_box({2, 0.5, 0.5}, {tiny, 1, 0}, kUnit, 1.0, clip));
}

}  // namespace
}  // namespace sightline::camera
