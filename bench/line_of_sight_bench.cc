// Line-of-sight query time against the number of boxes in a scene (the BVH of
// domains/camera/geometry/box_tree.h), with brute force alongside for contrast.
//
// The world is a fixed level, 400 m x 40 m x 400 m (y up), holding n random boxes:
//  - "detail" (the main series): the boxes always fill 2% of the level, so more boxes mean
//    finer detail: their edge shrinks like n^(-1/3) (about 22 m for 10 boxes, 1 m for
//    100,000), with each box's sides drawn in 0.5-1.5 x that edge;
//  - "crates": boxes of a fixed size (sides 0.5-1.5 m), so more boxes mean a denser level:
//    100,000 fill 1.6% of it, 1,000 only 0.016%.
// Queries are random segments of length 2-10 m (camera to character), in two patterns:
//  - frames (the camera's workload): 1024 frames, each a random character position in the
//    level and 64 sight lines to it from random camera positions 2-10 m away, run frame
//    after frame: each frame starts on a cold part of the tree and goes on on a warm one;
//  - incoherent: 65536 segments each somewhere else in the level, the worst case for the
//    caches.
// A clear segment is the expensive case for an any-hit query (no early exit); the counter
// `clear` is the fraction of clear ones. Results and their reading: docs/BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "sightline/domains/camera/geometry/box_tree.h"

namespace {

using sightline::camera::Aabb;
using sightline::camera::BoxTree;

const Eigen::Vector3d kLevel(400, 40, 400);
constexpr int kFrames = 1024;
constexpr int kPerFrame = 64;
constexpr int kSegments = kFrames * kPerFrame;  // a power of two: cycled with a mask

enum class Boxes { kDetail, kCrates };
enum class Queries { kFrames, kIncoherent };

std::vector<Aabb> random_boxes(std::size_t n, Boxes kind) {
  std::mt19937_64 rng(42);
  // E[side^3] = 1.25 edge^3 for sides uniform in [0.5, 1.5] x edge.
  const double edge = kind == Boxes::kCrates
                          ? 1.0
                          : std::cbrt(0.02 * kLevel.prod() / (1.25 * static_cast<double>(n)));
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_real_distribution<double> scale(0.5, 1.5);
  std::vector<Aabb> boxes(n);
  for (Aabb& b : boxes) {
    for (int a = 0; a < 3; ++a) {
      b.min[a] = unit(rng) * kLevel[a];
      b.max[a] = b.min[a] + edge * scale(rng);
    }
  }
  return boxes;
}

struct Segment {
  Eigen::Vector3d a, b;
};

std::vector<Segment> random_segments(Queries pattern) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_real_distribution<double> length(2, 10);
  std::normal_distribution<double> gauss;
  auto somewhere = [&] {
    return Eigen::Vector3d(kLevel.cwiseProduct(Eigen::Vector3d(unit(rng), unit(rng), unit(rng))));
  };
  auto direction = [&] {
    return Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
  };
  std::vector<Segment> segments(kSegments);
  Eigen::Vector3d character = somewhere();
  for (int i = 0; i < kSegments; ++i) {
    if (pattern == Queries::kIncoherent || i % kPerFrame == 0) character = somewhere();
    segments[i].b = character;
    segments[i].a = character + length(rng) * direction();
  }
  return segments;
}

void line_of_sight(benchmark::State& state, Boxes boxes, Queries pattern) {
  const BoxTree tree(random_boxes(static_cast<std::size_t>(state.range(0)), boxes));
  const std::vector<Segment> segments = random_segments(pattern);
  int clear = 0;
  for (const Segment& s : segments) clear += !tree.segment_blocked(s.a, s.b);
  std::size_t i = 0;
  for (auto _ : state) {
    const Segment& s = segments[i++ & (kSegments - 1)];
    benchmark::DoNotOptimize(tree.segment_blocked(s.a, s.b));
  }
  state.counters["clear"] = static_cast<double>(clear) / kSegments;
  state.counters["depth"] = tree.depth();
}

void BM_LineOfSight(benchmark::State& state) {
  line_of_sight(state, Boxes::kDetail, Queries::kFrames);
}
BENCHMARK(BM_LineOfSight)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

void BM_LineOfSightIncoherent(benchmark::State& state) {
  line_of_sight(state, Boxes::kDetail, Queries::kIncoherent);
}
BENCHMARK(BM_LineOfSightIncoherent)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

void BM_LineOfSightCrates(benchmark::State& state) {
  line_of_sight(state, Boxes::kCrates, Queries::kFrames);
}
BENCHMARK(BM_LineOfSightCrates)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

void BM_FirstHit(benchmark::State& state) {
  const BoxTree tree(random_boxes(static_cast<std::size_t>(state.range(0)), Boxes::kDetail));
  const std::vector<Segment> segments = random_segments(Queries::kFrames);
  std::size_t i = 0;
  for (auto _ : state) {
    const Segment& s = segments[i++ & (kSegments - 1)];
    benchmark::DoNotOptimize(tree.first_hit(s.a, s.b));
  }
}
BENCHMARK(BM_FirstHit)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

// The clearance constraint's query: the nearest box within 0.2 m of a camera position.
void BM_Clearance(benchmark::State& state) {
  const BoxTree tree(random_boxes(static_cast<std::size_t>(state.range(0)), Boxes::kDetail));
  const std::vector<Segment> segments = random_segments(Queries::kFrames);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tree.nearest(segments[i++ & (kSegments - 1)].a, 0.2));
  }
}
BENCHMARK(BM_Clearance)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

// What the thesis does: every box, one after another.
void BM_LineOfSightBruteForce(benchmark::State& state) {
  const std::vector<Aabb> boxes =
      random_boxes(static_cast<std::size_t>(state.range(0)), Boxes::kDetail);
  const std::vector<Segment> segments = random_segments(Queries::kFrames);
  std::size_t i = 0;
  for (auto _ : state) {
    const Segment& s = segments[i++ & (kSegments - 1)];
    bool blocked = false;
    for (const Aabb& b : boxes) {
      if (sightline::camera::segment_hits_box(s.a, s.b, b)) {
        blocked = true;
        break;
      }
    }
    benchmark::DoNotOptimize(blocked);
  }
}
BENCHMARK(BM_LineOfSightBruteForce)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000);

}  // namespace

BENCHMARK_MAIN();
