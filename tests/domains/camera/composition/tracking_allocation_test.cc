// A tracking shot's per-frame path allocates nothing once warm: the per-frame refinement
// (shot-search without its global phase), the occasional global solve with foresight, the
// smoothing and FORMATS.md's verdict on the pose, on a shipped tracking scene with two
// people walking past pillars and one with three crossing a square.
//
// This executable replaces the global operator new with one that counts, which is why it is
// a test program of its own.
#include <gtest/gtest.h>

#include <string>

#include "sightline/domains/camera/composition/tracking_camera.h"
#include "sightline/domains/camera/scene_file.h"

#include "tests/count_allocations.h"

namespace sightline::camera {
namespace {

void expect_no_allocation_after_warm_up(const std::string& file) {
  const Scene scene = read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/shots/" + file);
  TrackingCamera camera(scene, TrackingOptions{});
  camera.reset(Eigen::Vector3d::Zero());
  const double dt = 1.0 / scene.frame_rate();
  std::size_t frame = 0;
  // Warm up: the first second grows every vector the frames use to its working size.
  for (; scene.frame_time(frame) < scene.frame_time(0) + 1.0; ++frame) {
    camera.update(scene.character_at(scene.frame_time(frame)), dt);
  }
  const long before = g_allocations.load();
  int feasible = 0, frames = 0;
  for (; frame < scene.frame_count(); ++frame) {
    const CameraFrame& f = camera.update(scene.character_at(scene.frame_time(frame)), dt);
    feasible += f.look_at_visible ? 1 : 0;
    ++frames;
  }
  EXPECT_GT(frames, 100) << file;
  EXPECT_EQ(feasible, frames) << file << ": an infeasible frame writes its reason (a string)";
  EXPECT_EQ(g_allocations.load() - before, 0) << file << ": allocations over " << frames << " frames";
}

TEST(TrackingFramePath, AllocatesNothingOnceWarm) {
  expect_no_allocation_after_warm_up("walk-and-talk.yaml");
  expect_no_allocation_after_warm_up("crossing-square.yaml");
}

}  // namespace
}  // namespace sightline::camera
