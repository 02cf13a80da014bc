// SceneAtTime against brute force: random static boxes and random movers, queried at random
// times; the expected answers come from the movers' keyframes interpolated here and a slab
// test and point-box distance written here, over every box. Fans of sight lines from one
// point (lines_of_sight, static_blocked) likewise, and on a level against line_of_sight.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::camera {
namespace {

struct Box {
  Eigen::Vector3d min, max;
};

// Closed segment against closed box by sampling-free slab clipping, written independently.
bool touches(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Box& box, double* enter) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 3; ++i) {
    const double d = b[i] - a[i];
    if (std::abs(d) < 1e-300) {
      if (a[i] < box.min[i] || a[i] > box.max[i]) return false;
      continue;
    }
    double t0 = (box.min[i] - a[i]) / d, t1 = (box.max[i] - a[i]) / d;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
    if (lo > hi) return false;
  }
  *enter = lo;
  return true;
}

// Signed distance to a box: outside, the Euclidean distance; inside, minus the depth.
double signed_distance(const Eigen::Vector3d& p, const Box& box) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  double depth = std::numeric_limits<double>::infinity();
  bool inside = true;
  for (int i = 0; i < 3; ++i) {
    if (p[i] < box.min[i]) { out[i] = box.min[i] - p[i]; inside = false; }
    if (p[i] > box.max[i]) { out[i] = p[i] - box.max[i]; inside = false; }
    depth = std::min({depth, p[i] - box.min[i], box.max[i] - p[i]});
  }
  return inside ? -depth : out.norm();
}

struct World {
  std::vector<Box> statics;
  std::vector<std::vector<std::pair<double, Eigen::Vector3d>>> paths;
  std::vector<Eigen::Vector3d> sizes;

  std::vector<Box> at(double t) const {
    std::vector<Box> all = statics;
    for (std::size_t m = 0; m < paths.size(); ++m) {
      const auto& path = paths[m];
      Eigen::Vector3d p = path.front().second;
      if (t >= path.back().first) p = path.back().second;
      for (std::size_t k = 0; k + 1 < path.size(); ++k) {
        if (t >= path[k].first && t < path[k + 1].first) {
          const double u = (t - path[k].first) / (path[k + 1].first - path[k].first);
          p = (1 - u) * path[k].second + u * path[k + 1].second;
        }
      }
      const Eigen::Vector3d& s = sizes[m];
      all.push_back({p - Eigen::Vector3d(s.x() / 2, 0, s.z() / 2),
                     p + Eigen::Vector3d(s.x() / 2, s.y(), s.z() / 2)});
    }
    return all;
  }
};

Scene random_scene(std::mt19937& rng, World& world, int mover_count) {
  std::uniform_real_distribution<double> coord(-10, 10), extent(0.3, 3), when(0, 10);
  std::vector<SolidBox> solids;
  for (int i = 0; i < 12; ++i) {
    const Eigen::Vector3d lo(coord(rng), coord(rng) * 0.2, coord(rng));
    const Eigen::Vector3d hi = lo + Eigen::Vector3d(extent(rng), extent(rng), extent(rng));
    solids.push_back({"", {lo, hi}, {}});
    world.statics.push_back({lo, hi});
  }
  std::vector<Mover> movers;
  for (int m = 0; m < mover_count; ++m) {
    const Eigen::Vector3d size(extent(rng), extent(rng), extent(rng));
    std::vector<MoverKeyframe> path;
    std::vector<double> times;
    const int keys = 1 + m % 4;
    for (int k = 0; k < keys; ++k) times.push_back(when(rng));
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    std::vector<std::pair<double, Eigen::Vector3d>> mine;
    for (double t : times) {
      const Eigen::Vector3d p(coord(rng), coord(rng) * 0.1, coord(rng));
      path.push_back({t, p});
      mine.push_back({t, p});
    }
    movers.emplace_back("m", size, path);
    world.paths.push_back(mine);
    world.sizes.push_back(size);
  }
  Scene scene("random", std::move(solids), {}, {},
              Trajectory({{0, {0, 0, 0}, 0}, {10, {0, 0, 1}, 0}}));
  scene.set_movers(std::move(movers));
  return scene;
}

// A few movers (one group) and many (several groups, most skipped by their bounds).
// A level of 300 random triangles up to 3 m across around the scene's boxes (x, z in
// [-10, 10], y in [-3, 3]).
std::shared_ptr<Level> random_soup_level(std::mt19937& rng) {
  auto level = std::make_shared<Level>();
  std::uniform_real_distribution<double> coord(-10, 10), spread(-1.5, 1.5);
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d c(coord(rng), coord(rng) * 0.3, coord(rng));
    const auto base = static_cast<std::uint32_t>(level->mesh.vertices.size());
    for (int k = 0; k < 3; ++k) {
      level->mesh.vertices.push_back(
          (c + Eigen::Vector3d(spread(rng), spread(rng), spread(rng))).cast<float>());
    }
    level->mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return level;
}

class SceneAtTimeAgrees : public ::testing::TestWithParam<int> {};

TEST_P(SceneAtTimeAgrees, QueriesAgreeWithBruteForceOverStaticBoxesAndPlacedMovers) {
  const int mover_count = GetParam();
  std::mt19937 rng(7 + mover_count);
  std::uniform_real_distribution<double> coord(-12, 12), when(-1, 11);
  int blocked = 0, mover_first = 0, inside = 0, fan_blocked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    World world;
    const Scene scene = random_scene(rng, world, mover_count);
    SceneAtTime now(scene);
    double t = when(rng);
    for (int step = 0; step < 40; ++step) {
      // Times mostly advance frame by frame (the cursor path), sometimes jump back.
      t = step % 10 == 9 ? when(rng) : t + 0.1;
      now.set_time(t);
      const std::vector<Box> boxes = world.at(t);
      for (std::size_t m = 0; m < world.paths.size(); ++m) {
        const Box& expected = boxes[world.statics.size() + m];
        ASSERT_TRUE(now.mover_boxes()[m].min.isApprox(expected.min, 1e-9));
        ASSERT_TRUE(now.mover_boxes()[m].max.isApprox(expected.max, 1e-9));
      }
      for (int q = 0; q < 10; ++q) {
        const Eigen::Vector3d a(coord(rng), coord(rng) * 0.3, coord(rng));
        const Eigen::Vector3d b(coord(rng), coord(rng) * 0.3, coord(rng));
        double first = 2, enter = 0;
        std::size_t which = 0;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          if (touches(a, b, boxes[i], &enter) && enter < first) {
            first = enter;
            which = i;
          }
        }
        const bool expect_blocked = first <= 1;
        blocked += expect_blocked;
        ASSERT_EQ(now.line_of_sight(a, b), !expect_blocked);
        const auto hit = now.first_hit(a, b);
        ASSERT_EQ(hit.has_value(), expect_blocked);
        if (hit) {
          EXPECT_NEAR(hit->t, first, 1e-9);
          if (which >= world.statics.size() && hit->source == SurfaceHit::Source::kMover) {
            ++mover_first;
            EXPECT_EQ(hit->index, which - world.statics.size());
          }
        }
        double nearest = std::numeric_limits<double>::infinity();
        for (const Box& box : boxes) nearest = std::min(nearest, signed_distance(a, box));
        inside += nearest < 0;
        EXPECT_NEAR(now.clearance(a), nearest, 1e-9);
        EXPECT_NEAR(now.clearance(a, 0.5), std::min(nearest, 0.5), 1e-9);
        const auto surface = now.nearest_surface(a, 100);
        ASSERT_TRUE(surface);
        EXPECT_NEAR(surface->signed_distance, nearest, 1e-9);
        EXPECT_EQ(now.open_at(a), nearest > 0);
      }
      // A fan of sight lines from one point (lines_of_sight, static_blocked): bit for bit
      // the slab test over every box, and over the static ones only.
      const Eigen::Vector3d a(coord(rng), coord(rng) * 0.3, coord(rng));
      std::vector<Eigen::Vector3d> ends(1 + rng() % 12);
      for (auto& b : ends) b = Eigen::Vector3d(coord(rng), coord(rng) * 0.3, coord(rng));
      std::uint32_t want_clear = 0, want_static = 0;
      for (std::size_t i = 0; i < ends.size(); ++i) {
        double enter = 0;
        bool any = false, any_static = false;
        for (std::size_t k = 0; k < boxes.size(); ++k) {
          if (!touches(a, ends[i], boxes[k], &enter)) continue;
          any = true;
          any_static = any_static || k < world.statics.size();
        }
        if (!any) want_clear |= 1u << i;
        if (any_static) want_static |= 1u << i;
      }
      ASSERT_FALSE(now.packs_sight_lines());
      ASSERT_EQ(now.lines_of_sight(a, ends), want_clear);
      ASSERT_EQ(now.static_blocked(a, ends), want_static);
      fan_blocked += std::popcount(want_static);
    }
  }
  EXPECT_GT(fan_blocked, 500);
  // The random worlds exercised every branch.
  EXPECT_GT(blocked, 500);
  EXPECT_GT(mover_first, 50);
  EXPECT_GT(inside, 20);
}

INSTANTIATE_TEST_SUITE_P(FlatAndTree, SceneAtTimeAgrees, ::testing::Values(6, 40));

// On a level, a fan of sight lines goes to the triangles as ray packets: every bit is what
// line_of_sight answers for that line alone (itself checked against brute force above and in
// triangle_index_test), and static_blocked is the static Scene's answer (no movers).
TEST(SceneAtTime, FansOfSightLinesOnALevelAnswerAsLineOfSightOneByOne) {
  std::mt19937 rng(31);
  World world;
  Scene scene = random_scene(rng, world, 20);
  auto level = random_soup_level(rng);
  std::uniform_real_distribution<double> coord(-10, 10), when(-1, 11);
  scene.set_level(level);
  SceneAtTime now(scene);
  ASSERT_TRUE(now.packs_sight_lines());
  int clear = 0, blocked = 0, by_mover = 0;
  std::uniform_real_distribution<double> body(-0.4, 0.4);
  for (int trial = 0; trial < 400; ++trial) {
    now.set_time(when(rng));
    const Eigen::Vector3d a(coord(rng), 1 + coord(rng) * 0.2, coord(rng));
    const Eigen::Vector3d target(coord(rng), 1, coord(rng));
    std::vector<Eigen::Vector3d> ends(1 + rng() % TriangleIndex::kMaxFan);
    for (auto& b : ends) {
      // Most toward one body-sized region (a camera's sight lines), some anywhere.
      b = rng() % 4 != 0 ? Eigen::Vector3d(target + Eigen::Vector3d(body(rng), 2 * body(rng),
                                                                    body(rng)))
                         : Eigen::Vector3d(coord(rng), coord(rng) * 0.3, coord(rng));
    }
    const std::uint32_t sight = now.lines_of_sight(a, ends);
    const std::uint32_t fixed = now.static_blocked(a, ends);
    for (std::size_t i = 0; i < ends.size(); ++i) {
      const bool sees = now.line_of_sight(a, ends[i]);
      ASSERT_EQ((sight >> i & 1u) != 0, sees) << "trial " << trial << " line " << i;
      ASSERT_EQ((fixed >> i & 1u) != 0, !scene.line_of_sight(a, ends[i]))
          << "trial " << trial << " line " << i;
      (sees ? clear : blocked)++;
      by_mover += !sees && (fixed >> i & 1u) == 0;
    }
    if (ends.size() < 32) {
      ASSERT_EQ(sight >> ends.size(), 0u);
    }
  }
  EXPECT_GT(clear, 1000);
  EXPECT_GT(blocked, 1000);
  EXPECT_GT(by_mover, 20);
}

// closer_than(p, r, limit) is clearance(p, limit) < r, on a level with a solid volume (a
// slab below the ground), boxes and movers: every part that can decide it is exercised.
class SlabBelow : public SolidVolume {
 public:
  bool solid_at(const Eigen::Vector3d& p) const override { return p.y() < -1; }
  std::string describe() const override { return "slab"; }
};

TEST(SceneAtTime, CloserThanIsClearanceBelowTheRadius) {
  std::mt19937 rng(41);
  World world;
  Scene scene = random_scene(rng, world, 20);
  auto level = random_soup_level(rng);
  std::uniform_real_distribution<double> coord(-10, 10), when(-1, 11), radius(0.05, 1.0);
  level->solid = std::make_shared<SlabBelow>();
  scene.set_level(level);
  SceneAtTime now(scene);
  int closer = 0, clear = 0, solid = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    if (trial % 100 == 0) now.set_time(when(rng));
    const Eigen::Vector3d p(coord(rng), coord(rng) * 0.3, coord(rng));
    const double r = radius(rng);
    const double limit = trial % 2 == 0 ? r : r + 1e-6;
    const bool want = now.clearance(p, limit) < r;
    ASSERT_EQ(now.closer_than(p, r, limit), want) << "trial " << trial;
    (want ? closer : clear)++;
    solid += p.y() < -1;
  }
  EXPECT_GT(closer, 2000);
  EXPECT_GT(clear, 2000);
  EXPECT_GT(solid, 1000);
}

TEST(SceneAtTime, AMoverStandsAtItsEndsBeforeTheFirstAndAfterTheLastKeyframe) {
  Scene scene("one", {}, {}, {}, Trajectory({{0, {0, 0, 0}, 0}, {10, {0, 0, 1}, 0}}));
  scene.set_movers({Mover("door", {2, 3, 0.2}, {{2, {0, 0, 5}}, {4, {2, 0, 5}}})});
  SceneAtTime at(scene);
  at.set_time(0);
  EXPECT_FALSE(at.line_of_sight({0, 1, 0}, {0, 1, 10}));
  at.set_time(3);  // half open: spans x in [0, 2]
  EXPECT_TRUE(at.line_of_sight({-0.5, 1, 0}, {-0.5, 1, 10}));
  EXPECT_FALSE(at.line_of_sight({0.5, 1, 0}, {0.5, 1, 10}));
  at.set_time(100);  // open: spans x in [1, 3]
  EXPECT_TRUE(at.line_of_sight({0, 1, 0}, {0, 1, 10}));
  // The static Scene query never sees the mover.
  EXPECT_TRUE(scene.line_of_sight({2, 1, 0}, {2, 1, 10}));
}

}  // namespace
}  // namespace sightline::camera
