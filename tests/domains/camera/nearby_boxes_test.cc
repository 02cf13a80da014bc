// NearbyBoxes and SceneAtTime::set_nearby against brute force: on random box scenes (some
// snapped to a 0.5 m grid, so shared faces and exactly grazing sight lines are common),
// every segment NearbyBoxes covers is blocked exactly when a brute-force loop over all the
// scene's boxes says so, and a SceneAtTime with the list answers every sight line (inside
// the region or not, movers included) and every clearance as one without it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "sightline/domains/camera/geometry/segment_box.h"
#include "sightline/domains/camera/nearby_boxes.h"
#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::camera {
namespace {

using Eigen::Vector3d;

Scene random_scene(std::mt19937_64& rng, int n, bool snap, int movers) {
  std::uniform_real_distribution<double> pos(0, 40), size(0.1, 5);
  auto q = [&](double x) { return snap ? std::round(x * 2) / 2 : x; };
  std::vector<SolidBox> solids;
  for (int i = 0; i < n; ++i) {
    Aabb b;
    for (int a = 0; a < 3; ++a) {
      b.min[a] = q(pos(rng));
      b.max[a] = b.min[a] + std::max(snap ? 0.5 : 0.0, q(size(rng)));
    }
    solids.push_back({"b" + std::to_string(i), b, {}});
  }
  Scene scene("random", std::move(solids), {}, {},
              Trajectory({{0, {20, 0, 20}, 0}, {10, {25, 0, 20}, 0}}));
  std::vector<Mover> ms;
  for (int i = 0; i < movers; ++i) {
    ms.emplace_back("m" + std::to_string(i), Vector3d(1, 2, 1),
                    std::vector<MoverKeyframe>{{0, {pos(rng), 0, pos(rng)}},
                                               {10, {pos(rng), 0, pos(rng)}}});
  }
  scene.set_movers(std::move(ms));
  return scene;
}

bool brute_blocked(const Scene& scene, const Vector3d& a, const Vector3d& b) {
  SegmentClip clip;
  for (const SolidBox& s : scene.solids()) {
    if (clip_segment_to_box(a, b - a, s.box, 1.0, clip)) return true;
  }
  return false;
}

Vector3d point_in(std::mt19937_64& rng, const Aabb& box, bool snap) {
  Vector3d p;
  for (int a = 0; a < 3; ++a) {
    p[a] = std::uniform_real_distribution<double>(box.min[a], box.max[a])(rng);
    if (snap) p[a] = std::clamp(std::round(p[a] * 2) / 2, box.min[a], box.max[a]);
  }
  return p;
}

bool covers_nothing(const NearbyBoxes& nearby) {
  return !(nearby.region().min.array() <= nearby.region().max.array()).all();
}

class NearbyBoxesAgainstBruteForce : public ::testing::TestWithParam<bool> {};

TEST_P(NearbyBoxesAgainstBruteForce, AnswersEveryCoveredSegmentLikeEveryBoxTestedInTurn) {
  const bool snap = GetParam();
  std::mt19937_64 rng(31 + snap);
  const Scene scene = random_scene(rng, 300, snap, 0);
  NearbyBoxes nearby(scene);
  EXPECT_TRUE(covers_nothing(nearby));  // until cover()
  std::uniform_real_distribution<double> pos(0, 40), extent(0.5, 4);
  int blocked = 0, clear = 0, rebuilt = 0;
  for (int r = 0; r < 200; ++r) {
    const Vector3d c(pos(rng), pos(rng), pos(rng));
    const Vector3d h(extent(rng), extent(rng), extent(rng));
    const Aabb needed{c - h, c + h};
    const Aabb before = nearby.region();
    nearby.cover(needed);
    if (nearby.region().min != before.min || nearby.region().max != before.max) ++rebuilt;
    if (covers_nothing(nearby)) continue;  // too many boxes: nothing covered
    ASSERT_TRUE(nearby.region().contains(needed.min) && nearby.region().contains(needed.max));
    ASSERT_LE(nearby.size(), NearbyBoxes::kCapacity);
    for (int s = 0; s < 100; ++s) {
      const Vector3d a = point_in(rng, nearby.region(), snap);
      Vector3d b = point_in(rng, nearby.region(), snap);
      if (s % 7 == 0) b.y() = a.y();  // axis-parallel segments too
      ASSERT_TRUE(nearby.covers(a, b));
      const bool want = brute_blocked(scene, a, b);
      ASSERT_EQ(nearby.segment_blocked(a, b), want) << "region " << r << " segment " << s;
      ASSERT_EQ(scene.solid_tree().segment_blocked(a, b), want);
      (want ? blocked : clear) += 1;
    }
  }
  EXPECT_GT(blocked, 1000);
  EXPECT_GT(clear, 1000);
  EXPECT_GT(rebuilt, 50);
}

INSTANTIATE_TEST_SUITE_P(Grids, NearbyBoxesAgainstBruteForce, ::testing::Bool());

TEST(NearbyBoxes, KeepsItsListWhileTheRegionFitsAndCoversNothingWhenTooManyBoxesTouchIt) {
  std::mt19937_64 rng(3);
  // 2,000 boxes in a 40 m cube: a 30 m region touches far more than kCapacity.
  const Scene dense = random_scene(rng, 2000, false, 0);
  NearbyBoxes nearby(dense);
  nearby.cover({Vector3d(5, 5, 5), Vector3d(35, 35, 35)});
  EXPECT_TRUE(covers_nothing(nearby));
  EXPECT_FALSE(nearby.covers(Vector3d(20, 20, 20), Vector3d(21, 20, 20)));
  // A small region fits, with the margin around it; a region inside it changes nothing.
  nearby.cover({Vector3d(20, 20, 20), Vector3d(20.5, 20.5, 20.5)});
  ASSERT_FALSE(covers_nothing(nearby));
  const Aabb first = nearby.region();
  EXPECT_LE(first.min.x(), 20 - NearbyBoxes::kMargin + 1e-9);
  nearby.cover({Vector3d(19, 19, 19), Vector3d(21, 21, 21)});
  EXPECT_EQ(nearby.region().min, first.min);
  EXPECT_EQ(nearby.region().max, first.max);
}

TEST(SceneAtTime, AnswersEverySightLineAndClearanceTheSameWithTheNearbyBoxes) {
  for (bool snap : {false, true}) {
    std::mt19937_64 rng(41 + snap);
    const Scene scene = random_scene(rng, 150, snap, 40);
    SceneAtTime plain(scene), with(scene);
    NearbyBoxes nearby(scene);
    with.set_nearby(&nearby);
    std::uniform_real_distribution<double> pos(-2, 42), time(0, 10), extent(1, 6), u(0, 1);
    int inside = 0, outside = 0, blocked = 0, near_wall = 0;
    for (int r = 0; r < 150; ++r) {
      const double t = time(rng);
      const Vector3d c(pos(rng), pos(rng), pos(rng));
      const Vector3d h(extent(rng), extent(rng), extent(rng));
      // Covered before set_time (the movers near the region are listed) or after it (their
      // list is of the region before: segments outside it take the grouped path).
      const bool cover_first = r % 3 != 0;
      if (cover_first) nearby.cover({c - h, c + h});
      plain.set_time(t);
      with.set_time(t);
      if (!cover_first) nearby.cover({c - h, c + h});
      for (int s = 0; s < 100; ++s) {
        Vector3d a, b;
        if (s % 4 != 0 && !covers_nothing(nearby)) {
          a = point_in(rng, nearby.region(), snap);
          b = point_in(rng, nearby.region(), snap);
        } else {
          a = Vector3d(pos(rng), pos(rng), pos(rng));
          b = Vector3d(pos(rng), pos(rng), pos(rng));
        }
        (nearby.covers(a, b) ? inside : outside) += 1;
        const bool want = plain.line_of_sight(a, b);
        ASSERT_EQ(with.line_of_sight(a, b), want) << "region " << r << " segment " << s;
        ASSERT_EQ(with.mover_blocks(a, b), plain.mover_blocks(a, b)) << "region " << r;
        blocked += !want;
        for (double limit : {0.0, 0.2, 1.0, 3.0, std::numeric_limits<double>::infinity()}) {
          const double d = plain.clearance(a, limit);
          ASSERT_EQ(with.clearance(a, limit), d) << "region " << r << " point " << s;
          near_wall += d < limit;
        }
      }
    }
    EXPECT_GT(inside, 5000);
    EXPECT_GT(outside, 1000);
    EXPECT_GT(blocked, 1000);
    EXPECT_GT(near_wall, 1000);
  }
}

}  // namespace
}  // namespace sightline::camera
