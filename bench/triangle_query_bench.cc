// The camera's geometric queries on triangles (TriangleIndex, Embree 3): time per
// segment_blocked, first_hit, nearest within 0.2 m (the clearance query) and unlimited
// nearest, and the build time, against the number of triangles; and on boxes, BoxTree
// against the same boxes as 12 triangles each in Embree, to decide whether boxes move into
// Embree.
//
// Three families of scenes:
//  - "terrain" (synthetic): a 400 m x 400 m heightfield (hills and ripples) holding half
//    the triangles, and walls and pillars (closed boxes, 1-6 m tall, covering 5% of the
//    ground) on it holding the other half: 1k, 10k, 100k and 1M triangles;
//  - "boxes": line_of_sight_bench's detail series (random boxes filling 2% of a
//    400 m x 40 m x 400 m level): 1k, 10k and 100k boxes (12k to 1.2M triangles), once in a
//    BoxTree and once as triangles in a TriangleIndex;
//  - "maps": OpenArena maps from Debian's openarena-088-data (oa_thor, oa_minia,
//    am_underworks2), read by the Quake III loader.
// Queries come in frames, as the camera asks them: a character position and 64 sight lines
// to it from cameras 2-10 m away (above the ground on the terrain; in empty space, by the
// map's solid volume, on the maps), 1024 frames, cycled. `blocked` is the fraction of sight
// lines that meet something (a clear one is the expensive case for an any-hit query).
// Boxes and their triangles do not answer the same question everywhere: a box is solid (a
// sight line starting or ending inside one is blocked, and nearest is a signed distance,
// negative inside), its 12 triangles are only its surface. So `blocked` differs slightly
// between the two forms, by the sight lines that lie inside a box.
// Scenes are built once per process and shared by the benchmarks that use them.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sightline/domains/camera/geometry/box_tree.h"
#include "sightline/domains/camera/geometry/triangle_index.h"
#include "sightline/domains/camera/level/q3_level.h"

namespace {

using Eigen::Vector3d;
using sightline::camera::Aabb;
using sightline::camera::BoxTree;
using sightline::camera::TriangleIndex;
using sightline::camera::TriangleMesh;

constexpr int kFrames = 1024;
constexpr int kPerFrame = 64;
constexpr int kSegments = kFrames * kPerFrame;  // a power of two: cycled with a mask

struct Segment {
  Vector3d a, b;  // a: the camera, b: the character's eyes
};

// ---- scenes ----------------------------------------------------------------------------

void append_box(TriangleMesh& mesh, const Aabb& box) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int k = 0; k < 8; ++k) {
    mesh.vertices.emplace_back(static_cast<float>((k & 1) ? box.max.x() : box.min.x()),
                               static_cast<float>((k & 2) ? box.max.y() : box.min.y()),
                               static_cast<float>((k & 4) ? box.max.z() : box.min.z()));
  }
  const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({base + q[0], base + q[1], base + q[2]});
    mesh.triangles.push_back({base + q[0], base + q[2], base + q[3]});
  }
}

double terrain_height(double x, double z) {
  return 3 * std::sin(x / 17) * std::cos(z / 23) + 0.5 * std::sin(x / 3.1 + z / 4.3);
}

// About n triangles: a heightfield of n/2 and n/24 boxes of 12, 1-6 m tall, whose
// footprints cover 5% of the ground whatever n (so more triangles mean finer detail, not a
// denser level, as in line_of_sight_bench's detail series).
TriangleMesh terrain_scene(std::size_t n) {
  TriangleMesh mesh;
  const double half = 200;
  const int grid = std::max(2, static_cast<int>(std::sqrt(static_cast<double>(n) / 4)) + 1);
  for (int i = 0; i < grid; ++i) {
    for (int j = 0; j < grid; ++j) {
      const double x = -half + 2 * half * i / (grid - 1), z = -half + 2 * half * j / (grid - 1);
      mesh.vertices.emplace_back(static_cast<float>(x), static_cast<float>(terrain_height(x, z)),
                                 static_cast<float>(z));
    }
  }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(i * grid + j); };
  for (int i = 0; i + 1 < grid; ++i) {
    for (int j = 0; j + 1 < grid; ++j) {
      mesh.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  const std::size_t walls = std::max<std::size_t>(1, n / 24);
  // E[side^2] = 13/12 edge^2 for sides uniform in [0.5, 1.5] x edge.
  const double edge = std::sqrt(0.05 * 4 * half * half / (13.0 / 12 * static_cast<double>(walls)));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-half, half), side(0.5 * edge, 1.5 * edge),
      height(1, 6);
  for (std::size_t k = 0; k < walls; ++k) {
    const double x = pos(rng), z = pos(rng);
    const Vector3d lo(x, terrain_height(x, z) - 1, z);
    append_box(mesh, {lo, lo + Vector3d(side(rng), height(rng), side(rng))});
  }
  return mesh;
}

// line_of_sight_bench's "detail" boxes: n boxes filling 2% of the level.
const Vector3d kLevel(400, 40, 400);
std::vector<Aabb> detail_boxes(std::size_t n) {
  std::mt19937_64 rng(42);
  const double edge = std::cbrt(0.02 * kLevel.prod() / (1.25 * static_cast<double>(n)));
  std::uniform_real_distribution<double> unit(0, 1), scale(0.5, 1.5);
  std::vector<Aabb> boxes(n);
  for (Aabb& b : boxes) {
    for (int a = 0; a < 3; ++a) {
      b.min[a] = unit(rng) * kLevel[a];
      b.max[a] = b.min[a] + edge * scale(rng);
    }
  }
  return boxes;
}

// Frames of sight lines: characters from `character()`, cameras 2-10 m away along a
// direction from `direction()`, kept when `allowed(camera)`.
template <class Character, class Direction, class Allowed>
std::vector<Segment> frames(std::mt19937_64& rng, Character character, Direction direction,
                            Allowed allowed) {
  std::uniform_real_distribution<double> length(2, 10);
  std::vector<Segment> segments;
  segments.reserve(kSegments);
  while (segments.size() < kSegments) {
    const Vector3d eyes = character();
    for (int k = 0, tries = 0; k < kPerFrame && tries < 100 * kPerFrame; ++tries) {
      const Vector3d camera = eyes + length(rng) * direction();
      if (!allowed(camera)) continue;
      segments.push_back({camera, eyes});
      ++k;
    }
  }
  segments.resize(kSegments);
  return segments;
}

Vector3d random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

// A scene in both forms where it has them (triangles always; boxes for the box family).
struct Scene {
  std::string name;
  TriangleMesh mesh;
  std::vector<Aabb> boxes;
  std::unique_ptr<TriangleIndex> index;
  std::unique_ptr<BoxTree> tree;
  std::vector<Segment> segments;
  double build_seconds = 0;
};

void build_index(Scene& s) {
  const auto start = std::chrono::steady_clock::now();
  s.index = std::make_unique<TriangleIndex>(s.mesh);
  s.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const Scene& terrain(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Scene>> cache;
  auto& s = cache[n];
  if (s) return *s;
  s = std::make_unique<Scene>();
  s->mesh = terrain_scene(n);
  build_index(*s);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(-190, 190);
  s->segments = frames(
      rng,
      [&] {
        const double x = pos(rng), z = pos(rng);
        return Vector3d(x, terrain_height(x, z) + 1.5, z);
      },
      [&] {
        Vector3d d = random_direction(rng);
        d.y() = std::abs(d.y());  // cameras look from above
        return d;
      },
      [&](const Vector3d& c) { return c.y() > terrain_height(c.x(), c.z()) + 0.3; });
  return *s;
}

const Scene& boxes(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Scene>> cache;
  auto& s = cache[n];
  if (s) return *s;
  s = std::make_unique<Scene>();
  s->boxes = detail_boxes(n);
  for (const Aabb& b : s->boxes) append_box(s->mesh, b);
  build_index(*s);
  s->tree = std::make_unique<BoxTree>(s->boxes);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  s->segments = frames(
      rng, [&] { return Vector3d(kLevel.cwiseProduct(Vector3d(unit(rng), unit(rng), unit(rng)))); },
      [&] { return random_direction(rng); }, [](const Vector3d&) { return true; });
  return *s;
}

const char* const kMaps[] = {"oa_thor", "oa_minia", "am_underworks2"};

const Scene& map(int which) {
  static std::map<int, std::unique_ptr<Scene>> cache;
  auto& s = cache[which];
  if (s) return *s;
  s = std::make_unique<Scene>();
  sightline::camera::LevelSpec spec;
  spec.file = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3";
  spec.map = kMaps[which];
  // load_level's defaults for .pk3: 32 units to the metre, z up.
  const sightline::camera::Level level = sightline::camera::load_quake3_level(
      spec, sightline::camera::LevelTransform{0.03125, sightline::camera::UpAxis::kZ});
  s->name = kMaps[which];
  s->mesh = level.mesh;
  build_index(*s);
  const Aabb bounds = level.mesh.bounds();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  auto empty = [&](const Vector3d& p) { return !level.solid || !level.solid->solid_at(p); };
  s->segments = frames(
      rng,
      [&] {
        Vector3d p;
        for (int tries = 0; tries < 100000; ++tries) {
          p = bounds.min + bounds.size().cwiseProduct(Vector3d(unit(rng), unit(rng), unit(rng)));
          if (empty(p)) break;
        }
        return p;
      },
      [&] { return random_direction(rng); }, empty);
  return *s;
}

// ---- the benchmarks --------------------------------------------------------------------

enum class Query { kBlocked, kFirstHit, kClearance, kNearest };

template <class Index>
void run(benchmark::State& state, const Index& index, const std::vector<Segment>& segments,
         Query query) {
  std::size_t i = 0;
  for (auto _ : state) {
    const Segment& s = segments[i++ & (kSegments - 1)];
    switch (query) {
      case Query::kBlocked: benchmark::DoNotOptimize(index.segment_blocked(s.a, s.b)); break;
      case Query::kFirstHit: benchmark::DoNotOptimize(index.first_hit(s.a, s.b)); break;
      case Query::kClearance: benchmark::DoNotOptimize(index.nearest(s.a, 0.2)); break;
      case Query::kNearest: benchmark::DoNotOptimize(index.nearest(s.a)); break;
    }
  }
  int blocked = 0;
  for (const Segment& s : segments) blocked += index.segment_blocked(s.a, s.b) ? 1 : 0;
  state.counters["blocked"] = static_cast<double>(blocked) / kSegments;
}

void describe(benchmark::State& state, const Scene& s) {
  state.counters["triangles"] = static_cast<double>(s.mesh.size());
  state.counters["build_ms"] = 1e3 * s.build_seconds;
  if (!s.name.empty()) state.SetLabel(s.name);
}

template <Query q>
void BM_Terrain(benchmark::State& state) {
  const Scene& s = terrain(static_cast<std::size_t>(state.range(0)));
  run(state, *s.index, s.segments, q);
  describe(state, s);
}
BENCHMARK(BM_Terrain<Query::kBlocked>)->Name("Terrain/Blocked")->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK(BM_Terrain<Query::kFirstHit>)->Name("Terrain/FirstHit")->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK(BM_Terrain<Query::kClearance>)->Name("Terrain/Clearance0.2")->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK(BM_Terrain<Query::kNearest>)->Name("Terrain/Nearest")->RangeMultiplier(10)->Range(1000, 1000000);

template <Query q>
void BM_BoxesEmbree(benchmark::State& state) {
  const Scene& s = boxes(static_cast<std::size_t>(state.range(0)));
  run(state, *s.index, s.segments, q);
  describe(state, s);
}
template <Query q>
void BM_BoxesBoxTree(benchmark::State& state) {
  const Scene& s = boxes(static_cast<std::size_t>(state.range(0)));
  run(state, *s.tree, s.segments, q);
}
BENCHMARK(BM_BoxesBoxTree<Query::kBlocked>)->Name("Boxes/BoxTree/Blocked")->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_BoxesEmbree<Query::kBlocked>)->Name("Boxes/Embree/Blocked")->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_BoxesBoxTree<Query::kFirstHit>)->Name("Boxes/BoxTree/FirstHit")->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_BoxesEmbree<Query::kFirstHit>)->Name("Boxes/Embree/FirstHit")->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_BoxesBoxTree<Query::kClearance>)->Name("Boxes/BoxTree/Clearance0.2")->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_BoxesEmbree<Query::kClearance>)->Name("Boxes/Embree/Clearance0.2")->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_BoxesBoxTree<Query::kNearest>)->Name("Boxes/BoxTree/Nearest")->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_BoxesEmbree<Query::kNearest>)->Name("Boxes/Embree/Nearest")->RangeMultiplier(10)->Range(1000, 100000);

template <Query q>
void BM_Map(benchmark::State& state) {
  const Scene& s = map(static_cast<int>(state.range(0)));
  run(state, *s.index, s.segments, q);
  describe(state, s);
}
BENCHMARK(BM_Map<Query::kBlocked>)->Name("Map/Blocked")->DenseRange(0, 2);
BENCHMARK(BM_Map<Query::kFirstHit>)->Name("Map/FirstHit")->DenseRange(0, 2);
BENCHMARK(BM_Map<Query::kClearance>)->Name("Map/Clearance0.2")->DenseRange(0, 2);
BENCHMARK(BM_Map<Query::kNearest>)->Name("Map/Nearest")->DenseRange(0, 2);

// Build times, measured afresh each iteration (the scenes above are built once).
void BM_BuildTerrain(benchmark::State& state) {
  const TriangleMesh mesh = terrain_scene(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(TriangleIndex(mesh));
  state.counters["triangles"] = static_cast<double>(mesh.size());
}
BENCHMARK(BM_BuildTerrain)->Name("Build/Terrain/Embree")->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

void BM_BuildBoxesEmbree(benchmark::State& state) {
  TriangleMesh mesh;
  for (const Aabb& b : detail_boxes(static_cast<std::size_t>(state.range(0)))) append_box(mesh, b);
  for (auto _ : state) benchmark::DoNotOptimize(TriangleIndex(mesh));
}
void BM_BuildBoxesBoxTree(benchmark::State& state) {
  const std::vector<Aabb> boxes = detail_boxes(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(BoxTree(boxes));
}
BENCHMARK(BM_BuildBoxesBoxTree)->Name("Build/Boxes/BoxTree")->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildBoxesEmbree)->Name("Build/Boxes/Embree")->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);

void BM_BuildMap(benchmark::State& state) {
  const Scene& s = map(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(TriangleIndex(s.mesh));
  state.counters["triangles"] = static_cast<double>(s.mesh.size());
  state.SetLabel(s.name);
}
BENCHMARK(BM_BuildMap)->Name("Build/Map/Embree")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
