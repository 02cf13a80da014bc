// The public camera filming an experiment scene through the World interface (SceneWorld: the
// scene's geometry answered as a game's physics would, query by query) against the internal
// camera asking the scene directly: on every shipped level walk (no areas, so both cameras
// sense the same space) the two must move the camera identically, frame by frame. It caught
// the anticipating camera's wall-sliding forecast asking the scene's own (empty) geometry
// instead of the game's world.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "sightline/camera.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/domains/camera/scene_world.h"
#include "sightline/experiments/runs/camera_run.h"

namespace {

namespace camera = sightline::camera;

sightline::Vec3 plain(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

sightline::PersonState person(const camera::CharacterState& s) {
  return {plain(s.position), plain(s.velocity), s.yaw};
}

// Every shipped level walk.
std::vector<std::string> walk_names() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SIGHTLINE_SOURCE_DIR) +
                                                           "/experiments/scenes/levels")) {
    if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class PublicCameraOnWalk : public testing::TestWithParam<std::string> {};

TEST_P(PublicCameraOnWalk, MovesAsTheInternalCameraFrameByFrame) {
  const std::string path =
      std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/levels/" + GetParam() + ".yaml";
  camera::Scene scene = [&] {
    try {
      return camera::read_scene_file(path);
    } catch (const std::exception& e) {
      return camera::Scene("missing", {}, {}, {}, camera::Trajectory({camera::Keyframe{}}));
    }
  }();
  if (scene.level() == nullptr) GTEST_SKIP() << "the map is not installed (openarena-088-data)";
  const camera::CameraProfile profile = camera::preset_profile("anticipating");
  const sightline::experiments::CameraRun internal =
      sightline::experiments::run_camera(scene, profile, camera::ChaseCameraOptions{});

  sightline::CameraSettings settings;
  settings.profile = "anticipating";
  settings.people = {{plain(scene.character().size), scene.character().look_at_height}};
  settings.has_start = true;
  settings.start = plain(scene.start_camera_position());
  settings.frame_rate = scene.frame_rate();
  // Created one frame before the first, so that the first update lands on its time, as the
  // internal run's first frame does.
  const double dt0 = 1.0 / scene.frame_rate();
  const double t0 = scene.frame_time(0);
  std::vector<sightline::PersonState> people{person(scene.character_at(t0))};
  sightline::Camera public_camera(std::make_shared<camera::SceneWorld>(scene), settings, people,
                                  t0 - dt0);
  double previous = t0 - dt0;
  ASSERT_EQ(internal.trace.size(), scene.frame_count());
  int differing = 0;
  double worst = 0;
  for (std::size_t i = 0; i < scene.frame_count(); ++i) {
    const double t = scene.frame_time(i);
    people[0] = person(scene.character_at(t));
    const sightline::CameraPose& pose = public_camera.update(people, t - previous, t);
    previous = t;
    const Eigen::Vector3d p(pose.position.x, pose.position.y, pose.position.z);
    const double gap = (p - internal.trace[i].camera).norm();
    worst = std::max(worst, gap);
    if (gap > 1e-9 || pose.cut != internal.trace[i].cut) {
      if (differing == 0) {
        ADD_FAILURE() << "first difference at frame " << i << " (t = " << t << "): public ("
                      << p.transpose() << ") cut " << pose.cut << ", internal ("
                      << internal.trace[i].camera.transpose() << ") cut " << internal.trace[i].cut;
      }
      ++differing;
    }
  }
  EXPECT_EQ(differing, 0) << "largest gap " << worst << " m";
}

INSTANTIATE_TEST_SUITE_P(ShippedWalks, PublicCameraOnWalk, testing::ValuesIn(walk_names()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
