// Per-frame time of the chase camera (ChaseCamera::update with the `occlusion-octree`
// solver, the default) on generated scenes of 10, 1,000 and 10,000 boxes, and on the thesis
// scenes (experiments/scenes/) and the level walks (experiments/scenes/levels/). This is the figure a game programmer asks for: is the camera
// cheap enough to run every frame? Target: p99 under 200 us at 1,000 boxes on one core.
//
// Google Benchmark's statistics are per iteration, so one iteration here is a whole walk
// (every frame of the scene, a fresh camera) and the per-frame distribution comes from
// CameraFrame::solve_seconds (the whole update, timed inside it), collected over all
// iterations and reported as counters p50_us, p99_us and max_us. That is wall time: on a
// loaded machine a frame preempted by another process shows the whole time slice. So each
// update is also timed with the thread's CPU clock (CLOCK_THREAD_CPUTIME_ID, which stops
// while the thread is descheduled): cpu_p50_us, cpu_p99_us, cpu_max_us. On an idle core the
// two agree. Results and the command line: docs/BENCHMARKS.md.
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/metrics.h"
#include "sightline/experiments/sources/agile_families.h"
#include "sightline/experiments/sources/scene_families.h"
#include "sightline/experiments/sources/scene_files.h"
#include "sightline/experiments/sources/scene_generator.h"

namespace {

using sightline::camera::ChaseCamera;
using sightline::camera::ChaseCameraOptions;
using sightline::camera::Scene;

enum class World { kPillarForest, kCity };

double thread_cpu_us() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e6 + ts.tv_nsec * 1e-3;
}

double max_of(const std::vector<double>& v) {
  return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
}

// Walks the scene with a fresh camera every iteration; reports per-frame percentiles.
void walk(benchmark::State& state, const Scene& scene, const std::string& solver,
          const sightline::camera::CameraProfile& profile) {
  ChaseCameraOptions options;
  options.solver = solver;
  std::vector<double> frame_us, frame_cpu_us;
  frame_us.reserve(scene.frame_count() * 8);
  frame_cpu_us.reserve(scene.frame_count() * 8);
  for (auto _ : state) {
    ChaseCamera camera(scene, profile, options);
    double previous_t = scene.frame_time(0) - 1.0 / scene.frame_rate();
    for (std::size_t i = 0; i < scene.frame_count(); ++i) {
      const double t = scene.frame_time(i);
      const double dt = t > previous_t ? t - previous_t : 1.0 / scene.frame_rate();
      previous_t = t;
      const double cpu_before = thread_cpu_us();
      const auto& frame = camera.update(scene.character_at(t), dt);
      frame_cpu_us.push_back(thread_cpu_us() - cpu_before);
      frame_us.push_back(frame.solve_seconds * 1e6);
    }
    benchmark::DoNotOptimize(camera.frame().position.data());
  }
  state.counters["frames"] = static_cast<double>(frame_us.size());
  state.counters["boxes"] = static_cast<double>(scene.solids().size());
  state.counters["p50_us"] = sightline::experiments::percentile(frame_us, 50);
  state.counters["p99_us"] = sightline::experiments::percentile(frame_us, 99);
  state.counters["max_us"] = max_of(frame_us);
  state.counters["cpu_p50_us"] = sightline::experiments::percentile(frame_cpu_us, 50);
  state.counters["cpu_p99_us"] = sightline::experiments::percentile(frame_cpu_us, 99);
  state.counters["cpu_max_us"] = max_of(frame_cpu_us);
}

void walk(benchmark::State& state, const Scene& scene, const std::string& solver) {
  walk(state, scene, solver, scene.profile());
}

// `count` movers (people and carts, seeded) crossing the character's walk at random times,
// between the character and where the camera follows it.
void add_crossing_movers(Scene& scene, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<sightline::camera::Mover> movers;
  const auto& path = scene.trajectory();
  for (int i = 0; i < count; ++i) {
    const double when = path.start_time() + u(rng) * path.duration();
    const auto at = path.state_at(when);
    const Eigen::Vector3d behind = at.position - 2.5 * at.facing();
    const Eigen::Vector3d across(at.facing().z(), 0, -at.facing().x());
    const double speed = 1 + 3 * u(rng), span = 8;
    const Eigen::Vector3d size = u(rng) < 0.6 ? Eigen::Vector3d(0.6, 1.8, 0.6)
                                              : Eigen::Vector3d(2.5, 1.8, 1.2);
    movers.emplace_back("m" + std::to_string(i), size,
                        std::vector<sightline::camera::MoverKeyframe>{
                            {when - span / speed, behind - span * across},
                            {when + span / speed, behind + span * across}});
  }
  scene.set_movers(std::move(movers));
}

// The city with crossing movers (range 1), followed by the anticipating camera (range 2 = 1,
// preset `anticipating`) or the reactive one (0, thesis-default) for comparison.
void BM_AnticipatingFrame(benchmark::State& state) {
  sightline::experiments::GeneratedSceneOptions options;
  options.boxes = static_cast<std::size_t>(state.range(0));
  options.seed = 1;
  Scene scene = sightline::experiments::generate_city(options);
  add_crossing_movers(scene, static_cast<int>(state.range(1)), 7);
  walk(state, scene, "occlusion-octree",
       sightline::camera::preset_profile(state.range(2) ? "anticipating" : "thesis-default"));
  state.counters["movers"] = static_cast<double>(scene.movers().size());
}

BENCHMARK(BM_AnticipatingFrame)
    ->Args({1000, 0, 1})
    ->Args({1000, 20, 1})
    ->Args({1000, 20, 0})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);

void BM_ChaseCameraFrame(benchmark::State& state, World world) {
  sightline::experiments::GeneratedSceneOptions options;
  options.boxes = static_cast<std::size_t>(state.range(0));
  options.seed = 1;
  const Scene scene = world == World::kPillarForest
                          ? sightline::experiments::generate_pillar_forest(options)
                          : sightline::experiments::generate_city(options);
  walk(state, scene, "occlusion-octree");
}

BENCHMARK_CAPTURE(BM_ChaseCameraFrame, pillar_forest, World::kPillarForest)
    ->Arg(10)
    ->Arg(1000)
    ->Arg(10000)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ChaseCameraFrame, city, World::kCity)
    ->Arg(10)
    ->Arg(1000)
    ->Arg(10000)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);

// The thesis scenes, through experiments::run_camera (what `sightline follow` runs): its
// metrics' solve-time percentiles, one run per iteration.
void BM_ThesisScene(benchmark::State& state, const std::string& path) {
  const Scene scene = sightline::camera::read_scene_file(path);
  ChaseCameraOptions options;
  options.solver = "occlusion-octree";
  std::vector<double> p50, p99;
  for (auto _ : state) {
    const auto run = sightline::experiments::run_camera(scene, scene.profile(), options);
    p50.push_back(run.metrics.solve_us_p50);
    p99.push_back(run.metrics.solve_us_p99);
  }
  // The median over iterations of each run's percentile.
  state.counters["frames"] = static_cast<double>(scene.frame_count());
  state.counters["p50_us"] = sightline::experiments::percentile(p50, 50);
  state.counters["p99_us"] = sightline::experiments::percentile(p99, 50);
}

}  // namespace

int main(int argc, char** argv) {
  // Walks on real levels (experiments/scenes/levels/, made by `sightline level walk`): the
  // per-frame distribution over one whole walk (the level is loaded once, outside timing).
  // SIGHTLINE_BENCH_WALKS adds folders of walks (':'-separated): a user's own levels, or
  // walks on maps the project does not ship (docs/studies/2026-11-24-held-out-maps.md).
  std::vector<std::string> level_folders{std::string(SIGHTLINE_SOURCE_DIR) +
                                         "/experiments/scenes/levels"};
  if (const char* extra = std::getenv("SIGHTLINE_BENCH_WALKS")) {
    std::istringstream folders(extra);
    for (std::string folder; std::getline(folders, folder, ':');) {
      if (!folder.empty()) level_folders.push_back(folder);
    }
  }
  for (const std::string& levels : level_folders) {
    if (!std::filesystem::is_directory(levels)) {
      if (levels != level_folders.front()) {
        std::cerr << "SIGHTLINE_BENCH_WALKS: '" << levels << "' is not a folder\n";
        return 2;
      }
      continue;
    }
    for (const std::string& path : sightline::experiments::scene_files(levels)) {
      auto scene = std::make_shared<const Scene>(sightline::camera::read_scene_file(path));
      benchmark::RegisterBenchmark(
          ("BM_LevelWalk/" + std::filesystem::path(path).stem().string()).c_str(),
          [scene](benchmark::State& state) {
            walk(state, *scene, "occlusion-octree");
            state.counters["triangles"] = static_cast<double>(scene->triangle_index().triangle_count());
          })
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(
          ("BM_LevelWalkAnticipating/" + std::filesystem::path(path).stem().string()).c_str(),
          [scene](benchmark::State& state) {
            walk(state, *scene, "occlusion-octree",
                 sightline::camera::preset_profile("anticipating"));
            state.counters["triangles"] = static_cast<double>(scene->triangle_index().triangle_count());
          })
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
  for (const std::string& path : sightline::experiments::scene_files(
           std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes")) {
    benchmark::RegisterBenchmark(
        ("BM_ThesisScene/" + std::filesystem::path(path).stem().string()).c_str(),
        [path](benchmark::State& state) { BM_ThesisScene(state, path); })
        ->Iterations(3)
        ->Unit(benchmark::kMillisecond);
  }
  // The default camera (preset `default`) on every box scene: the shipped thesis and
  // anticipation scenes, and seeds 1-3 of the generated walk and agile families (issue 24's
  // target: p99 under 100 us on box scenes, one core).
  std::vector<std::shared_ptr<const Scene>> box_scenes;
  for (const char* folder : {"/experiments/scenes", "/experiments/scenes/anticipation"}) {
    for (const std::string& path : sightline::experiments::scene_files(std::string(SIGHTLINE_SOURCE_DIR) + folder)) {
      box_scenes.push_back(std::make_shared<const Scene>(sightline::camera::read_scene_file(path)));
    }
  }
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    for (const auto family : sightline::experiments::all_scene_families()) {
      box_scenes.push_back(std::make_shared<const Scene>(sightline::experiments::generate_family(family, seed)));
    }
    for (const auto family : sightline::experiments::all_agile_families()) {
      box_scenes.push_back(std::make_shared<const Scene>(sightline::experiments::generate_agile(family, seed)));
    }
  }
  for (const auto& scene : box_scenes) {
    benchmark::RegisterBenchmark(("BM_BoxSceneDefault/" + scene->name()).c_str(),
                                 [scene](benchmark::State& state) {
                                   walk(state, *scene, "occlusion-octree",
                                        sightline::camera::preset_profile(sightline::camera::kDefaultPreset));
                                 })
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
