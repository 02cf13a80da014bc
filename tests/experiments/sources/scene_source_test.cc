// Scene sources (experiments/sources/scene_source.h): a source registered from this test file
// alone, and a built-in family, named in a suite file and filmed by the runner; ids stable
// across re-runs; bad entries refused with the line.
#include "sightline/experiments/sources/scene_source.h"

#include <gtest/gtest.h>

#include "sightline/csp/input_error.h"
#include "sightline/experiments/execution/suite_runner.h"
#include "sightline/experiments/suite/suite.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;

// A toy source: a hall with one pillar the character walks past, the pillar's side chosen
// by the seed. Registered once, from here.
camera::Scene toy_hall(std::uint64_t seed) {
  const double side = seed % 2 ? 1.0 : -1.0;
  std::vector<camera::SolidBox> boxes = {
      {"pillar", camera::Aabb{{side * 1.0, 0, 1.5}, {side * 1.6, 3, 2.1}}, {}}};
  camera::Trajectory walk({camera::Keyframe{0, {0, 0, -2}, 0}, camera::Keyframe{2, {0, 0, 4}, 0}});
  return camera::Scene("toy-hall-" + std::to_string(seed), std::move(boxes), {}, {},
                       std::move(walk), 30);
}

void register_toy_hall() {
  SceneSources& sources = SceneSources::global();
  if (sources.contains("toy-hall")) return;
  sources.add(seeded_source("toy-hall", "a hall with one pillar (a test's own source)", toy_hall));
}

TEST(SceneSources, ASourceRegisteredByATestIsFilmedFromASuiteFile) {
  register_toy_hall();
  ScratchDir dir("scene-sources");
  const std::string suite_path = dir.write("suite.yaml", R"(name: sources
camera:
  scenes:
    - scenes/wall.yaml
    - {source: toy-hall, seeds: [1, 2]}
    - {source: corridor, seed: 3}
  solvers: [occlusion-octree]
)");
  const Suite suite = read_suite_file(suite_path);
  ASSERT_EQ(suite.scenes.size(), 4u);
  EXPECT_EQ(suite.scenes[1].label, "toy-hall-1");
  EXPECT_EQ(suite.scenes[2].label, "toy-hall-2");
  EXPECT_TRUE(suite.scenes[1].path.empty());
  RunnerOptions options;
  options.out_dir = dir.path("out");
  options.jobs = 2;
  options.progress = false;
  const SuiteOutcome first = run_suite(suite, options);
  ASSERT_EQ(first.results.size(), 4u);
  const std::vector<std::string> columns = metric_columns(suite);
  for (const RunResult& r : first.results) {
    EXPECT_EQ(r.status, "ok") << r.subject << ": " << r.note;
    // Judged by the independent check: the pillar never hides her for long.
    EXPECT_GT(metric_value(columns, r, "visible_pct"), 90) << r.subject;
  }
  // Read again and re-run: the generated scenes have the same ids, nothing is redone.
  const SuiteOutcome again = run_suite(read_suite_file(suite_path), options);
  EXPECT_EQ(again.reused, 4u);
  EXPECT_EQ(again.ran, 0u);
}

TEST(SceneSources, TheFingerprintFollowsTheScene) {
  EXPECT_EQ(scene_fingerprint(toy_hall(1)), scene_fingerprint(toy_hall(1)));
  EXPECT_NE(scene_fingerprint(toy_hall(1)), scene_fingerprint(toy_hall(3)));  // same name pattern, other seed
  EXPECT_NE(scene_fingerprint(toy_hall(1)), scene_fingerprint(toy_hall(2)));
}

TEST(SceneSources, BadEntriesAreRefusedWithTheLine) {
  register_toy_hall();
  ScratchDir dir("scene-sources-bad");
  auto refused = [&](const std::string& entry, const std::string& words) {
    const std::string path = dir.write("bad.yaml", "name: bad\ncamera:\n  scenes:\n    - " + entry +
                                                       "\n  solvers: [occlusion-octree]\n");
    try {
      read_suite_file(path);
      ADD_FAILURE() << "accepted " << entry;
    } catch (const csp::InputError& e) {
      EXPECT_EQ(e.where().line, 4) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused("{source: no-such}", "unknown scene source 'no-such'");
  refused("{source: no-such}", "toy-hall");  // the list names every source
  refused("{source: corridor, mood: calm}", "mood");
  refused("{source: corridor, seeds: [-1]}", ">= 0");
  refused("{source: corridor, seed: 1, seeds: [2]}", "not both");
  refused("{seeds: [1]}", "source");
}

TEST(SceneSources, EveryBuiltInSourceIsListed) {
  const std::vector<std::string> names = SceneSources::global().names();
  for (const char* n : {"files", "corridor", "junction", "rooms", "colonnade", "traffic", "stairs",
                        "pillar-forest", "city", "switchback", "crossings"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  }
}

}  // namespace
}  // namespace sightline::experiments
