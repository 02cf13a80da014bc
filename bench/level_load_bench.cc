// Load and index time of real levels: every Quake III map installed by Debian's
// openarena-085-data and openarena-088-data packages, read from its .pk3 (load_level: unzip,
// parse, tessellate, convert) and then indexed by Embree (TriangleIndex), timed separately.
// Target: under 1 s for the largest map, both together. Prints one Markdown row per map,
// sorted by triangle count; figures with machine and date in docs/BENCHMARKS.md.
//
//   build/bench/level_load_bench [--repetitions 3]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "sightline/domains/camera/geometry/triangle_index.h"
#include "sightline/domains/camera/level/level.h"
#include "sightline/domains/camera/level/pk3_archive.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Row {
  std::string pack, map;
  std::size_t triangles = 0;
  double load_s = 1e300, index_s = 1e300;
};

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 3;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--repetitions") == 0) repetitions = std::max(1, std::atoi(argv[i + 1]));
  }
  const std::filesystem::path base = "/usr/share/games/openarena/baseoa";
  std::vector<Row> rows;
  for (const char* pack : {"pak6-patch085.pk3", "pak6-patch088.pk3"}) {
    const std::string file = (base / pack).string();
    if (!std::filesystem::exists(file)) {
      std::fprintf(stderr, "level_load_bench: %s is not installed (scripts/install-deps.sh)\n", file.c_str());
      return 2;
    }
    for (const std::string& map : sightline::camera::Pk3Archive(file).map_entries()) {
      Row row;
      row.pack = pack;
      row.map = map;
      for (int r = 0; r < repetitions; ++r) {
        sightline::camera::LevelSpec spec;
        spec.file = file;
        spec.map = map;
        const auto t0 = Clock::now();
        const sightline::camera::Level level = sightline::camera::load_level(spec);
        const auto t1 = Clock::now();
        const sightline::camera::TriangleIndex index(level.mesh);
        const auto t2 = Clock::now();
        row.triangles = index.triangle_count();
        row.load_s = std::min(row.load_s, std::chrono::duration<double>(t1 - t0).count());
        row.index_s = std::min(row.index_s, std::chrono::duration<double>(t2 - t1).count());
      }
      rows.push_back(row);
    }
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.triangles < b.triangles; });
  std::printf("| pack | map | triangles | load s | index s | total s |\n|---|---|---:|---:|---:|---:|\n");
  for (const Row& r : rows) {
    std::printf("| %s | %s | %zu | %.3f | %.3f | %.3f |\n", r.pack.c_str(), r.map.c_str(),
                r.triangles, r.load_s, r.index_s, r.load_s + r.index_s);
  }
  return 0;
}
