// The camera constraints on hand-computed cases, their exact gradients against finite
// differences, and the occlusion and clearance constraints against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/constraints/clearance.h"
#include "sightline/domains/camera/constraints/occlusion.h"
#include "sightline/domains/camera/constraints/smooth_constraints.h"

namespace sightline::camera {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A frame table plus the values of cam_x, cam_y, cam_z (ids 0, 1, 2).
struct Frame {
  csp::Parameters table;
  FrameParameters p = FrameParameters::add_to(table);
  void set(const FrameValues& v) { p.write(table, v); }
};

FrameValues character_at(Eigen::Vector3d feet, double yaw) {
  FrameValues v;
  v.feet = feet;
  v.yaw = yaw;
  v.look_at = feet + Eigen::Vector3d(0, 1.5, 0);
  return v;
}

TEST(HeightConstraint, IsTheDeviationFromTheDesiredHeightAboveTheFeet) {
  Frame f;
  FrameValues v = character_at({0, 1, 0}, 0);
  v.desired_height = 2.5;
  f.set(v);
  const HeightConstraint c(1, f.p, 2.0);
  const double cam[] = {0, 4, 0};  // 3 m above the feet: 0.5 too high
  EXPECT_DOUBLE_EQ(c.violation(cam), 0.5);
  const double low[] = {0, 2, 0};  // 1 m above: 1.5 too low
  EXPECT_DOUBLE_EQ(c.violation(low), 1.5);
  EXPECT_EQ(c.weight(), 2.0);
  EXPECT_EQ(c.kind(), "camera.height");
}

TEST(DistanceConstraint, MeasuresHorizontalDistanceOnly) {
  Frame f;
  FrameValues v = character_at({1, 0, 1}, 0);
  v.desired_distance = 4;
  f.set(v);
  const DistanceConstraint c(0, 2, f.p, 1.0);
  const double cam[] = {4, 9, 5};  // (3, _, 4) away: 5 m whatever the height
  EXPECT_DOUBLE_EQ(c.violation(cam), 1.0);
  const double above[] = {1, 3, 1};  // right above: distance 0
  EXPECT_DOUBLE_EQ(c.violation(above), 4.0);
}

TEST(OrientationConstraint, IsTheAngleBetweenFacingAndCameraToCharacter) {
  Frame f;
  FrameValues v = character_at({0, 0, 0}, 0);  // facing +z
  v.desired_orientation = 0;
  f.set(v);
  const OrientationConstraint c(0, 2, f.p, 1.0);
  auto angle = [&](double x, double z) {
    const double cam[] = {x, 2, z};
    return c.violation(cam);
  };
  EXPECT_NEAR(angle(0, -4), 0, 1e-12);     // behind: looking along the facing
  EXPECT_NEAR(angle(4, 0), 90, 1e-12);     // on the right
  EXPECT_NEAR(angle(-4, 0), 90, 1e-12);    // on the left
  EXPECT_NEAR(angle(0, 4), 180, 1e-12);    // in front, facing the camera
  EXPECT_NEAR(angle(-1, -1), 45, 1e-12);
  EXPECT_NEAR(angle(-1, -std::sqrt(3.0)), 30, 1e-12);

  v.desired_orientation = 30;
  v.yaw = 90;  // facing +x: behind is -x
  f.set(v);
  const double behind[] = {-3, 2, 0};
  EXPECT_NEAR(c.violation(behind), 30, 1e-12);
  const double at_30[] = {-std::sqrt(3.0), 2, 1};  // direction (sqrt3, -1): 30 degrees off +x
  EXPECT_NEAR(c.violation(at_30), 0, 1e-12);
}

TEST(OrientationConstraint, AgreesWithTheThesisAcosFormula) {
  Frame f;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-10, 10), yaw(0, 360), desired(0, 180);
  const OrientationConstraint c(0, 2, f.p, 1.0);
  for (int i = 0; i < 1000; ++i) {
    FrameValues v = character_at({u(rng), 0, u(rng)}, yaw(rng));
    v.desired_orientation = desired(rng);
    f.set(v);
    const double cam[] = {u(rng), 2, u(rng)};
    const Eigen::Vector3d d = Eigen::Vector3d(v.feet.x() - cam[0], 0, v.feet.z() - cam[2]).normalized();
    const double dot = std::clamp(d.dot(facing_from_yaw(v.yaw)), -1.0, 1.0);
    const double expected = std::abs(v.desired_orientation - std::acos(dot) * 180 / kPi);
    EXPECT_NEAR(c.violation(cam), expected, 1e-9);
  }
}

TEST(FrameCoherenceConstraint, IsTheCameraSpeed) {
  Frame f;
  FrameValues v;
  v.last_camera = {1, 1, 1};
  v.dt = 0.5;
  f.set(v);
  const FrameCoherenceConstraint c(0, 1, 2, f.p, 1.0);
  const double cam[] = {4, 5, 1};  // moved 5 m in 0.5 s
  EXPECT_DOUBLE_EQ(c.violation(cam), 10.0);
  const double still[] = {1, 1, 1};
  EXPECT_EQ(c.violation(still), 0.0);
}

TEST(CameraConstraints, ReadTheFrameLiveSoReparameterisingNeedsNoRebuild) {
  Frame f;
  FrameValues v = character_at({0, 0, 0}, 0);
  v.desired_height = 2;
  f.set(v);
  const HeightConstraint c(1, f.p, 1.0);
  const double cam[] = {0, 2, 0};
  EXPECT_EQ(c.violation(cam), 0.0);
  v.feet.y() = 1;  // the character climbed a step
  f.set(v);
  EXPECT_DOUBLE_EQ(c.violation(cam), 1.0);
}

// Central differences of f at x along each of n coordinates.
template <class F>
std::vector<double> finite_difference(F f, std::vector<double> x, int n) {
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) {
    const double h = 1e-6;
    const double keep = x[i];
    x[i] = keep + h;
    const double up = f(x);
    x[i] = keep - h;
    const double down = f(x);
    x[i] = keep;
    g[i] = (up - down) / (2 * h);
  }
  return g;
}

TEST(CameraConstraints, ExactGradientsMatchFiniteDifferences) {
  Frame f;
  const HeightConstraint height(1, f.p, 1.0);
  const DistanceConstraint distance(0, 2, f.p, 1.0);
  const OrientationConstraint orientation(0, 2, f.p, 1.0);
  const FrameCoherenceConstraint coherence(0, 1, 2, f.p, 1.0);
  const csp::Constraint* all[] = {&height, &distance, &orientation, &coherence};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-6, 6), yaw(0, 360), desired(0, 180);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    FrameValues v = character_at({u(rng), u(rng) / 3, u(rng)}, yaw(rng));
    v.desired_height = 2 + u(rng) / 3;
    v.desired_distance = 4 + u(rng) / 3;
    v.desired_orientation = desired(rng);
    v.last_camera = {u(rng), u(rng), u(rng)};
    v.dt = 1.0 / 60;
    f.set(v);
    std::vector<double> cam = {u(rng), u(rng), u(rng)};
    for (const csp::Constraint* c : all) {
      ASSERT_TRUE(c->has_exact_gradient());
      const auto scope = c->scope();
      std::vector<double> grad(scope.size());
      const double value = c->violation_and_gradient(cam, grad);
      EXPECT_DOUBLE_EQ(value, c->violation(cam));
      // Skip points within a finite-difference step of a kink (|r| = 0).
      if (value < 1e-3) continue;
      auto g = finite_difference(
          [&](const std::vector<double>& x) { return c->violation(x); }, cam, 3);
      for (std::size_t i = 0; i < scope.size(); ++i) {
        EXPECT_NEAR(grad[i], g[scope[i]], 1e-4 * (1 + std::abs(g[scope[i]]))) << c->kind();
      }
      // The smooth stand-in, against differences of its own value.
      const double s = 0.5;
      c->smooth_violation_and_gradient(cam, grad, s);
      auto gs = finite_difference(
          [&](const std::vector<double>& x) {
            std::vector<double> scratch(scope.size());
            return c->smooth_violation_and_gradient(x, scratch, s);
          },
          cam, 3);
      for (std::size_t i = 0; i < scope.size(); ++i) {
        EXPECT_NEAR(grad[i], gs[scope[i]], 1e-4 * (1 + std::abs(gs[scope[i]]))) << c->kind();
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(OrientationConstraint, GradientStaysBoundedRightBehindTheCharacter) {
  Frame f;
  FrameValues v = character_at({0, 0, 0}, 0);
  v.desired_orientation = 30;
  f.set(v);
  const OrientationConstraint c(0, 2, f.p, 1.0);
  // 1e-9 rad off the facing, 4 m back: acos' would be ~1e9 here; the true derivative of the
  // angle is 1 / distance per radian = (180 / pi) / 4 degrees per metre sideways.
  const double cam[] = {-4e-9, 2, -4};
  double grad[2];
  EXPECT_NEAR(c.violation_and_gradient(cam, grad), 30, 1e-6);
  EXPECT_NEAR(std::abs(grad[0]), 180 / kPi / 4, 1e-6);
  EXPECT_NEAR(grad[1], 0, 1e-6);
}

TEST(CameraConstraints, DegenerateGeometryGivesZeroGradientsNotNaN) {
  Frame f;
  FrameValues v = character_at({1, 0, 2}, 0);
  v.desired_distance = 3;
  v.desired_orientation = 20;
  v.last_camera = {1, 5, 2};
  f.set(v);
  const double above[] = {1, 5, 2};  // right above the character, and not moving
  double g2[2], g3[3];
  const DistanceConstraint distance(0, 2, f.p, 1.0);
  EXPECT_EQ(distance.violation_and_gradient(above, g2), 3.0);
  EXPECT_EQ(g2[0], 0.0);
  EXPECT_EQ(g2[1], 0.0);
  const OrientationConstraint orientation(0, 2, f.p, 1.0);
  EXPECT_EQ(orientation.violation_and_gradient(above, g2), 70.0);  // |20 - 90|
  EXPECT_EQ(g2[0], 0.0);
  const FrameCoherenceConstraint coherence(0, 1, 2, f.p, 1.0);
  EXPECT_EQ(coherence.violation_and_gradient(above, g3), 0.0);
  EXPECT_EQ(g3[0], 0.0);
  EXPECT_FALSE(std::isnan(g3[1]));
}

// A scene: a low wall (1 m high) across x at z in [-2, -1.8], a tall wall far to the east.
Scene walls_scene() {
  std::vector<SolidBox> solids = {
      {"low-wall", {{-10, 0, -2}, {10, 1, -1.8}}, {}},
      {"tall-wall", {{20, 0, -10}, {20.5, 5, 10}}, {}},
  };
  return Scene("walls", std::move(solids), {}, {}, Trajectory({{0, {0, 0, 0}, 0}}));
}

TEST(LookAtVisibleConstraint, IsOneExactlyWhenTheSightLineIsBlocked) {
  const Scene scene = walls_scene();
  Frame f;
  f.set(character_at({0, 0, 0}, 0));  // look-at point (0, 1.5, 0)
  const SceneAtTime at(scene);
  const LookAtVisibleConstraint c(0, 1, 2, at, f.p);
  EXPECT_TRUE(c.is_hard());
  const double over[] = {0, 3, -6};    // the line passes over the low wall
  EXPECT_EQ(c.violation(over), 0.0);
  const double behind[] = {0, 0.2, -3};  // crosses the wall at 0.63 m, below its top
  EXPECT_EQ(c.violation(behind), 1.0);
  const double east[] = {25, 1.5, 0};  // behind the tall wall
  EXPECT_EQ(c.violation(east), 1.0);
}

TEST(BodyVisibilityConstraint, CountsTheVisibleSamplePoints) {
  const Scene scene = walls_scene();
  Frame f;
  f.set(character_at({0, 0, 0}, 0));
  const SceneAtTime at(scene);
  const BodyVisibilityConstraint c(0, 1, 2, at, f.p, 1.0);
  // Level with the body's centre (0.9 m), 10 m back: the wall hides the centre and the four
  // lower sample points (at 0.18 m); the four upper ones (1.62 m) show: 4 of 9 visible.
  const double low[] = {0, 0.9, -10};
  EXPECT_NEAR(c.violation(low), 5.0 / 9, 1e-12);
  const double high[] = {0, 6, -4};  // steep enough to see the feet over the wall
  EXPECT_EQ(c.violation(high), 0.0);
  const double hidden[] = {0, 0.3, -3};
  EXPECT_EQ(c.violation(hidden), 1.0);
}

TEST(BodyVisibility, AgreesWithBruteForceOnRandomScenes) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-8, 8), s(0.2, 3);
  std::vector<SolidBox> solids;
  for (int i = 0; i < 60; ++i) {
    const Eigen::Vector3d lo(u(rng), u(rng) / 4 + 1, u(rng));
    solids.push_back({"", {lo, lo + Eigen::Vector3d(s(rng), s(rng), s(rng))}, {}});
  }
  const Scene scene("random", solids, {}, {}, Trajectory({{0, {0, 0, 0}, 0}}));
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Vector3d camera(u(rng), u(rng) / 2 + 2, u(rng));
    const Aabb body = Aabb::around_feet({u(rng), 0, u(rng)}, {0.6, 1.8, 0.6});
    int visible = 0;
    for (const Eigen::Vector3d& p : body_sample_points(body)) {
      bool blocked = false;
      for (const SolidBox& b : solids) blocked = blocked || segment_hits_box(camera, p, b.box);
      visible += !blocked;
      EXPECT_TRUE(body.contains(p));
    }
    EXPECT_EQ(visible_fraction(scene, camera, body), visible / 9.0);
  }
}

TEST(ClearanceConstraint, GrowsAsTheCameraSphereSinksIntoGeometry) {
  const Scene scene = walls_scene();
  Frame f;
  f.set(FrameValues{});  // clearance radius 0.2
  const SceneAtTime at(scene);
  const ClearanceConstraint c(0, 1, 2, at, f.p);
  EXPECT_TRUE(c.is_hard());
  const double free_cam[] = {0, 3, -5};
  EXPECT_EQ(c.violation(free_cam), 0.0);
  const double near[] = {0, 0.5, -2.1};  // 0.1 m in front of the low wall
  EXPECT_NEAR(c.violation(near), 0.1, 1e-12);
  const double inside[] = {0, 0.5, -1.95};  // 0.05 m deep inside the wall
  EXPECT_NEAR(c.violation(inside), 0.25, 1e-12);
  const double above[] = {0, 1.2, -1.9};  // 0.2 m above its top: touching, not violated
  EXPECT_NEAR(c.violation(above), 0.0, 1e-12);
}

TEST(ClearanceConstraint, GradientMatchesFiniteDifferences) {
  const Scene scene = walls_scene();
  Frame f;
  f.set(FrameValues{});
  const SceneAtTime at(scene);
  const ClearanceConstraint c(0, 1, 2, at, f.p);
  ASSERT_TRUE(c.has_exact_gradient());
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> x(-1, 1), y(0.7, 1.3), z(-2.3, -1.5);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<double> cam = {x(rng), y(rng), z(rng)};
    double grad[3];
    const double value = c.violation_and_gradient(cam, grad);
    EXPECT_DOUBLE_EQ(value, c.violation(cam));
    if (value < 1e-3) continue;
    auto g = finite_difference([&](const std::vector<double>& p) { return c.violation(p); }, cam, 3);
    // Where two faces are equally near the derivative jumps; skip those points.
    if (std::abs(g[0]) + std::abs(g[1]) + std::abs(g[2]) > 1.0001) continue;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(grad[i], g[i], 1e-5);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace sightline::camera
