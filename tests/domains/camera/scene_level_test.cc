// Scene queries with a level: boxes and triangles answer together, and the level's solid
// volume decides the sign of clearance (a triangle soup has no inside). Checked against the
// plain geometry of a hand-made level whose answers are known.
#include <gtest/gtest.h>

#include <memory>

#include "sightline/domains/camera/scene.h"
#include "sightline/domains/camera/space_sensor.h"

namespace sightline::camera {
namespace {

// Solid below y = 0 (a floor slab) and beyond |x| = 50: a stand-in for a map's brushes.
class SlabBelowGround : public SolidVolume {
 public:
  bool solid_at(const Eigen::Vector3d& p) const override { return p.y() < 0 || std::abs(p.x()) > 50; }
  std::string describe() const override { return "slab"; }
};

void add_quad(TriangleMesh& mesh, Eigen::Vector3f a, Eigen::Vector3f b, Eigen::Vector3f c,
              Eigen::Vector3f d) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {a, b, c, d});
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

// A floor at y = 0 over [-10, 10]^2, a wall at z = 5 (x in [-10, 10], y in [0, 3]), a ceiling
// at y = 3 over z in [5, 10] (a covered walkway behind the wall), plus one box pillar.
Scene level_scene(bool with_solid) {
  auto level = std::make_shared<Level>();
  add_quad(level->mesh, {-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10});
  add_quad(level->mesh, {-10, 0, 5}, {10, 0, 5}, {10, 3, 5}, {-10, 3, 5});
  add_quad(level->mesh, {-10, 3, 5}, {10, 3, 5}, {10, 3, 10}, {-10, 3, 10});
  if (with_solid) level->solid = std::make_shared<SlabBelowGround>();
  std::vector<SolidBox> boxes{{"pillar", {{-3, 0, -3}, {-2, 3, -2}}, {}}};
  Scene scene("level", std::move(boxes), {}, {}, Trajectory({{0, {0, 0, 0}, 0}, {1, {0, 0, 1}, 0}}));
  scene.set_level(level);
  return scene;
}

TEST(SceneWithLevel, SightLinesAreBlockedByTrianglesAndBoxesAlike) {
  const Scene s = level_scene(true);
  EXPECT_FALSE(s.line_of_sight({0, 1, 0}, {0, 1, 8}));   // through the wall
  EXPECT_FALSE(s.line_of_sight({-5, 1, -5}, {0, 1, 0}));  // through the pillar
  EXPECT_TRUE(s.line_of_sight({0, 1, 0}, {4, 2, 4}));
  const auto hit = s.first_hit({0, 1, 0}, {0, 1, 8});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->source, SurfaceHit::Source::kTriangle);
  EXPECT_NEAR(hit->t, 5.0 / 8, 1e-6);
  EXPECT_NEAR(hit->normal.z(), -1, 1e-6);  // facing the segment's start
  const auto box = s.first_hit({-5, 1, -2.5}, {0, 1, -2.5});
  ASSERT_TRUE(box);
  EXPECT_EQ(box->source, SurfaceHit::Source::kBox);
  EXPECT_NEAR(box->normal.x(), -1, 1e-12);
}

TEST(SceneWithLevel, ClearanceIsTheNearestSurfaceAndNegativeInsideSolidMatter) {
  const Scene s = level_scene(true);
  EXPECT_NEAR(s.clearance({0, 1, 4.5}), 0.5, 1e-6);       // the wall
  EXPECT_NEAR(s.clearance({0, 0.25, 0}), 0.25, 1e-6);     // the floor
  EXPECT_NEAR(s.clearance({-1.5, 1, -2.5}), 0.5, 1e-12);  // the pillar box
  EXPECT_EQ(s.clearance({0, 1.5, 0}, 0.2), 0.2);          // nothing within the limit
  EXPECT_NEAR(s.clearance({0, -0.5, 0}), -0.5, 1e-6);     // under the floor: inside the slab
  EXPECT_LT(s.clearance({60, 1, 0}, 0.2), 0);             // outside the world
  EXPECT_FALSE(s.open_at({0, -0.5, 0}));
  EXPECT_FALSE(s.open_at({-2.5, 1, -2.5}));
  EXPECT_TRUE(s.open_at({0, 1, 0}));
  // The gradient points away from the nearest surface, into solid matter it points deeper.
  const auto above = s.nearest_surface({0, 0.1, 0}, 1);
  ASSERT_TRUE(above);
  EXPECT_NEAR(above->gradient.y(), 1, 1e-6);
  const auto below = s.nearest_surface({0, -0.1, 0}, 1);
  ASSERT_TRUE(below);
  EXPECT_NEAR(below->signed_distance, -0.1, 1e-6);
  EXPECT_NEAR(below->gradient.y(), 1, 1e-6);  // up, toward the open side, raises d
}

TEST(SceneWithLevel, WithoutSolidVolumesTrianglesHaveNoInside) {
  const Scene s = level_scene(false);
  EXPECT_NEAR(s.clearance({0, -0.5, 0}), 0.5, 1e-6);
  EXPECT_TRUE(s.open_at({0, -0.5, 0}));
}

TEST(SpaceSensor, SeesTheCeilingAndTheRoomBehindAndAdaptsLikeAnArea) {
  const Scene s = level_scene(true);
  CameraProfile profile;  // height 2.5, distance 4, enclosed ceiling margin 0.5
  profile.sensing.smoothing = 0;
  const SceneAtTime at(s);
  SpaceSensor sensor(at, profile);
  CharacterState c;
  c.position = {0, 0, 7};  // under the walkway roof, between the wall and its far end
  c.yaw = 180;             // facing -z: the camera wants to be toward +z
  sensor.update(c);
  EXPECT_NEAR(sensor.ceiling(), 3, 1e-6);
  EXPECT_NEAR(sensor.desired_height(), 2.5, 1e-9);  // min(2.5, 3 - 0.5)
  // Behind (+z and 30 degrees either side) the mesh ends at z = 10: 3 m straight back, more
  // at 30 degrees (3 / cos 30), and nothing there stops the rays but the probe length.
  EXPECT_NEAR(sensor.room_behind(), profile.sensing.behind_probe, 1e-6);
  c.t = 1;
  c.position = {0, 0, 4};
  c.yaw = 0;  // facing +z toward the wall 1 m ahead; behind is open floor
  sensor.update(c);
  EXPECT_NEAR(sensor.ceiling(), 1.5 + profile.sensing.ceiling_probe, 1e-9);  // open sky
  c.t = 2;
  c.yaw = 180;  // now the wall is right behind: 1 m, 1/cos 30 m to the sides
  sensor.update(c);
  EXPECT_NEAR(sensor.room_behind(), 1 / std::cos(30 * 3.14159265358979 / 180), 1e-5);
  EXPECT_NEAR(sensor.desired_distance(), profile.sensing.min_distance, 1e-9);
}

TEST(SpaceSensor, LowPassesWhatItSeesAndIgnoresARepeatedTime) {
  const Scene s = level_scene(true);
  CameraProfile profile;
  profile.sensing.smoothing = 0.5;
  const SceneAtTime at(s);
  SpaceSensor sensor(at, profile);
  CharacterState c;
  c.position = {0, 0, 4};
  c.yaw = 0;
  sensor.update(c);  // first frame: taken as sensed
  const double open = sensor.room_behind();
  c.yaw = 180;
  c.t = 0.1;
  sensor.update(c);
  const double once = sensor.room_behind();
  EXPECT_LT(once, open);
  EXPECT_GT(once, 1.2);  // only part of the way down after 0.1 s of a 0.5 s low-pass
  sensor.update(c);      // the same frame again: no change
  EXPECT_EQ(sensor.room_behind(), once);
}

}  // namespace
}  // namespace sightline::camera
