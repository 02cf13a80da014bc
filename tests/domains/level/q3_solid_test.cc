// Q3SolidVolume on real maps: the map's own spawn points are open, far points are solid, and
// every answer matches a brute force written here (its own tree walk over the lumps, and
// every solid brush of the map tested, not just the leaf's).
#include "sightline/domains/camera/level/q3_solid.h"

#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "sightline/domains/camera/level/q3_level.h"
#include "tests/domains/level/q3_test_support.h"

namespace sightline::camera {
namespace {

using namespace q3test;

const LevelTransform kQuakeFrame{0.03125, UpAxis::kZ};

// The brute force: the point's leaf found by a walk written here, and all solid brushes of
// the map tried side by side, from the raw lumps.
class BruteForceSolid {
 public:
  explicit BruteForceSolid(const std::vector<unsigned char>& b) : b_(b) {}

  // The byte offset of the leaf the point falls into, down the tree's planes.
  std::size_t leaf_at(const Eigen::Vector3d& p) const {
    std::int32_t node = 0;
    while (node >= 0) {
      const std::size_t at = lump_offset(b_, kNodesLump) + 36 * static_cast<std::size_t>(node);
      const std::size_t plane =
          lump_offset(b_, kPlanesLump) + 16 * static_cast<std::size_t>(le_i32(b_, at));
      const double d = vec_at(b_, plane).dot(p) - le_f32(b_, plane + 12);
      node = le_i32(b_, at + (d >= 0 ? 4 : 8));
    }
    return lump_offset(b_, kLeavesLump) + 48 * static_cast<std::size_t>(-(node + 1));
  }
  int leaf_cluster(const Eigen::Vector3d& p) const { return le_i32(b_, leaf_at(p)); }
  std::size_t brush_count() const { return lump_length(b_, kBrushesLump) / 12; }
  bool solid_brush(std::size_t i) const {
    const auto shader =
        static_cast<std::size_t>(le_i32(b_, lump_offset(b_, kBrushesLump) + 12 * i + 8));
    return (le_i32(b_, lump_offset(b_, kShadersLump) + 72 * shader + 68) & 1) != 0;
  }
  bool in_brush(std::size_t i, const Eigen::Vector3d& p) const {
    const std::size_t at = lump_offset(b_, kBrushesLump) + 12 * i;
    const auto first = static_cast<std::size_t>(le_i32(b_, at));
    const auto n = static_cast<std::size_t>(le_i32(b_, at + 4));
    bool inside = n > 0;
    for (std::size_t s = first; s < first + n && inside; ++s) {
      const std::size_t plane =
          lump_offset(b_, kPlanesLump) +
          16 * static_cast<std::size_t>(le_i32(b_, lump_offset(b_, kBrushSidesLump) + 8 * s));
      inside = vec_at(b_, plane).dot(p) <= le_f32(b_, plane + 12);
    }
    return inside;
  }
  // The game's own point contents (CM_PointContents) over the raw lumps: the leaf's cluster,
  // the leaf's listed brushes, then each brush model's brushes within its bounds.
  bool point_contents_solid(const Eigen::Vector3d& p) const {
    const std::size_t leaf = leaf_at(p);
    if (le_i32(b_, leaf) < 0) return true;
    const auto first = static_cast<std::size_t>(le_i32(b_, leaf + 40));
    const auto n = static_cast<std::size_t>(le_i32(b_, leaf + 44));
    for (std::size_t k = first; k < first + n; ++k) {
      const auto brush =
          static_cast<std::size_t>(le_i32(b_, lump_offset(b_, kLeafBrushesLump) + 4 * k));
      if (solid_brush(brush) && in_brush(brush, p)) return true;
    }
    for (std::size_t model = 1; model < lump_length(b_, 7) / 40; ++model) {
      const std::size_t at = lump_offset(b_, 7) + 40 * model;
      const Eigen::Vector3d lo = vec_at(b_, at), hi = vec_at(b_, at + 12);
      if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
      const auto mb = static_cast<std::size_t>(le_i32(b_, at + 32));
      for (std::size_t brush = mb; brush < mb + static_cast<std::size_t>(le_i32(b_, at + 36));
           ++brush) {
        if (solid_brush(brush) && in_brush(brush, p)) return true;
      }
    }
    return false;
  }
  // Every brush of the map: the world's and the brush entities' (doors, platforms).
  bool in_a_solid_brush(const Eigen::Vector3d& p) const {
    for (std::size_t i = 0; i < brush_count(); ++i) {
      if (solid_brush(i) && in_brush(i, p)) return true;
    }
    return false;
  }
  // The box of brush i's axial sides (q3map2 gives every brush its six axial bevels).
  std::pair<Eigen::Vector3d, Eigen::Vector3d> axial_box(std::size_t i) const {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(-1e30), hi = -lo;
    const std::size_t at = lump_offset(b_, kBrushesLump) + 12 * i;
    const auto first = static_cast<std::size_t>(le_i32(b_, at));
    const auto n = static_cast<std::size_t>(le_i32(b_, at + 4));
    for (std::size_t s = first; s < first + n; ++s) {
      const std::size_t plane =
          lump_offset(b_, kPlanesLump) +
          16 * static_cast<std::size_t>(le_i32(b_, lump_offset(b_, kBrushSidesLump) + 8 * s));
      const Eigen::Vector3d normal = vec_at(b_, plane);
      const double dist = le_f32(b_, plane + 12);
      for (int k = 0; k < 3; ++k) {
        if (normal[k] == 1) hi[k] = std::min(hi[k], dist);
        if (normal[k] == -1) lo[k] = std::max(lo[k], -dist);
      }
    }
    return {lo, hi};
  }

 private:
  const std::vector<unsigned char>& b_;
};

struct LoadedMap {
  std::vector<unsigned char> bytes;
  Level level;
  const Q3SolidVolume* solid = nullptr;
};

LoadedMap load(const std::string& map, std::string* why) {
  LoadedMap out;
  const auto path = extract_map(map, why);
  if (path.empty()) return out;
  out.bytes = read_bytes(path);
  out.level = load_quake3_level({path.string(), "", {}, {}, {}}, kQuakeFrame);
  out.solid = dynamic_cast<const Q3SolidVolume*>(out.level.solid.get());
  return out;
}

#define LOAD_OR_SKIP(map, loaded)                \
  SKIP_WITHOUT_OPENARENA();                      \
  std::string why;                               \
  const LoadedMap loaded = load(map, &why);      \
  if (loaded.bytes.empty()) GTEST_SKIP() << why; \
  ASSERT_NE(loaded.solid, nullptr)

class Q3Solid : public ::testing::TestWithParam<const char*> {};

TEST_P(Q3Solid, TheMapsSpawnPointsAreOpenAndFarPointsSolid) {
  LOAD_OR_SKIP(GetParam(), m);
  const auto spawns = spawn_points(m.bytes);
  ASSERT_GE(spawns.size(), 2u);
  for (const Eigen::Vector3d& s : spawns) {
    // A spawn's origin is where the player's box centre stands (24 units above the floor
    // once dropped); a little higher is surely in the air of the room.
    const Eigen::Vector3d p = s + Eigen::Vector3d(0, 0, 8);
    EXPECT_FALSE(m.solid->solid_at_file(p)) << s.transpose();
    EXPECT_FALSE(m.level.solid->solid_at(kQuakeFrame.to_scene(p))) << s.transpose();
  }
  // Beyond the world model's bounds (model 0 of the models lump: float mins[3], maxs[3]);
  // not just beyond the drawn faces, since a sky box may enclose open air far around them.
  const std::size_t model = lump_offset(m.bytes, 7);
  const Eigen::Vector3d lo = vec_at(m.bytes, model), hi = vec_at(m.bytes, model + 12);
  const Eigen::Vector3d centre = (lo + hi) / 2;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      Eigen::Vector3d far = centre;
      far[axis] = (sign < 0 ? lo : hi)[axis] + sign * 64;
      EXPECT_TRUE(m.solid->solid_at_file(far)) << far.transpose();
      EXPECT_TRUE(m.level.solid->solid_at(kQuakeFrame.to_scene(far))) << far.transpose();
    }
  }
  EXPECT_TRUE(m.level.solid->solid_at(Eigen::Vector3d(1e6, 0, 0)));
}

TEST_P(Q3Solid, AgreesWithABruteForceOverEveryBrushOfTheMap) {
  LOAD_OR_SKIP(GetParam(), m);
  const BruteForceSolid brute(m.bytes);
  const Aabb box = m.level.mesh.bounds();
  Eigen::Vector3d lo = m.level.transform.to_file(box.min), hi = m.level.transform.to_file(box.max);
  const Eigen::Vector3d a = lo.cwiseMin(hi), b = lo.cwiseMax(hi);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  int open = 0, opaque_leaf = 0, in_leaf_brush = 0;
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3d p(a.x() + unit(random) * (b.x() - a.x()),
                            a.y() + unit(random) * (b.y() - a.y()),
                            a.z() + unit(random) * (b.z() - a.z()));
    const bool opaque = brute.leaf_cluster(p) < 0;
    const bool in_brush = brute.in_a_solid_brush(p);
    const bool expected = opaque || in_brush;
    ASSERT_EQ(m.solid->solid_at_file(p), expected) << p.transpose();
    open += expected ? 0 : 1;
    opaque_leaf += opaque ? 1 : 0;
    in_leaf_brush += !opaque && in_brush ? 1 : 0;
  }
  // All three kinds of answer were exercised (a detail brush inside an open leaf too).
  EXPECT_GT(open, 100);
  EXPECT_GT(opaque_leaf, 100);
  EXPECT_GT(in_leaf_brush, 0);
}

// Points on the brushes' own faces and a hair either side of them (their axial box's
// corners, face centres and centre, each nudged by +-1e-9 and +-1e-3 file units along each
// axis), where an answer turns on <= against <: the same answers as the game's walk over
// the raw lumps, point for point.
TEST_P(Q3Solid, AnswersAsTheGameOnAndBesideEveryBrushFace) {
  LOAD_OR_SKIP(GetParam(), m);
  const BruteForceSolid brute(m.bytes);
  int checked = 0, solid = 0;
  for (std::size_t b = 0; b < brute.brush_count(); b += 1 + brute.brush_count() / 1500) {
    if (!brute.solid_brush(b)) continue;
    const auto [lo, hi] = brute.axial_box(b);
    if ((lo.array() < -1e6).any() || (hi.array() > 1e6).any()) continue;  // no full axial box
    std::vector<Eigen::Vector3d> points{(lo + hi) / 2};
    for (int corner = 0; corner < 8; ++corner) {
      points.emplace_back(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(),
                          corner & 4 ? hi.z() : lo.z());
    }
    for (int axis = 0; axis < 3; ++axis) {
      for (const Eigen::Vector3d& end : {lo, hi}) {
        Eigen::Vector3d face = (lo + hi) / 2;
        face[axis] = end[axis];
        points.push_back(face);
      }
    }
    const std::size_t base = points.size();
    for (std::size_t i = 0; i < base; ++i) {
      for (int axis = 0; axis < 3; ++axis) {
        for (double nudge : {-1e-3, -1e-9, 1e-9, 1e-3}) {
          Eigen::Vector3d q = points[i];
          q[axis] += nudge;
          points.push_back(q);
        }
      }
    }
    for (const Eigen::Vector3d& q : points) {
      const bool expected = brute.point_contents_solid(q);
      ASSERT_EQ(m.solid->solid_at_file(q), expected) << "brush " << b << " at " << q.transpose();
      solid += expected ? 1 : 0;
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GT(solid, checked / 10);            // on and inside the faces: solid
  EXPECT_LT(solid, checked - checked / 10);  // a hair outside: often open
}

// Doors and platforms are brush models: no leaf lists their brushes, yet their faces are in
// the mesh, so inside them is solid too.
TEST_P(Q3Solid, TheInsideOfADoorOrPlatformIsSolid) {
  LOAD_OR_SKIP(GetParam(), m);
  const BruteForceSolid brute(m.bytes);
  const std::size_t models = lump_length(m.bytes, 7) / 40;
  int checked = 0;
  for (std::size_t model = 1; model < models; ++model) {
    const std::size_t at = lump_offset(m.bytes, 7) + 40 * model;
    const auto first = static_cast<std::size_t>(le_i32(m.bytes, at + 32));
    const auto n = static_cast<std::size_t>(le_i32(m.bytes, at + 36));
    for (std::size_t b = first; b < first + n; ++b) {
      if (!brute.solid_brush(b)) continue;
      const auto [lo, hi] = brute.axial_box(b);
      const Eigen::Vector3d centre = (lo + hi) / 2;
      if (!brute.in_brush(b, centre)) continue;  // a wedge whose box centre is outside it
      EXPECT_TRUE(m.solid->solid_at_file(centre)) << "model " << model << " brush " << b;
      EXPECT_TRUE(m.level.solid->solid_at(kQuakeFrame.to_scene(centre)));
      ++checked;
    }
  }
  EXPECT_GE(checked, 3);
}

TEST_P(Q3Solid, AnswersTheSameFromSeveralThreads) {
  LOAD_OR_SKIP(GetParam(), m);
  std::vector<Eigen::Vector3d> points;
  std::mt19937 random(11);
  const Aabb box = m.level.mesh.bounds();
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 20000; ++i) {
    points.push_back(box.min + box.size().cwiseProduct(
                                   Eigen::Vector3d(unit(random), unit(random), unit(random))));
  }
  std::vector<char> serial;
  for (const auto& p : points) serial.push_back(m.level.solid->solid_at(p) ? 1 : 0);
  std::vector<std::vector<char>> parallel(4, std::vector<char>(points.size()));
  std::vector<std::thread> threads;
  for (auto& out : parallel) {
    threads.emplace_back([&] {
      for (std::size_t i = 0; i < points.size(); ++i) out[i] = m.level.solid->solid_at(points[i]);
    });
  }
  for (auto& t : threads) t.join();
  for (const auto& out : parallel) EXPECT_TRUE(out == serial);
}

TEST_P(Q3Solid, DescribesItsSolidBrushes) {
  LOAD_OR_SKIP(GetParam(), m);
  EXPECT_NE(m.solid->describe().find("solid brushes"), std::string::npos);
  EXPECT_NE(m.solid->describe().find("Quake III"), std::string::npos);
  EXPECT_NE(m.solid->describe().find("brush models"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(OpenArena, Q3Solid, ::testing::Values("aggressor", "pxlfan", "oa_thor"));

}  // namespace
}  // namespace sightline::camera
