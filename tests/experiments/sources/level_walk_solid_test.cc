// Level walks and the level's solid volume: matter the drawn triangles miss (a Quake III
// brush faced with a non-solid surface) must not be walked through. The checks here sample
// each leg themselves, more finely than the generator (every 0.02-0.05 m, at knee, waist and
// chest height), with the volume's own solid_at(): not first_in_solid().
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sightline/domains/camera/level/level.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/sources/level_walk.h"
#include "sightline/experiments/sources/spawn_points.h"

namespace sightline::experiments {
namespace {

using camera::TriangleMesh;
using Eigen::Vector3d;

const char* const kBaseoa = "/usr/share/games/openarena/baseoa/";

// Solid inside axis-aligned boxes, and nowhere else: matter no triangle shows.
class Boxes final : public camera::SolidVolume {
 public:
  explicit Boxes(std::vector<std::pair<Vector3d, Vector3d>> boxes) : boxes_(std::move(boxes)) {}
  bool solid_at(const Vector3d& p) const override {
    for (const auto& [lo, hi] : boxes_) {
      if ((p.array() >= lo.array()).all() && (p.array() <= hi.array()).all()) return true;
    }
    return false;
  }
  std::string describe() const override { return "test boxes"; }

 private:
  std::vector<std::pair<Vector3d, Vector3d>> boxes_;
};

// The times (interpolated along the leg) at which the person of `keys` has a body point
// (knee, waist or chest) inside `solid`, the leg sampled every `step` metres.
std::vector<double> times_in_solid(const std::vector<camera::Keyframe>& keys,
                                   const camera::SolidVolume& solid, double step) {
  std::vector<double> out;
  for (std::size_t i = 1; i < keys.size(); ++i) {
    const Vector3d& a = keys[i - 1].position;
    const Vector3d& b = keys[i].position;
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
    for (int k = 0; k <= n; ++k) {
      const double f = static_cast<double>(k) / n;
      for (double h : {0.5, 0.9, 1.3}) {
        if (solid.solid_at(a + f * (b - a) + h * Vector3d::UnitY())) {
          out.push_back(keys[i - 1].t + f * (keys[i].t - keys[i - 1].t));
          break;
        }
      }
    }
  }
  return out;
}

std::vector<Vector3d> feet_of(const std::vector<camera::Keyframe>& keys) {
  std::vector<Vector3d> feet;
  for (const auto& k : keys) feet.push_back(k.position);
  return feet;
}

// ---- first_in_solid --------------------------------------------------------------------

// A slab 0.25 m thick and 6 m tall across x = 5, from z = 0 to 10.
const Boxes kSlab({{Vector3d(5, 0, 0), Vector3d(5.25, 6, 10)}});

TEST(FirstInSolid, FindsTheLegThatCrossesASlabAndNoneBesideIt) {
  EXPECT_EQ(first_in_solid({{0, 0, 5}, {4, 0, 5}, {8, 0, 5}, {9, 0, 5}}, kSlab), 1u);
  EXPECT_EQ(first_in_solid({{0, 0, 5}, {4, 0, 5}, {4, 0, 11}, {8, 0, 11}}, kSlab), std::nullopt);
  // Standing in it, and standing beside it.
  EXPECT_EQ(first_in_solid({{5.1, 0, 5}}, kSlab), 0u);
  EXPECT_EQ(first_in_solid({{4.9, 0, 5}}, kSlab), std::nullopt);
  // A kerb below the knees is stepped over; a beam above the head is walked under.
  const Boxes kerb({{Vector3d(5, 0, 0), Vector3d(5.25, 0.4, 10)}});
  const Boxes beam({{Vector3d(5, 1.9, 0), Vector3d(5.25, 2.2, 10)}});
  EXPECT_EQ(first_in_solid({{0, 0, 5}, {9, 0, 5}}, kerb), std::nullopt);
  EXPECT_EQ(first_in_solid({{0, 0, 5}, {9, 0, 5}}, beam), std::nullopt);
  // A slab only at chest height, or only at knee height, is met.
  const Boxes chest({{Vector3d(5, 1.2, 0), Vector3d(5.25, 1.4, 10)}});
  const Boxes knee({{Vector3d(5, 0.45, 0), Vector3d(5.25, 0.55, 10)}});
  EXPECT_EQ(first_in_solid({{0, 0, 5}, {9, 0, 5}}, chest), 0u);
  EXPECT_EQ(first_in_solid({{0, 0, 5}, {9, 0, 5}}, knee), 0u);
}

TEST(FirstInSolid, MeetsTheSlabWhateverTheAngleItIsCrossedAt) {
  // Legs through the slab's middle at angles up to 80 degrees from square, starting at
  // odd offsets: a sample always lands inside 0.25 m of slab (brute force: every 1 mm).
  for (int degrees = -80; degrees <= 80; degrees += 5) {
    for (double offset : {0.0, 0.013, 0.037, 0.061, 0.089}) {
      const double a = degrees * 3.14159265358979 / 180;
      const Vector3d dir(std::cos(a), 0, std::sin(a));
      const Vector3d from = Vector3d(5.125, 0, 5) - (3 + offset) * dir;
      const Vector3d to = Vector3d(5.125, 0, 5) + (2 - offset) * dir;
      camera::Keyframe k0, k1;
      k0.position = from;
      k1.position = to;
      k1.t = 1;
      ASSERT_FALSE(times_in_solid({k0, k1}, kSlab, 0.001).empty());
      EXPECT_EQ(first_in_solid({from, to}, kSlab), 0u) << degrees << " degrees";
    }
  }
}

// ---- generate_walks on a level built here ----------------------------------------------

void add_box(TriangleMesh& mesh, const Vector3d& lo, const Vector3d& hi) {
  // Six faces, outwards (two triangles each).
  const auto v = [&](int x, int y, int z) {
    mesh.vertices.push_back(Vector3d(x ? hi.x() : lo.x(), y ? hi.y() : lo.y(),
                                     z ? hi.z() : lo.z()).cast<float>());
  };
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int i = 0; i < 8; ++i) v(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const std::uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    mesh.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    mesh.triangles.push_back({base + f[0], base + f[2], base + f[3]});
  }
}

// A 20 x 12 m hall walled in (drawn); across it at x = 10, from z = 0 to 8, a slab 0.25 m
// thick and 3 m tall that only the solid volume knows (its faces are not drawn).
TriangleMesh hall() {
  TriangleMesh mesh;
  add_box(mesh, {-1, -1, -1}, {21, 0, 13});  // the floor: its top at y = 0
  add_box(mesh, {-1, 0, -1}, {0, 3, 13});
  add_box(mesh, {20, 0, -1}, {21, 3, 13});
  add_box(mesh, {0, 0, -1}, {20, 3, 0});
  add_box(mesh, {0, 0, 12}, {20, 3, 13});
  return mesh;
}
const Boxes kHiddenSlab({{Vector3d(10, 0, 0), Vector3d(10.25, 3, 8)}});

TEST(GenerateWalks, WithTheSolidVolumeNoWalkCrossesMatterTheTrianglesMiss) {
  const TriangleMesh mesh = hall();
  WalkOptions options;
  options.walks = 3;
  options.seed = 5;
  options.min_seconds = 20;
  options.max_seconds = 40;
  // Without it the walks go through the slab: the level is a fair test.
  int crossings = 0;
  for (const LevelWalk& walk : generate_walks(mesh, options).walks) {
    crossings += static_cast<int>(!times_in_solid(walk.keyframes, kHiddenSlab, 0.02).empty());
  }
  EXPECT_GT(crossings, 0);
  const LevelWalks result = generate_walks(mesh, options, {}, &kHiddenSlab);
  ASSERT_EQ(result.walks.size(), 3u);
  for (const LevelWalk& walk : result.walks) {
    EXPECT_GE(walk.keyframes.back().t, options.min_seconds - 1e-9);
    EXPECT_TRUE(times_in_solid(walk.keyframes, kHiddenSlab, 0.02).empty());
  }
  // Solid matter nowhere near the walks changes nothing: the same draws, the same walks.
  const Boxes far({{Vector3d(100, 0, 100), Vector3d(101, 3, 101)}});
  const LevelWalks same = generate_walks(mesh, options, {}, &far);
  const LevelWalks plain = generate_walks(mesh, options);
  for (std::size_t w = 0; w < plain.walks.size(); ++w) {
    EXPECT_EQ(walk_scene_yaml("w", "", "hall.obj", "", same.walks[w]),
              walk_scene_yaml("w", "", "hall.obj", "", plain.walks[w]));
  }
}

// ---- oa_thor: four slabs of caulk faced with see-through pipes -------------------------

camera::LevelSpec oa_thor() {
  camera::LevelSpec spec;
  spec.file = std::string(kBaseoa) + "pak6-patch088.pk3";
  spec.map = "oa_thor";
  return spec;
}

TEST(OaThorWalks, TheShippedWalk3IsInsideBrush1069AtFrame3230) {
  if (!std::filesystem::exists(oa_thor().file)) GTEST_SKIP() << oa_thor().file << " is not installed";
  const camera::Scene scene = camera::read_scene_file(
      std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/levels/oa_thor-walk3.yaml");
  ASSERT_NE(scene.level(), nullptr);
  ASSERT_NE(scene.level()->solid, nullptr);
  const auto& keys = scene.trajectory().keyframes();
  // The trace's frame 3230 at 60 frames/s: 53.8 s; and 1070 at frames 3445-3580.
  const std::vector<double> inside = times_in_solid(keys, *scene.level()->solid, 0.05);
  ASSERT_FALSE(inside.empty());
  const auto near = [&](double t0, double t1) {
    return std::any_of(inside.begin(), inside.end(), [&](double t) { return t >= t0 && t <= t1; });
  };
  EXPECT_TRUE(near(3230 / 60.0 - 0.5, 3230 / 60.0 + 0.5));
  EXPECT_TRUE(near(3445 / 60.0, 3580 / 60.0));
  // The generator's check finds it too, on a leg spanning one of those times.
  const auto leg = first_in_solid(feet_of(keys), *scene.level()->solid);
  ASSERT_TRUE(leg.has_value());
  EXPECT_LE(keys[*leg].t, inside.front() + 1e-9);
  EXPECT_GE(keys[*leg + 1].t, inside.front() - 1e-9);
}

TEST(OaThorWalks, WalksMadeWithTheSolidVolumeNeverEnterIt) {
  if (!std::filesystem::exists(oa_thor().file)) GTEST_SKIP() << oa_thor().file << " is not installed";
  const camera::LevelSpec spec = oa_thor();
  const camera::Level level = camera::load_level(spec);
  ASSERT_NE(level.solid, nullptr);
  const std::vector<Vector3d> spawns = quake3_spawn_points(spec, level.transform);
  WalkOptions options;  // as the shipped walks: `--walks 5 --seed 14`
  options.walks = 5;
  options.seed = 14;
  int crossings = 0;
  for (const LevelWalk& walk : generate_walks(level.mesh, options, spawns).walks) {
    crossings += static_cast<int>(!times_in_solid(walk.keyframes, *level.solid, 0.05).empty());
  }
  EXPECT_GE(crossings, 3) << "without the solid volume walks 2, 3 and 5 cross the slabs";
  const LevelWalks result = generate_walks(level.mesh, options, spawns, level.solid.get());
  ASSERT_EQ(result.walks.size(), 5u);
  for (std::size_t w = 0; w < result.walks.size(); ++w) {
    const std::vector<double> inside = times_in_solid(result.walks[w].keyframes, *level.solid, 0.05);
    EXPECT_TRUE(inside.empty()) << "walk " << w + 1 << " is inside solid matter at "
                                << (inside.empty() ? 0.0 : inside.front()) << " s";
  }
}

}  // namespace
}  // namespace sightline::experiments
