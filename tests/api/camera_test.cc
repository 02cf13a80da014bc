// The public C++ camera (sightline/camera.h), tried as a game would: a world of its own
// (brute force over boxes, no sightline code) or sightline's geometry world, people states
// each frame. Visibility, openness and smoothness are judged by the test's own oracle.
#include "sightline/camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "box_oracle.h"

namespace {

using sightline::Box;
using sightline::PersonState;
using sightline::Vec3;

std::vector<Box> pillars_and_wall() {
  return {
      Box{{-1.6, 0, -0.4}, {-0.8, 3, 0.4}},   // pillar left of the walk
      Box{{0.8, 0, 2.6}, {1.6, 3, 3.4}},      // pillar right of the walk
      Box{{-6, 0, 7.8}, {6, 3, 8.2}},         // a wall ahead, reached and turned from
      Box{{-3.5, 0, -3}, {-3.1, 2.5, 3}},     // a long low wall beside the walk
  };
}

// Walks +z from z = -6 to z = 6 at 1.5 m/s, then turns right and walks +x.
PersonState walker(double t) {
  PersonState p;
  if (t < 8) {
    p.position = {0, 0, -6 + 1.5 * t};
    p.velocity = {0, 0, 1.5};
    p.yaw = 0;
  } else {
    const double u = t - 8;
    p.position = {1.5 * u, 0, 6};
    p.velocity = {1.5, 0, 0};
    p.yaw = 90;
  }
  return p;
}

Box body_of(const Vec3& feet, const sightline::PersonShape& s) {
  return Box{{feet.x - s.size.x / 2, feet.y, feet.z - s.size.z / 2},
             {feet.x + s.size.x / 2, feet.y + s.size.y, feet.z + s.size.z / 2}};
}

double length(const Vec3& a, const Vec3& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

struct RunFigures {
  int frames = 0, hidden = 0, inside = 0, unflagged_jumps = 0, cuts = 0;
};

// Runs `camera` over the walk (with `crosser` people crossing it, if any) and judges each
// frame with the oracle over `boxes` plus the other people's bodies.
RunFigures run(sightline::Camera& camera, const std::vector<Box>& boxes, bool with_crosser) {
  RunFigures f;
  const double dt = 1.0 / 60;
  Vec3 last = camera.pose().position;
  for (int i = 1; i <= 12 * 60; ++i) {
    const double t = i * dt;
    std::vector<PersonState> people{walker(t)};
    std::vector<Box> solid = boxes;
    if (with_crosser) {
      // Crosses the walk between the camera and the walker, right to left, at 1.2 m/s.
      PersonState c;
      c.position = {3 - 1.2 * (t - 2), 0, 1.5 * t - 7.5};
      c.velocity = {-1.2, 0, 1.5};
      c.yaw = 270;
      people.push_back(c);
      solid.push_back(body_of(c.position, sightline::PersonShape{}));
    }
    const sightline::CameraPose& pose = camera.update(people, dt);
    ++f.frames;
    if (!box_oracle::clear(solid, pose.position, pose.target)) ++f.hidden;
    for (const Box& b : boxes) {
      if (box_oracle::distance(pose.position, b) < 0) ++f.inside;
    }
    if (pose.cut) ++f.cuts;
    else if (length(pose.position, last) > 8.0 * dt + 1e-6) ++f.unflagged_jumps;
    last = pose.position;
  }
  return f;
}

sightline::Camera make_camera(std::shared_ptr<const sightline::World> world, int people,
                              const std::string& profile = "anticipating") {
  sightline::CameraSettings s;
  s.profile = profile;
  s.people.assign(people, sightline::PersonShape{});
  std::vector<PersonState> start{walker(0)};
  if (people > 1) {
    PersonState c;
    c.position = {5.4, 0, -7.5};
    start.push_back(c);
  }
  return sightline::Camera(std::move(world), s, start, 0.0);
}

TEST(PublicCamera, KeepsThePersonInViewWithTheGamesOwnWorld) {
  auto world = std::make_shared<box_oracle::BruteForceWorld>(pillars_and_wall());
  sightline::Camera camera = make_camera(world, 1);
  const RunFigures f = run(camera, pillars_and_wall(), false);
  EXPECT_EQ(f.hidden, 0);
  EXPECT_EQ(f.inside, 0);
  EXPECT_EQ(f.unflagged_jumps, 0);
  EXPECT_GT(world->calls, 0);  // the camera asked the game's world
}

TEST(PublicCamera, KeepsThePersonInViewWithSightlinesGeometryWorld) {
  sightline::WorldGeometry g;
  g.boxes = pillars_and_wall();
  sightline::Camera camera = make_camera(sightline::make_geometry_world(g), 1);
  const RunFigures f = run(camera, pillars_and_wall(), false);
  EXPECT_EQ(f.hidden, 0);
  EXPECT_EQ(f.inside, 0);
  EXPECT_EQ(f.unflagged_jumps, 0);
}

TEST(PublicCamera, ThesisPresetAlsoKeepsThePersonInView) {
  auto world = std::make_shared<box_oracle::BruteForceWorld>(pillars_and_wall());
  sightline::Camera camera = make_camera(world, 1, "thesis-default");
  const RunFigures f = run(camera, pillars_and_wall(), false);
  EXPECT_EQ(f.hidden, 0);
  EXPECT_EQ(f.unflagged_jumps, 0);
}

TEST(PublicCamera, OtherPeopleBlockSightWhereTheGameSaysTheyAre) {
  // The world does not know the crossing person (a game's camera channel may ignore pawns):
  // the camera places it from the state passed to update and keeps the walker in view of it.
  auto world = std::make_shared<box_oracle::BruteForceWorld>(pillars_and_wall());
  sightline::Camera camera = make_camera(world, 2);
  const RunFigures f = run(camera, pillars_and_wall(), true);
  EXPECT_EQ(f.hidden, 0);
  EXPECT_EQ(f.unflagged_jumps, 0);
}

TEST(PublicCamera, RefusesBadInputWithAMessage) {
  auto world = std::make_shared<box_oracle::BruteForceWorld>(pillars_and_wall());
  sightline::CameraSettings s;
  std::vector<PersonState> one{walker(0)};
  s.profile = "no-such-preset";
  EXPECT_THROW(sightline::Camera(world, s, one), sightline::Error);
  s.profile = "anticipating-path";  // reads a scripted future
  EXPECT_THROW(sightline::Camera(world, s, one), sightline::Error);
  s.profile = "anticipating";
  s.solver = "no-such-solver";
  EXPECT_THROW(sightline::Camera(world, s, one), sightline::Error);
  s.solver = "occlusion-octree";
  EXPECT_THROW(sightline::Camera(nullptr, s, one), sightline::Error);
  std::vector<PersonState> nan{walker(0)};
  nan[0].position.x = std::nan("");
  EXPECT_THROW(sightline::Camera(world, s, nan), sightline::Error);
  sightline::Camera camera(world, s, one);
  EXPECT_THROW(camera.update(nan, 1.0 / 60), sightline::Error);
  EXPECT_THROW(camera.update(one, 0.0), sightline::Error);
  std::vector<PersonState> two{walker(0), walker(0)};
  EXPECT_THROW(camera.update(two, 1.0 / 60), sightline::Error);
  // Still usable after refusals.
  EXPECT_NO_THROW(camera.update(std::vector<PersonState>{walker(1.0 / 60)}, 1.0 / 60));
}

TEST(PublicCamera, ProfileTextIsReadAsAProfile) {
  auto world = std::make_shared<box_oracle::BruteForceWorld>(pillars_and_wall());
  sightline::CameraSettings s;
  s.profile = "name: mine\nbase: thesis-default\ndistance: {desired: 5}\n";
  std::vector<PersonState> one{walker(0)};
  sightline::Camera camera(world, s, one);
  const sightline::CameraPose& p = camera.update(std::vector<PersonState>{walker(1.0 / 60)}, 1.0 / 60);
  EXPECT_TRUE(std::isfinite(p.position.x));
  s.profile = "name: broken\ndistance: {desired: [1, 2]}\n";
  EXPECT_THROW(sightline::Camera(world, s, one), sightline::Error);
}

TEST(PublicCamera, ListsPresetsAndSolvers) {
  const auto presets = sightline::camera_presets();
  EXPECT_NE(std::find(presets.begin(), presets.end(), "anticipating"), presets.end());
  EXPECT_EQ(std::find(presets.begin(), presets.end(), "anticipating-path"), presets.end());
  const auto solvers = sightline::camera_solvers();
  EXPECT_NE(std::find(solvers.begin(), solvers.end(), "occlusion-octree"), solvers.end());
  EXPECT_STRNE(sightline::version(), "");
}

}  // namespace
