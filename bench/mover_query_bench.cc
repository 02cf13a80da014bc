// Movers beside the static geometry: how the camera's queries should find them.
//
// A street of 1,000 static boxes (a 200 m x 200 m block of buildings and pillars) and 5 to
// 500 movers (pedestrian- to bus-sized boxes) crossing it. Each "frame" the movers are placed
// at the frame's time and 64 or 1,024 sight lines are tested (a baseline's probes; an
// octree frame's candidates). Two ways to
// hold the movers:
//   - flat:    the movers' boxes in an array, refreshed every frame,
//              tested one by one after one reject against their common bounds;
//   - rebuilt: a BoxTree (the static index's BVH) rebuilt over the movers every frame
//              (allocates: not allowed on the frame path, shown for scale);
//   - refit:   a BoxTree built once at the first frame and refitted every frame (its shape
//              kept, node bounds recomputed; BoxTree::refit).
// BM_SceneAtTime is what the camera runs: the flat array sorted every frame into groups of
// four along the movers' longest axis, each group with its own bounds (scene_at_time.h).
// Reported per frame (Time column): placement (and build) plus the sight lines.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "sightline/domains/camera/geometry/box_tree.h"
#include "sightline/domains/camera/scene_at_time.h"

namespace {

using Eigen::Vector3d;
using sightline::camera::Aabb;
using sightline::camera::BoxTree;
using sightline::camera::Mover;
using sightline::camera::MoverKeyframe;
using sightline::camera::Scene;
using sightline::camera::SceneAtTime;
using sightline::camera::SolidBox;
using sightline::camera::Trajectory;

constexpr double kFrameSeconds = 1.0 / 60;

Scene street(int movers) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> xz(-100, 100), side(1, 8), height(2, 15);
  std::vector<SolidBox> boxes;
  for (int i = 0; i < 1000; ++i) {
    const Vector3d lo(xz(rng), 0, xz(rng));
    boxes.push_back({"", {lo, lo + Vector3d(side(rng), height(rng), side(rng))}, {}});
  }
  std::vector<Mover> list;
  std::uniform_real_distribution<double> start(0, 5), size(0.5, 3);
  for (int m = 0; m < movers; ++m) {
    const double t0 = start(rng);
    const Vector3d a(xz(rng), 0, xz(rng)), b(xz(rng), 0, xz(rng));
    list.emplace_back("", Vector3d(size(rng), 2 * size(rng), size(rng)),
                      std::vector<MoverKeyframe>{{t0, a}, {t0 + 20, b}, {t0 + 40, a}});
  }
  Scene scene("street", std::move(boxes), {}, {},
              Trajectory({{0, {0, 0, 0}, 0}, {60, {0, 0, 1}, 0}}));
  scene.set_movers(std::move(list));
  return scene;
}

std::vector<std::pair<Vector3d, Vector3d>> sight_lines() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> xz(-100, 100), off(-8, 8), up(1, 6);
  std::vector<std::pair<Vector3d, Vector3d>> lines;
  for (int i = 0; i < 65536; ++i) {
    const Vector3d look(xz(rng), 1.5, xz(rng));
    lines.push_back({look + Vector3d(off(rng), up(rng), off(rng)), look});
  }
  return lines;
}

void BM_SceneAtTime(benchmark::State& state) {
  const Scene scene = street(static_cast<int>(state.range(0)));
  const auto lines = sight_lines();
  const auto per_frame = static_cast<int>(state.range(1));
  SceneAtTime now(scene);
  std::size_t next = 0, frame = 0;
  int blocked = 0;
  for (auto _ : state) {
    now.set_time(static_cast<double>(frame++ % 3600) * kFrameSeconds);
    for (int i = 0; i < per_frame; ++i, next = (next + 1) % lines.size()) {
      blocked += now.mover_blocks(lines[next].first, lines[next].second);
    }
  }
  benchmark::DoNotOptimize(blocked);
}

void BM_MoversRebuiltTree(benchmark::State& state) {
  const Scene scene = street(static_cast<int>(state.range(0)));
  const auto lines = sight_lines();
  const auto per_frame = static_cast<int>(state.range(1));
  std::size_t next = 0, frame = 0;
  int blocked = 0;
  std::vector<Aabb> boxes(scene.movers().size());
  for (auto _ : state) {
    const double t = static_cast<double>(frame++ % 3600) * kFrameSeconds;
    for (std::size_t m = 0; m < boxes.size(); ++m) boxes[m] = scene.movers()[m].box_at(t);
    const BoxTree tree(boxes);
    for (int i = 0; i < per_frame; ++i, next = (next + 1) % lines.size()) {
      blocked += tree.segment_blocked(lines[next].first, lines[next].second);
    }
  }
  benchmark::DoNotOptimize(blocked);
}

void BM_MoversRefitTree(benchmark::State& state) {
  const Scene scene = street(static_cast<int>(state.range(0)));
  const auto lines = sight_lines();
  const auto per_frame = static_cast<int>(state.range(1));
  std::size_t next = 0, frame = 0;
  int blocked = 0;
  std::vector<Aabb> boxes(scene.movers().size());
  for (std::size_t m = 0; m < boxes.size(); ++m) boxes[m] = scene.movers()[m].box_at(0);
  BoxTree tree(boxes);
  for (auto _ : state) {
    const double t = static_cast<double>(frame++ % 3600) * kFrameSeconds;
    for (std::size_t m = 0; m < boxes.size(); ++m) boxes[m] = scene.movers()[m].box_at(t);
    tree.refit(boxes);
    for (int i = 0; i < per_frame; ++i, next = (next + 1) % lines.size()) {
      blocked += tree.segment_blocked(lines[next].first, lines[next].second);
    }
  }
  benchmark::DoNotOptimize(blocked);
}

// The static index alone, for scale: the same sight lines through the 1,000 boxes.
void BM_StaticSightLines(benchmark::State& state) {
  const Scene scene = street(0);
  const auto lines = sight_lines();
  const auto per_frame = static_cast<int>(state.range(0));
  std::size_t next = 0;
  int blocked = 0;
  for (auto _ : state) {
    for (int i = 0; i < per_frame; ++i, next = (next + 1) % lines.size()) {
      blocked += !scene.line_of_sight(lines[next].first, lines[next].second);
    }
  }
  benchmark::DoNotOptimize(blocked);
}

BENCHMARK(BM_StaticSightLines)->Arg(64)->Arg(1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SceneAtTime)
    ->ArgsProduct({{5, 20, 100, 500}, {64, 1024}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MoversRefitTree)
    ->ArgsProduct({{5, 20, 100, 500}, {64, 1024}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MoversRebuiltTree)
    ->ArgsProduct({{5, 20, 100, 500}, {64, 1024}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
