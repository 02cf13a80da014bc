// Level walks on levels built here, whose walkable floors are known: every keyframe must
// stand on a surface (a ray down from the feet meets one within 0.25 m) with 1.8 m of
// headroom, and no leg may pass through a surface at knee (0.5 m) or chest (1.3 m) height.
// Those checks are brute force over every triangle, written here with signed volumes (not
// the generator's probe, not Recast, not Embree).
#include "sightline/experiments/sources/level_walk.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/level/level.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/sources/spawn_points.h"

namespace sightline::experiments {
namespace {

using camera::TriangleMesh;
using Eigen::Vector3d;

// ---- Levels ----------------------------------------------------------------------------

// A quad a-b-c-d, turned so its front (counter-clockwise side) faces `front`.
void add_quad(TriangleMesh& mesh, Vector3d a, Vector3d b, Vector3d c, Vector3d d,
              const Vector3d& front) {
  if ((b - a).cross(c - a).dot(front) < 0) std::swap(b, d);
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const Vector3d& v : {a, b, c, d}) mesh.vertices.push_back(v.cast<float>());
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}
void add_floor(TriangleMesh& mesh, double x0, double z0, double x1, double z1, double y) {
  add_quad(mesh, {x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}, Vector3d::UnitY());
}
void add_ceiling(TriangleMesh& mesh, double x0, double z0, double x1, double z1, double y) {
  add_quad(mesh, {x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}, -Vector3d::UnitY());
}
// A closed box, faces outwards.
void add_box(TriangleMesh& mesh, const Vector3d& lo, const Vector3d& hi) {
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {-1.0, 1.0}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vector3d corner[4];
      for (int k = 0; k < 4; ++k) {
        corner[k][axis] = side < 0 ? lo[axis] : hi[axis];
        corner[k][u] = (k == 1 || k == 2) ? hi[u] : lo[u];
        corner[k][v] = (k >= 2) ? hi[v] : lo[v];
      }
      Vector3d out = Vector3d::Zero();
      out[axis] = side;
      add_quad(mesh, corner[0], corner[1], corner[2], corner[3], out);
    }
  }
}
void add_walls(TriangleMesh& mesh, double x0, double z0, double x1, double z1, double h) {
  add_box(mesh, {x0 - 0.2, 0, z0 - 0.2}, {x0, h, z1 + 0.2});
  add_box(mesh, {x1, 0, z0 - 0.2}, {x1 + 0.2, h, z1 + 0.2});
  add_box(mesh, {x0, 0, z0 - 0.2}, {x1, h, z0});
  add_box(mesh, {x0, 0, z1}, {x1, h, z1 + 0.2});
}

// A 20 x 12 m hall: a floor at 0 (x < 14), a platform at 5 risers (x >= 14) reached by a
// 4 m wide staircase of 0.5 m treads, a pillar, a low beam at 1.5 m (nobody walks under
// it), a bar at knee height, a ceiling at 2.4 m over one corner.
TriangleMesh stairs_level(double riser) {
  TriangleMesh mesh;
  add_floor(mesh, 0, 0, 14, 12, 0);
  add_walls(mesh, 0, 0, 20, 12, 5 * riser + 3);
  add_box(mesh, {14, 0, 0}, {20, 5 * riser, 12});
  for (int i = 1; i <= 4; ++i)
    add_box(mesh, {14 - (5 - i) * 0.5, 0, 4}, {14 - (4 - i) * 0.5, i * riser, 8});
  add_box(mesh, {5, 0, 5}, {6, 4, 6});
  add_box(mesh, {8, 1.5, 2}, {10, 1.7, 10});
  add_box(mesh, {2, 0.45, 8}, {3, 0.6, 12});
  add_ceiling(mesh, 0, 0, 6, 4, 2.4);
  return mesh;
}

// Two 10 x 10 m rooms under a 2.5 m ceiling, joined by a 6 m corridor 2 m wide under 2.2 m.
TriangleMesh two_rooms() {
  TriangleMesh mesh;
  for (double x0 : {0.0, 16.0}) {
    add_floor(mesh, x0, 0, x0 + 10, 10, 0);
    add_ceiling(mesh, x0, 0, x0 + 10, 10, 2.5);
    add_box(mesh, {x0 - 0.2, 0, -0.2}, {x0 + 10.2, 3, 0});
    add_box(mesh, {x0 - 0.2, 0, 10}, {x0 + 10.2, 3, 10.2});
  }
  add_box(mesh, {-0.2, 0, 0}, {0, 3, 10});
  add_box(mesh, {26, 0, 0}, {26.2, 3, 10});
  for (double x : {10.0, 16.0}) {  // the walls with the doors
    const double x0 = x == 10 ? 10 : 15.8;
    add_box(mesh, {x0, 0, 0}, {x0 + 0.2, 3, 4});
    add_box(mesh, {x0, 0, 6}, {x0 + 0.2, 3, 10});
  }
  add_floor(mesh, 10, 4, 16, 6, 0);
  add_ceiling(mesh, 10, 4, 16, 6, 2.2);
  add_box(mesh, {10.2, 0, 3.8}, {15.8, 3, 4});
  add_box(mesh, {10.2, 0, 6}, {15.8, 3, 6.2});
  return mesh;
}

// ---- Brute-force geometry ---------------------------------------------------------------

// Six times the signed volume of the tetrahedron a, b, c, d.
double orient(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
  return (b - a).cross(c - a).dot(d - a);
}
// The closed segment p-q meets triangle a-b-c (not coplanar): p and q on opposite sides of
// its plane, and the line p-q passing inside all three edges.
bool segment_meets_triangle(const Vector3d& p, const Vector3d& q, const Vector3d& a,
                            const Vector3d& b, const Vector3d& c) {
  const double sp = orient(a, b, c, p), sq = orient(a, b, c, q);
  if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0) || (sp == 0 && sq == 0)) return false;
  const double e1 = orient(p, q, a, b), e2 = orient(p, q, b, c), e3 = orient(p, q, c, a);
  return (e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0);
}
bool segment_blocked(const TriangleMesh& mesh, const Vector3d& p, const Vector3d& q) {
  for (std::uint32_t i = 0; i < mesh.size(); ++i) {
    if (segment_meets_triangle(p, q, mesh.vertex(i, 0), mesh.vertex(i, 1), mesh.vertex(i, 2))) {
      return true;
    }
  }
  return false;
}

// Every keyframe on a surface with headroom, every leg clear at knee and chest height.
void expect_walkable(const TriangleMesh& mesh, const LevelWalk& walk) {
  const Vector3d up = Vector3d::UnitY();
  int floorless = 0, headless = 0, clipped = 0;
  for (std::size_t i = 0; i < walk.keyframes.size(); ++i) {
    const Vector3d& feet = walk.keyframes[i].position;
    if (!segment_blocked(mesh, feet + 0.001 * up, feet - 0.25 * up)) {
      ++floorless;
      ADD_FAILURE() << "keyframe " << i << " at " << feet.transpose() << " has no floor";
    }
    if (segment_blocked(mesh, feet + 0.005 * up, feet + 1.8 * up)) {
      ++headless;
      ADD_FAILURE() << "keyframe " << i << " at " << feet.transpose() << " has no headroom";
    }
    if (i == 0) continue;
    const Vector3d& from = walk.keyframes[i - 1].position;
    for (double h : {0.5, 1.3}) {
      if (segment_blocked(mesh, from + h * up, feet + h * up)) {
        ++clipped;
        ADD_FAILURE() << "leg " << i - 1 << "-" << i << " crosses a surface at " << h << " m";
      }
    }
    if (floorless + headless + clipped > 10) return;
  }
}

// Times from 0, increasing, within the drawn duration; speeds a person's; faces forwards.
void expect_person_like(const LevelWalk& walk, const WalkOptions& options) {
  const auto& k = walk.keyframes;
  ASSERT_GE(k.size(), 2u);
  EXPECT_EQ(k.front().t, 0.0);
  EXPECT_GE(k.back().t, options.min_seconds - 1e-9);
  EXPECT_LE(k.back().t, options.max_seconds + 1e-9);
  double length = 0, fast = 0;
  for (std::size_t i = 1; i < k.size(); ++i) {
    const double dt = k[i].t - k[i - 1].t;
    ASSERT_GT(dt, 1e-4) << "keyframe " << i;
    const Vector3d d = k[i].position - k[i - 1].position;
    const double across = std::hypot(d.x(), d.z());
    length += d.norm();
    if (across < 0.02) continue;
    const double speed = across / dt;
    EXPECT_LE(speed, options.max_speed + 1e-6) << "leg to keyframe " << i;
    // Slowing at corners halves the speed at most.
    EXPECT_GE(speed, 0.5 * options.min_speed - 1e-6) << "leg to keyframe " << i;
    if (speed >= options.min_speed - 1e-6) fast += across;
    const Vector3d facing = camera::facing_from_yaw(k[i].yaw);
    EXPECT_GT(facing.dot(Vector3d(d.x(), 0, d.z()) / across), 0.999)
        << "keyframe " << i << " does not face the way it walks";
  }
  EXPECT_NEAR(walk.length_metres, length, 1e-6);
  EXPECT_GT(fast, 0.5 * length) << "most of the way is walked at 1.5-4 m/s";
}

WalkOptions three_walks(std::uint64_t seed) {
  WalkOptions options;
  options.walks = 3;
  options.seed = seed;
  return options;
}

// ---- Tests ------------------------------------------------------------------------------

TEST(WalkOptions, DefaultsAreValidAndBadFieldsAreNamed) {
  EXPECT_EQ(WalkOptions().validate(), "");
  WalkOptions o;
  o.agent_radius = 0;
  EXPECT_NE(o.validate().find("agent_radius"), std::string::npos);
  o = WalkOptions();
  o.max_speed = 1;
  EXPECT_NE(o.validate().find("max_speed"), std::string::npos);
  o = WalkOptions();
  o.walks = 0;
  EXPECT_NE(o.validate().find("walks"), std::string::npos);
  o = WalkOptions();
  o.max_slope_degrees = 90;
  EXPECT_NE(o.validate().find("max_slope_degrees"), std::string::npos);
  EXPECT_THROW(generate_walks(stairs_level(0.4), o), std::invalid_argument);
}

TEST(GenerateWalks, KeyframesStandOnFloorsWithHeadroomAndLegsClearKneesAndChest) {
  const TriangleMesh mesh = stairs_level(0.4);
  const WalkOptions options = three_walks(11);
  const LevelWalks result = generate_walks(mesh, options);
  ASSERT_EQ(result.walks.size(), 3u);
  for (const LevelWalk& walk : result.walks) {
    expect_walkable(mesh, walk);
    expect_person_like(walk, options);
  }
}

TEST(GenerateWalks, StairsOfRisersBelowTheStepJoinThePlatformAndTallerOnesDoNot) {
  // The lower floor is 14 x 12 m less the pillar, beam and bar; the platform 6 x 12 m.
  const double lower_floor = 14 * 12;
  const LevelWalks climbable = generate_walks(stairs_level(0.4), three_walks(3));
  EXPECT_GT(climbable.navigation.region_area, lower_floor);
  bool on_platform = false;
  for (const LevelWalk& walk : climbable.walks) {
    for (const auto& k : walk.keyframes) on_platform |= k.position.y() > 1.9;
  }
  EXPECT_TRUE(on_platform) << "walks between far-apart goals climb the stairs";
  const LevelWalks too_high = generate_walks(stairs_level(0.7), three_walks(3));
  EXPECT_LT(too_high.navigation.region_area, lower_floor);
  for (const LevelWalk& walk : too_high.walks) {
    for (const auto& k : walk.keyframes) EXPECT_LT(k.position.y(), 0.3);
    expect_walkable(stairs_level(0.7), walk);
  }
}

TEST(GenerateWalks, WalksGoFromRoomToRoomThroughTheCorridor) {
  const TriangleMesh mesh = two_rooms();
  const WalkOptions options = three_walks(5);
  const LevelWalks result = generate_walks(mesh, options);
  for (const LevelWalk& walk : result.walks) {
    expect_walkable(mesh, walk);
    expect_person_like(walk, options);
    bool in_a = false, in_b = false;
    for (const auto& k : walk.keyframes) {
      in_a |= k.position.x() < 9;
      in_b |= k.position.x() > 17;
    }
    EXPECT_TRUE(in_a && in_b) << "far-apart goals lie in both rooms";
  }
}

TEST(GenerateWalks, StopsTurnOnTheSpot) {
  WalkOptions options = three_walks(8);
  options.walks = 1;
  options.stop_probability = 1;
  const LevelWalks result = generate_walks(two_rooms(), options);
  const auto& k = result.walks[0].keyframes;
  EXPECT_GT(result.walks[0].stops, 0);
  int pauses = 0;
  for (std::size_t i = 1; i < k.size(); ++i) {
    if ((k[i].position - k[i - 1].position).norm() == 0 && k[i].t - k[i - 1].t >= 0.4) ++pauses;
  }
  EXPECT_GE(pauses, result.walks[0].stops);
  expect_walkable(two_rooms(), result.walks[0]);
}

TEST(GenerateWalks, KeepsToTheLargestConnectedRegion) {
  TriangleMesh mesh;
  add_floor(mesh, 0, 0, 12, 12, 0);
  add_floor(mesh, 20, 0, 26, 6, 10);  // a smaller floor, high up and far away
  const LevelWalks result = generate_walks(mesh, three_walks(2));
  // 12 x 12 m less the ledge cells and the radius all round.
  EXPECT_GT(result.navigation.region_area, 10.8 * 10.8);
  EXPECT_LT(result.navigation.region_area, 11.5 * 11.5);
  for (const LevelWalk& walk : result.walks) {
    for (const auto& k : walk.keyframes) {
      EXPECT_LT(k.position.x(), 12);
      EXPECT_LT(std::abs(k.position.y()), 0.05);
    }
  }
}

TEST(GenerateWalks, ALevelWithoutWalkableFloorIsReported) {
  TriangleMesh walls;
  add_box(walls, {0, 0, 0}, {0.2, 3, 10});
  add_quad(walls, {2, 0, 0}, {2, 3, 0}, {2, 3, 10}, {2, 0, 10}, Vector3d::UnitX());
  TriangleMesh speck;
  add_floor(speck, 0, 0, 1, 1, 0);
  TriangleMesh plane;  // one wall, flat along x: no extent across it
  add_quad(plane, {0, 0, 0}, {0, 3, 0}, {0, 3, 10}, {0, 0, 10}, Vector3d::UnitX());
  TriangleMesh nothing;
  for (const TriangleMesh* mesh : {&walls, &speck, &plane, &nothing}) {
    try {
      generate_walks(*mesh, WalkOptions());
      ADD_FAILURE() << "expected WalkError";
    } catch (const WalkError& e) {
      EXPECT_NE(std::string(e.what()).find("no walkable region"), std::string::npos) << e.what();
    }
  }
}

TEST(WalkSceneYaml, TheSameSeedWritesTheSameFilesAndAnotherDoesNot) {
  const TriangleMesh mesh = stairs_level(0.4);
  const auto files = [&](std::uint64_t seed) {
    std::vector<std::string> out;
    for (const LevelWalk& w : generate_walks(mesh, three_walks(seed)).walks) {
      out.push_back(walk_scene_yaml("hall-walk", "a walk", "/levels/hall.obj", "", w));
    }
    return out;
  };
  const auto first = files(21);
  EXPECT_EQ(first, files(21));
  EXPECT_NE(first, files(22));
  EXPECT_NE(first[0], first[1]) << "walks of one seed differ from each other";
  WalkOptions one = three_walks(21);
  one.walks = 1;
  EXPECT_EQ(walk_scene_yaml("hall-walk", "a walk", "/levels/hall.obj", "",
                            generate_walks(mesh, one).walks[0]),
            first[0])
      << "walk 1 does not depend on how many walks are made";
}

TEST(WalkSceneYaml, WritesTheSceneFormatWithTheLevelAndEveryKeyframe) {
  WalkOptions options = three_walks(4);
  options.walks = 1;
  const LevelWalk walk = generate_walks(two_rooms(), options).walks[0];
  const std::string text = walk_scene_yaml("rooms-walk1", "two rooms: \"walk\" 1", "/x/y z.pk3",
                                           "oa_x", walk, 0.03125, camera::UpAxis::kZ);
  const csp::Spec scene = csp::parse_yaml(text, "walk.yaml");
  EXPECT_EQ(scene.at("name").as_string(), "rooms-walk1");
  EXPECT_EQ(scene.at("description").as_string(), "two rooms: \"walk\" 1");
  const csp::Spec& level = scene.at("level");
  EXPECT_EQ(level.at("file").as_string(), "/x/y z.pk3");
  EXPECT_EQ(level.at("map").as_string(), "oa_x");
  EXPECT_EQ(level.at("scale").as_number(), 0.03125);
  EXPECT_EQ(level.at("up").as_string(), "z");
  EXPECT_EQ(scene.find("boxes"), nullptr);
  const std::vector<csp::Spec>& trajectory = scene.at("trajectory").items();
  ASSERT_EQ(trajectory.size(), walk.keyframes.size());
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const auto& k = walk.keyframes[i];
    EXPECT_NEAR(trajectory[i].at("t").as_number(), k.t, 5e-7);
    const std::vector<double> position = trajectory[i].at("position").as_numbers();
    ASSERT_EQ(position.size(), 3u);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(position[static_cast<std::size_t>(a)], k.position[a], 5e-7);
    EXPECT_NEAR(trajectory[i].at("yaw").as_number(), k.yaw, 5e-7);
  }
  const csp::Spec bare = csp::parse_yaml(walk_scene_yaml("w", "", "a.obj", "", walk), "bare.yaml");
  EXPECT_EQ(bare.at("level").find("map"), nullptr);
  EXPECT_EQ(bare.at("level").find("scale"), nullptr);
  EXPECT_EQ(bare.find("description"), nullptr);
}

// Real levels: Quake III maps from Debian's OpenArena data (skipped where not installed).
struct InstalledMap {
  const char* pk3;
  const char* map;
};
class GenerateWalksOnQuake3Map : public ::testing::TestWithParam<InstalledMap> {};

TEST_P(GenerateWalksOnQuake3Map, KeyframesStandOnFloorsWithHeadroomAndLegsClearKneesAndChest) {
  const std::string pk3 = std::string("/usr/share/games/openarena/baseoa/") + GetParam().pk3;
  if (!std::filesystem::exists(pk3)) GTEST_SKIP() << pk3 << " is not installed";
  camera::LevelSpec spec;
  spec.file = pk3;
  spec.map = GetParam().map;
  const camera::Level level = camera::load_level(spec);
  WalkOptions options = three_walks(1);
  options.walks = 2;
  const std::vector<Vector3d> spawns = quake3_spawn_points(spec, level.transform);
  ASSERT_FALSE(spawns.empty());
  const LevelWalks result = generate_walks(level.mesh, options, spawns);
  EXPECT_GT(result.navigation.region_area, 100.0);
  EXPECT_GT(result.navigation.region_anchors, 0);
  // The arena: within the spawn points' heights, give or take a few storeys (the floors
  // nobody plays on lie 30 and 100 m below).
  double low = spawns[0].y(), high = low;
  for (const Vector3d& s : spawns) low = std::min(low, s.y()), high = std::max(high, s.y());
  for (const LevelWalk& walk : result.walks) {
    expect_walkable(level.mesh, walk);
    expect_person_like(walk, options);
    for (const auto& k : walk.keyframes) {
      EXPECT_GT(k.position.y(), low - 15);
      EXPECT_LT(k.position.y(), high + 15);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(OpenArena, GenerateWalksOnQuake3Map,
                         ::testing::Values(InstalledMap{"pak6-patch088.pk3", "oa_thor"},
                                           InstalledMap{"pak6-patch088.pk3", "aggressor"},
                                           InstalledMap{"pak6-patch088.pk3", "am_lavaarena"},
                                           // A stop with no turn left a keyframe pair 40 ns apart.
                                           InstalledMap{"pak6-patch085.pk3", "ctf_inyard"},
                                           // Both have a floor far below the arena,
                                           // larger than it.
                                           InstalledMap{"pak6-patch088.pk3", "oa_koth2"},
                                           InstalledMap{"pak6-patch088.pk3", "czest2ctf"}),
                         [](const auto& info) { return std::string(info.param.map); });

// The walks shipped in experiments/scenes/levels, read back from their files: the same
// checks, on the installed maps they name.
TEST(ShippedLevelWalks, StandOnFloorsWithHeadroomAndClearKneesAndChest) {
  const std::filesystem::path folder =
      std::filesystem::path(SIGHTLINE_SOURCE_DIR) / "experiments/scenes/levels";
  for (const char* pk3 : {"pak6-patch085.pk3", "pak6-patch088.pk3"}) {
    if (!std::filesystem::exists(std::string("/usr/share/games/openarena/baseoa/") + pk3)) {
      GTEST_SKIP() << pk3 << ", which the shipped walks name, is not installed";
    }
  }
  int walks = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().filename().string());
    // The project's own scene reader: the file is a valid scene, its level loads.
    const camera::Scene scene = camera::read_scene_file(entry.path().string());
    ASSERT_NE(scene.level(), nullptr);
    LevelWalk walk;
    walk.keyframes = scene.trajectory().keyframes();
    for (std::size_t i = 1; i < walk.keyframes.size(); ++i) {
      walk.length_metres += (walk.keyframes[i].position - walk.keyframes[i - 1].position).norm();
    }
    expect_walkable(scene.level()->mesh, walk);
    // Six decimals: speeds and the facing are checked on rounded numbers.
    WalkOptions options;
    options.max_speed += 1e-3;
    options.min_speed -= 1e-3;
    expect_person_like(walk, options);
    ++walks;
  }
  EXPECT_GE(walks, 20);
}

}  // namespace
}  // namespace sightline::experiments
