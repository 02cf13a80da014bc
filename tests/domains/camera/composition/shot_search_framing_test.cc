// shot-search's view of a problem (shot_search_framing.h) and the move it makes along the rim
// of a screen_position's flat zone: hold_on_screen keeps one person where they are in the
// image (checked by this test's own pinhole, FORMATS.md's definition) while the camera moves.
// What the move buys shot-search: composition_solvers_test.cc (problem 11).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <vector>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/shot_search_framing.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

// FORMATS.md's pinhole with roll 0, worked here: the screen point of `q` from `pose`.
Eigen::Vector2d on_screen(const CameraPose& pose, const Eigen::Vector3d& q) {
  const Eigen::Vector3d f = (pose.look_at - pose.position).normalized();
  const Eigen::Vector3d r = f.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d u = r.cross(f);
  const double t = std::tan(pose.fov * 3.14159265358979323846 / 360);
  const Eigen::Vector3d d = q - pose.position;
  const double z = d.dot(f);
  return {(1 + d.dot(r) / (z * t * pose.aspect)) / 2, (1 + d.dot(u) / (z * t)) / 2};
}

TEST(ShotSearchFraming, HoldOnScreenKeepsOnePersonWhereTheyAreAsTheCameraMoves) {
  const Scene scene = parse_scene(csp::parse_yaml(
      "name: two\n"
      "actors:\n"
      "  - {name: alice, trajectory: [{t: 0, position: [-1, 0, 0], yaw: 0}]}\n"
      "  - {name: bob, trajectory: [{t: 0, position: [1, 0, 0], yaw: 180}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-4, 0.5, 2], max: [4, 4, 8]}\n"
      "  properties:\n"
      "    - {kind: screen_position, target: alice, at: [0.35, 0.6]}\n"
      "    - {kind: screen_position, target: bob, at: [0.7, 0.5]}\n",
      "two.yaml"));
  const CompositionProblem owner(scene, *scene.shot(), 0);
  std::vector<int> targets, excluded;
  std::vector<std::size_t> placed;
  csp::Assignment values;
  shot_search_detail::Framing framing(owner.problem(), owner, targets, excluded, placed, values);
  const auto& people = owner.world().people();
  const Eigen::Vector3d alice = people[*owner.world().find("alice")].aim;
  const Eigen::Vector3d bob = people[*owner.world().find("bob")].aim;

  shot_search_detail::Point x{-0.5, 1.8, 5, 0, 0, 50, 0};
  framing.aim(x);
  const CameraPose start = owner.pose(framing.values(x));
  const Eigen::Vector2d alice_at = on_screen(start, alice);
  const Eigen::Vector2d bob_at = on_screen(start, bob);
  Eigen::Vector2d held;
  ASSERT_TRUE(framing.screen_point(x, 0, held));
  EXPECT_LT((held - alice_at).norm(), 1e-9);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  int bob_moved = 0;
  for (int trial = 0; trial < 50; ++trial) {
    shot_search_detail::Point y = x;
    for (int k = 0; k < 3; ++k) y[static_cast<std::size_t>(k)] += 0.3 * unit(rng);
    y[3] += 3 * unit(rng);
    y[4] += 3 * unit(rng);
    ASSERT_TRUE(framing.hold_on_screen(y, 0, held)) << trial;
    const CameraPose moved = owner.pose(framing.values(y));
    EXPECT_LT((on_screen(moved, alice) - alice_at).norm(), 1e-6) << trial;
    bob_moved += (on_screen(moved, bob) - bob_at).norm() > 1e-3;
  }
  // The move is a real one: the other person's place on screen changes.
  EXPECT_GT(bob_moved, 40);
}

}  // namespace
}  // namespace sightline::camera
