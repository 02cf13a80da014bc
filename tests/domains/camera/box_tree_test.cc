// The BVH answers exactly as brute force does, on random scenes: sight lines, first hits
// (parameter and box, ties to the smaller index), nearest boxes, containment, overlap and
// touching.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "sightline/domains/camera/geometry/box_tree.h"

namespace sightline::camera {
namespace {

struct RandomScene {
  std::vector<Aabb> boxes;
  double world;
};

// n boxes in a cube of side `world`. With `snap`, coordinates are multiples of 0.5, which
// makes shared faces, coincident boxes and exact grazing common.
RandomScene make_scene(std::mt19937_64& rng, int n, double world, bool snap) {
  std::uniform_real_distribution<double> pos(0, world);
  std::uniform_real_distribution<double> size(0.05, world / 6);
  auto q = [&](double x) { return snap ? std::round(x * 2) / 2 : x; };
  RandomScene s{{}, world};
  for (int i = 0; i < n; ++i) {
    Aabb b;
    for (int a = 0; a < 3; ++a) {
      b.min[a] = q(pos(rng));
      b.max[a] = b.min[a] + std::max(snap ? 0.5 : 0.0, q(size(rng)));
    }
    s.boxes.push_back(b);
  }
  return s;
}

Eigen::Vector3d random_point(std::mt19937_64& rng, double world, bool snap) {
  std::uniform_real_distribution<double> pos(-0.1 * world, 1.1 * world);
  Eigen::Vector3d p(pos(rng), pos(rng), pos(rng));
  if (snap) p = (p * 2).array().round() / 2;
  return p;
}

std::optional<BoxTree::Hit> brute_first_hit(const std::vector<Aabb>& boxes,
                                            const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  std::optional<BoxTree::Hit> best;
  SegmentClip clip;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (clip_segment_to_box(a, b - a, boxes[i], 1.0, clip) && (!best || clip.enter < best->t)) {
      best = BoxTree::Hit{clip.enter, i};  // strict <: the smallest index wins ties
    }
  }
  return best;
}

class BoxTreeAgainstBruteForce : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(BoxTreeAgainstBruteForce, AnswersEveryQueryExactlyLikeBruteForce) {
  const auto [n, snap] = GetParam();
  std::mt19937_64 rng(1000 + n * 2 + snap);
  const RandomScene scene = make_scene(rng, n, 20.0, snap);
  const BoxTree tree(scene.boxes);
  ASSERT_EQ(tree.size(), scene.boxes.size());
  const int queries = 3000;
  int blocked = 0, inside = 0;
  for (int q = 0; q < queries; ++q) {
    const Eigen::Vector3d a = random_point(rng, scene.world, snap);
    Eigen::Vector3d b = random_point(rng, scene.world, snap);
    if (q % 5 == 0) b = a + (b - a) * 0.1;  // short segments too
    if (q % 7 == 0) b.y() = a.y();          // and axis-parallel ones
    if (q % 11 == 0) b.x() = a.x();

    const auto expected = brute_first_hit(scene.boxes, a, b);
    ASSERT_EQ(tree.segment_blocked(a, b), expected.has_value()) << "query " << q;
    const auto hit = tree.first_hit(a, b);
    ASSERT_EQ(hit.has_value(), expected.has_value()) << "query " << q;
    if (expected) {
      ++blocked;
      ASSERT_EQ(hit->t, expected->t) << "query " << q;
      ASSERT_EQ(hit->box, expected->box) << "query " << q;
    }

    // Nearest box, unbounded and with a limit.
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_box = 0;
    for (std::uint32_t i = 0; i < scene.boxes.size(); ++i) {
      const double d = scene.boxes[i].signed_distance(a);
      if (d < best) best = d, best_box = i;
    }
    if (best < 0) ++inside;
    const auto nearest = tree.nearest(a);
    ASSERT_EQ(nearest.has_value(), !scene.boxes.empty());
    if (nearest) {
      ASSERT_EQ(nearest->signed_distance, best) << "query " << q;
      ASSERT_EQ(nearest->box, best_box) << "query " << q;
    }
    for (double limit : {0.0, 0.2, 1.0}) {
      const auto bounded = tree.nearest(a, limit);
      ASSERT_EQ(bounded.has_value(), best < limit) << "query " << q << " limit " << limit;
      if (bounded) {
        ASSERT_EQ(bounded->signed_distance, best);
      }
    }

    // Containment.
    std::set<std::uint32_t> expected_in, got_in;
    for (std::uint32_t i = 0; i < scene.boxes.size(); ++i) {
      if (scene.boxes[i].contains(a)) expected_in.insert(i);
    }
    tree.for_each_containing(a, [&](std::uint32_t i) { ASSERT_TRUE(got_in.insert(i).second); });
    ASSERT_EQ(got_in, expected_in) << "query " << q;

    // Interior overlap with a random box.
    Aabb probe{a.cwiseMin(b), a.cwiseMax(b)};
    probe.max = probe.min + (probe.max - probe.min) * 0.2;
    std::optional<std::uint32_t> expected_overlap;
    for (std::uint32_t i = 0; i < scene.boxes.size() && !expected_overlap; ++i) {
      if (scene.boxes[i].overlaps_interior(probe)) expected_overlap = i;
    }
    ASSERT_EQ(tree.any_overlapping(probe), expected_overlap) << "query " << q;

    // Every box touching a random box (closed: shared faces count).
    std::set<std::uint32_t> expected_touching, got_touching;
    for (std::uint32_t i = 0; i < scene.boxes.size(); ++i) {
      const Aabb& c = scene.boxes[i];
      if ((c.min.array() <= probe.max.array()).all() && (probe.min.array() <= c.max.array()).all()) {
        expected_touching.insert(i);
      }
    }
    tree.for_each_touching(probe, [&](std::uint32_t i) {
      ASSERT_TRUE(got_touching.insert(i).second);
    });
    ASSERT_EQ(got_touching, expected_touching) << "query " << q;
  }
  if (n >= 50) {
    // The scenes are neither empty nor solid: both answers occur often.
    EXPECT_GT(blocked, queries / 10);
    EXPECT_LT(blocked, queries);
    EXPECT_GT(inside, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(RandomScenes, BoxTreeAgainstBruteForce,
                         ::testing::Combine(::testing::Values(0, 1, 2, 7, 50, 400, 2000),
                                            ::testing::Bool()));

TEST(BoxTree, CoincidentBoxesStillBuildAShallowTree) {
  std::vector<Aabb> boxes(1000, Aabb{{0, 0, 0}, {1, 1, 1}});
  const BoxTree tree(boxes);
  EXPECT_LE(tree.depth(), 20);
  const auto hit = tree.first_hit({-1, 0.5, 0.5}, {2, 0.5, 0.5});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->box, 0u);  // all tie at t = 1/3: the smallest index
  EXPECT_DOUBLE_EQ(hit->t, 1.0 / 3);
}

TEST(BoxTree, DepthGrowsLogarithmically) {
  std::mt19937_64 rng(7);
  const RandomScene scene = make_scene(rng, 20000, 200.0, false);
  const BoxTree tree(scene.boxes);
  EXPECT_LE(tree.depth(), 40);  // log2(20000 / 2) is about 13; SAH trees are a bit deeper
}

TEST(BoxTree, CoordinatesBeyondFloatRangeStillAnswerExactly) {
  // Node bounds are floats: beyond their range they become infinite, never wrong.
  const std::vector<Aabb> boxes = {{{1e300, 0, 0}, {2e300, 1, 1}},
                                   {{-5, -5, -5}, {-4, -4, -4}},
                                   {{0, 0, 0}, {1, 1, 1}}};
  const BoxTree tree(boxes);
  EXPECT_TRUE(tree.segment_blocked({0.5e300, 0.5, 0.5}, {3e300, 0.5, 0.5}));
  EXPECT_FALSE(tree.segment_blocked({0.5e300, 2, 0.5}, {3e300, 2, 0.5}));
  const auto hit = tree.first_hit({-10, -4.5, -4.5}, {10, -4.5, -4.5});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->box, 1u);
  EXPECT_DOUBLE_EQ(tree.nearest({1.5e300, 3, 0.5})->signed_distance, 2.0);
}

TEST(BoxTree, EmptyTreeAnswersNothing) {
  const BoxTree tree;
  EXPECT_FALSE(tree.segment_blocked({0, 0, 0}, {1, 1, 1}));
  EXPECT_FALSE(tree.first_hit({0, 0, 0}, {1, 1, 1}));
  EXPECT_FALSE(tree.nearest({0, 0, 0}));
  EXPECT_FALSE(tree.any_overlapping(Aabb{{0, 0, 0}, {1, 1, 1}}));
}

TEST(Aabb, SignedDistanceIsEuclideanOutsideAndMinusTheDepthInside) {
  const Aabb box{{0, 0, 0}, {2, 4, 6}};
  EXPECT_DOUBLE_EQ(box.signed_distance({3, 2, 3}), 1.0);          // off a face
  EXPECT_DOUBLE_EQ(box.signed_distance({3, 5, 3}), std::sqrt(2));  // off an edge
  EXPECT_DOUBLE_EQ(box.signed_distance({-1, -2, 8}), 3.0);         // off a corner: sqrt(1+4+4)
  EXPECT_DOUBLE_EQ(box.signed_distance({1, 2, 3}), -1.0);          // centre: 1 from x faces
  EXPECT_DOUBLE_EQ(box.signed_distance({0.25, 2, 3}), -0.25);
  EXPECT_EQ(box.signed_distance({2, 2, 3}), 0.0);                  // on a face
}

TEST(Aabb, TouchingBoxesDoNotOverlap) {
  const Aabb floor{{-5, -1, -5}, {5, 0, 5}};
  const Aabb body = Aabb::around_feet({0, 0, 0}, {0.6, 1.8, 0.6});
  EXPECT_FALSE(floor.overlaps_interior(body));
  EXPECT_TRUE(floor.overlaps_interior(Aabb::around_feet({0, -0.01, 0}, {0.6, 1.8, 0.6})));
  EXPECT_DOUBLE_EQ(body.min.x(), -0.3);
  EXPECT_DOUBLE_EQ(body.max.y(), 1.8);
}

}  // namespace
}  // namespace sightline::camera
