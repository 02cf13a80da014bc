// The per-frame path of the camera allocates nothing: re-parameterising the problem for a new
// frame, scoring candidate positions (every constraint, including occlusion through the BVH
// and a profile's `expression` extra), exact gradients and the scene's queries.
//
// This executable replaces the global operator new with one that counts, which is why it is
// a test program of its own.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/constraints/occlusion.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"

#include "tests/count_allocations.h"

namespace sightline::camera {
namespace {

TEST(CameraFramePath, AllocatesNothing) {
  // A scene with walls, a door, an enclosed area and a profile extra (an expression).
  const Scene scene =
      read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) + "/examples/scenes/room-with-door.yaml");
  CameraProblem cp(scene);
  ASSERT_EQ(cp.ids().extras.size(), 1u);
  const csp::Problem& problem = cp.problem();

  std::vector<double> values(3);
  std::vector<double> gradient(3);
  double total = 0;
  Eigen::Vector3d camera = scene.start_camera_position();
  auto one_frame = [&](std::size_t frame) {
    const CharacterState s = scene.character_at(scene.frame_time(frame));
    cp.set_frame(s, camera, 1.0 / scene.frame_rate());
    // Score the eight corners of a small cube around the ideal position, as an octree would.
    const Eigen::Vector3d ideal = cp.ideal_position();
    for (int k = 0; k < 8; ++k) {
      values[0] = ideal.x() + ((k & 1) ? 0.3 : -0.3);
      values[1] = ideal.y() + ((k & 2) ? 0.3 : -0.3);
      values[2] = ideal.z() + ((k & 4) ? 0.3 : -0.3);
      total += problem.score(values).soft;
    }
    // Exact gradients (the camera's own constraints). The expression extra has none: its
    // gradient is csp::Constraint's finite-difference default, outside this domain.
    for (csp::ConstraintId id = 0; id < problem.num_constraints(); ++id) {
      const csp::Constraint& c = problem.constraint(id);
      if (!c.has_exact_gradient()) continue;
      total += c.violation_and_gradient(values, std::span<double>(gradient.data(), c.scope().size()));
    }
    const Eigen::Vector3d look = scene.character().look_at(s.position);
    total += scene.line_of_sight(ideal, look);
    total += scene.first_hit(ideal, look).has_value();
    total += scene.clearance(ideal, 0.2);
    total += scene.innermost_area(s.position).value_or(0);
    total += visible_fraction(scene, ideal, scene.character().body_at(s.position));
    camera = ideal;
  };

  one_frame(0);  // anything lazily set up happens here
  const long before = g_allocations.load();
  for (std::size_t f = 1; f < scene.frame_count(); ++f) one_frame(f);
  const long after = g_allocations.load();
  EXPECT_EQ(after - before, 0) << "allocations over " << scene.frame_count() - 1 << " frames";
  EXPECT_TRUE(std::isfinite(total));
  // The counter itself works.
  const long probe = g_allocations.load();
  auto* leak_check = new std::vector<int>(10);
  delete leak_check;
  EXPECT_GE(g_allocations.load() - probe, 2);
}

TEST(CameraFramePath, WithAnticipationAndMoversAllocatesNothing) {
  // Walls, a cart crossing, the anticipating preset: the prediction (its horizon samples'
  // SceneAtTimes, the traces against walls) and the future-visibility constraint.
  std::vector<SolidBox> solids = {{"west", {{-2.2, 0, -5}, {-2, 3, 12}}, {}},
                                  {"end", {{-2, 0, 10}, {2, 3, 10.3}}, {}}};
  Scene scene("corridor", std::move(solids), {}, {},
              Trajectory({{0, {0, 0, 0}, 0}, {4, {0, 0, 9}, 30}}));
  scene.set_movers({Mover("cart", {1, 2, 1}, {{0, {-6, 0, 4}}, {6, {6, 0, 4}}})});
  const CameraProfile profile = preset_profile("anticipating");
  CameraProblem cp(scene, profile);
  ASSERT_TRUE(cp.ids().future_visible.has_value());
  std::vector<double> values(3);
  double total = 0;
  auto one_frame = [&](std::size_t frame) {
    const CharacterState s = scene.character_at(scene.frame_time(frame));
    cp.set_frame(s, cp.ideal_position(), 1.0 / scene.frame_rate());
    const Eigen::Vector3d ideal = cp.ideal_position();
    for (int k = 0; k < 8; ++k) {
      values[0] = ideal.x() + ((k & 1) ? 0.3 : -0.3);
      values[1] = ideal.y() + ((k & 2) ? 0.3 : -0.3);
      values[2] = ideal.z() + ((k & 4) ? 0.3 : -0.3);
      total += cp.problem().score(values).soft;
    }
  };
  one_frame(0);
  const long before = g_allocations.load();
  for (std::size_t f = 1; f < scene.frame_count(); ++f) one_frame(f);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(total));
}

TEST(CameraFramePath, OnALevelWithAnticipationAllocatesNothing) {
  // A level's triangles (a floor, a wall, a roof: the body's and the predicted sight lines
  // go to Embree as ray packets), a box and a cart crossing, the anticipating preset; each
  // candidate scored in full and through the bounded counts the octree uses.
  auto level = std::make_shared<Level>();
  auto quad = [&](Eigen::Vector3f a, Eigen::Vector3f b, Eigen::Vector3f c, Eigen::Vector3f d) {
    const auto base = static_cast<std::uint32_t>(level->mesh.vertices.size());
    level->mesh.vertices.insert(level->mesh.vertices.end(), {a, b, c, d});
    level->mesh.triangles.push_back({base, base + 1, base + 2});
    level->mesh.triangles.push_back({base, base + 2, base + 3});
  };
  quad({-10, 0, -10}, {-10, 0, 12}, {10, 0, 12}, {10, 0, -10});
  quad({-3, 0, 5}, {10, 0, 5}, {10, 3, 5}, {-3, 3, 5});
  quad({-10, 3, 5}, {10, 3, 5}, {10, 3, 10}, {-10, 3, 10});
  std::vector<SolidBox> solids = {{"pillar", {{-4, 0, 2}, {-3.5, 3, 2.5}}, {}}};
  Scene scene("level", std::move(solids), {}, {},
              Trajectory({{0, {0, 0, 0}, 0}, {4, {-6, 0, 9}, -40}}));
  scene.set_level(level);
  scene.set_movers({Mover("cart", {1, 2, 1}, {{0, {-6, 0, 4}}, {6, {6, 0, 4}}})});
  const CameraProfile profile = preset_profile("anticipating");
  CameraProblem cp(scene, profile);
  ASSERT_TRUE(cp.ids().future_visible.has_value() && cp.ids().visible_fraction.has_value());
  ASSERT_TRUE(cp.scene_at_time().packs_sight_lines());
  const csp::Constraint* body = &cp.problem().constraint(*cp.ids().visible_fraction);
  const csp::Constraint* future = &cp.problem().constraint(*cp.ids().future_visible);
  std::vector<double> values(3);
  double total = 0;
  auto one_frame = [&](std::size_t frame) {
    const CharacterState s = scene.character_at(scene.frame_time(frame));
    cp.set_frame(s, cp.ideal_position(), 1.0 / scene.frame_rate());
    const Eigen::Vector3d ideal = cp.ideal_position();
    for (int k = 0; k < 8; ++k) {
      values[0] = ideal.x() + ((k & 1) ? 0.8 : -0.8);
      values[1] = ideal.y() + ((k & 2) ? 0.8 : -0.8);
      values[2] = ideal.z() + ((k & 4) ? 0.8 : -0.8);
      total += cp.problem().score(values).soft;
      total += body->violation_until(values, 0.5, 1.0, 0.25);
      total += future->violation_until(values, 0.5, 1.0, 0.0);
    }
  };
  one_frame(0);
  const long before = g_allocations.load();
  for (std::size_t f = 1; f < scene.frame_count(); ++f) one_frame(f);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(total));
  EXPECT_GT(total, 0);
}

}  // namespace
}  // namespace sightline::camera
