// Suite files: what they expand into, and the errors a bad one gets (file:line, and what
// was expected or which names are valid).
#include "sightline/experiments/suite/suite.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <set>

#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;

const char* kGoodSuite = R"(name: tiny
camera:
  scenes: [scenes/*.yaml]
  solvers:
    - occlusion-octree
    - {label: bourne-published, solver: bourne-octree, controller: {visibility_guard: false},
       area_adaptation: false}
  profiles: [scene, close-follow]
  seeds: [1, 2]
problems:
  instances:
    - {nqueens: [6, 8]}
  solvers: [sls, {solver: bnb, label: exact}]
  seeds: 3
  limits: {time_seconds: 2}
)";

// The message of the InputError `read` throws, or "" when it throws none.
template <class F>
std::string error_of(F read) {
  try {
    read();
  } catch (const csp::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SuiteFile, ExpandsIntoEveryCombinationInAFixedOrder) {
  ScratchDir dir("suite-expand");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kGoodSuite));
  ASSERT_EQ(suite.scenes.size(), 2u);
  EXPECT_EQ(suite.scenes[0].label, "room");  // glob results are sorted by path
  EXPECT_EQ(suite.scenes[1].label, "wall");
  ASSERT_EQ(suite.camera_solvers.size(), 2u);
  EXPECT_FALSE(suite.camera_solvers[1].options.visibility_guard);
  EXPECT_TRUE(suite.camera_solvers[0].options.visibility_guard);
  ASSERT_EQ(suite.profiles.size(), 2u);
  EXPECT_EQ(suite.profiles[1].label, "close-follow");
  EXPECT_EQ(suite.toy_seeds, std::vector<std::uint64_t>{3});
  EXPECT_EQ(suite.toy_limits.time_limit_seconds, 2);

  const std::vector<SuiteRun> runs = expand_runs(suite);
  ASSERT_EQ(runs.size(), 2u * 2 * 2 * 2 + 2u * 2 * 1);
  EXPECT_EQ(runs.front().kind, SuiteRun::Kind::kCamera);
  EXPECT_EQ(runs.back().kind, SuiteRun::Kind::kToy);
  std::set<std::string> ids;
  for (const SuiteRun& r : runs) ids.insert(r.id);
  EXPECT_EQ(ids.size(), runs.size()) << "run ids must be unique";
  EXPECT_EQ(runs[0].id.rfind("room__occlusion-octree__scene__s1__", 0), 0u) << runs[0].id;
}

TEST(SuiteFile, RunIdsAreStableAcrossReadsAndChangeWhenARunIsRedefined) {
  ScratchDir dir("suite-ids");
  const std::string path = dir.write("suite.yaml", kGoodSuite);
  const std::vector<SuiteRun> first = expand_runs(read_suite_file(path));
  const std::vector<SuiteRun> again = expand_runs(read_suite_file(path));
  ASSERT_EQ(first.size(), again.size());
  for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(first[i].id, again[i].id);

  std::string edited = kGoodSuite;
  edited.replace(edited.find("visibility_guard: false"), 23, "visibility_guard: true ");
  const std::vector<SuiteRun> changed = expand_runs(read_suite_file(dir.write("suite.yaml", edited)));
  std::size_t differing = 0;
  for (std::size_t i = 0; i < first.size(); ++i) differing += first[i].id != changed[i].id;
  EXPECT_EQ(differing, 2u * 2 * 2) << "exactly the bourne-published runs are redefined";
}

TEST(SuiteFile, AreaAdaptationCanBeDroppedPerSolverEntry) {
  ScratchDir dir("suite-areas");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kGoodSuite));
  for (const SuiteRun& run : expand_runs(suite)) {
    if (run.kind != SuiteRun::Kind::kCamera) continue;
    const camera::CameraProfile p = run_profile(suite, run);
    const bool published = suite.camera_solvers[run.solver].label == "bourne-published";
    EXPECT_EQ(p.enclosed == camera::AreaAdaptation{}, published) << run.id;
    EXPECT_EQ(p.semi_enclosed == camera::AreaAdaptation{}, published) << run.id;
  }
}

TEST(SuiteFile, AnUnknownFieldIsAnErrorNamingTheLineAndTheValidFields) {
  ScratchDir dir("suite-field");
  const std::string path = dir.write("suite.yaml", R"(name: x
camera:
  scenes: [scenes/wall.yaml]
  solvers: [occlusion-octree]
  seed: [1]
)");
  const std::string message = error_of([&] { read_suite_file(path); });
  EXPECT_NE(message.find("suite.yaml:5"), std::string::npos) << message;
  EXPECT_NE(message.find("seed"), std::string::npos) << message;
  EXPECT_NE(message.find("seeds"), std::string::npos) << message;
}

TEST(SuiteFile, AnUnknownSolverIsAnErrorListingTheValidNames) {
  ScratchDir dir("suite-solver");
  const std::string path = dir.write("suite.yaml", R"(name: x
camera:
  scenes: [scenes/wall.yaml]
  solvers:
    - occlusion-octree
    - occlusion-octre
)");
  const std::string message = error_of([&] { read_suite_file(path); });
  EXPECT_NE(message.find("suite.yaml:6"), std::string::npos) << message;
  EXPECT_NE(message.find("occlusion-octre'"), std::string::npos) << message;
  EXPECT_NE(message.find("sliding-octree"), std::string::npos) << "lists valid names: " << message;

  const std::string toy = dir.write("toy.yaml", R"(name: x
problems:
  instances: [{nqueens: 8}]
  solvers: [sls, annealing]
)");
  const std::string toy_message = error_of([&] { read_suite_file(toy); });
  EXPECT_NE(toy_message.find("toy.yaml:4"), std::string::npos) << toy_message;
  EXPECT_NE(toy_message.find("annealing"), std::string::npos) << toy_message;
  EXPECT_NE(toy_message.find("bnb"), std::string::npos) << toy_message;
}

TEST(SuiteFile, BadSolverOptionsAreErrorsAtTheirEntry) {
  ScratchDir dir("suite-options");
  const std::string path = dir.write("suite.yaml", R"(name: x
camera:
  scenes: [scenes/wall.yaml]
  solvers:
    - {solver: sliding-octree, options: {no_such_option: 3}}
)");
  const std::string message = error_of([&] { read_suite_file(path); });
  EXPECT_NE(message.find("suite.yaml:5"), std::string::npos) << message;
  EXPECT_NE(message.find("no_such_option"), std::string::npos) << message;
}

TEST(SuiteFile, SmoothingStagesAreReadAndABadCountIsAnErrorAtItsLine) {
  ScratchDir dir("suite-stages");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: x
camera:
  scenes: [scenes/wall.yaml]
  solvers:
    - occlusion-octree
    - {label: smooth, solver: occlusion-octree, controller: {target_smoothing_stages: 2}}
)"));
  ASSERT_EQ(suite.camera_solvers.size(), 2u);
  EXPECT_EQ(suite.camera_solvers[0].options.target_smoothing_stages, 1);
  EXPECT_EQ(suite.camera_solvers[1].options.target_smoothing_stages, 2);
  for (const char* bad : {"0", "5", "1.5", "two"}) {
    const std::string path = dir.write("bad.yaml", std::string(R"(name: x
camera:
  scenes: [scenes/wall.yaml]
  solvers:
    - {solver: occlusion-octree, controller: {target_smoothing_stages: )") + bad + "}}\n");
    const std::string message = error_of([&] { read_suite_file(path); });
    EXPECT_NE(message.find("bad.yaml:5"), std::string::npos) << bad << ": " << message;
    EXPECT_NE(message.find("stages"), std::string::npos) << bad << ": " << message;
  }
}

TEST(SuiteFile, ReplayAssetsAreInlineUnlessTheReportSaysBesideAndOtherValuesAreErrors) {
  ScratchDir dir("suite-replay-assets");
  const std::string head = "name: x\ncamera:\n  scenes: [scenes/wall.yaml]\n  solvers: [spring-arm]\n";
  EXPECT_FALSE(read_suite_file(dir.write("a.yaml", head)).replay_assets_beside);
  EXPECT_FALSE(read_suite_file(dir.write("b.yaml", head + "report: {replay_assets: inline}\n"))
                   .replay_assets_beside);
  EXPECT_TRUE(read_suite_file(dir.write("c.yaml", head + "report: {replay_assets: beside}\n"))
                  .replay_assets_beside);
  const std::string bad = dir.write("d.yaml", head + "report:\n  replay_assets: next-door\n");
  const std::string message = error_of([&] { read_suite_file(bad); });
  EXPECT_NE(message.find("d.yaml:6"), std::string::npos) << message;
  EXPECT_NE(message.find("inline or beside"), std::string::npos) << message;
}

TEST(SuiteFile, AGlobMatchingNothingIsAnError) {
  ScratchDir dir("suite-glob");
  const std::string path = dir.write("suite.yaml", R"(name: x
camera:
  scenes:
    - scenes/wall.yaml
    - scenes/nothing-*.yaml
  solvers: [occlusion-octree]
)");
  const std::string message = error_of([&] { read_suite_file(path); });
  EXPECT_NE(message.find("suite.yaml:5"), std::string::npos) << message;
  EXPECT_NE(message.find("matches no file"), std::string::npos) << message;

  const std::string missing = dir.write("missing.yaml", R"(name: x
camera:
  scenes: [scenes/absent.yaml]
  solvers: [occlusion-octree]
)");
  const std::string missing_message = error_of([&] { read_suite_file(missing); });
  EXPECT_NE(missing_message.find("missing.yaml:3"), std::string::npos) << missing_message;
  EXPECT_NE(missing_message.find("does not exist"), std::string::npos) << missing_message;
}

TEST(SuiteFile, MissingScenesOrSolversAreErrors) {
  ScratchDir dir("suite-missing");
  const std::string no_scenes = dir.write("a.yaml", "name: x\ncamera:\n  solvers: [sls]\n");
  const std::string m1 = error_of([&] { read_suite_file(no_scenes); });
  EXPECT_NE(m1.find("a.yaml:3"), std::string::npos) << m1;
  EXPECT_NE(m1.find("scenes"), std::string::npos) << m1;

  const std::string no_solvers = dir.write("b.yaml", "name: x\ncamera:\n  scenes: [scenes/wall.yaml]\n");
  const std::string m2 = error_of([&] { read_suite_file(no_solvers); });
  EXPECT_NE(m2.find("b.yaml:3"), std::string::npos) << m2;
  EXPECT_NE(m2.find("solvers"), std::string::npos) << m2;

  const std::string empty = dir.write("c.yaml", "name: x\n");
  EXPECT_NE(error_of([&] { read_suite_file(empty); }).find("c.yaml:1"), std::string::npos);
}

TEST(SuiteFile, DuplicateLabelsAndBadSeedsAreErrors) {
  ScratchDir dir("suite-dup");
  const std::string dup = dir.write("dup.yaml", R"(name: x
camera:
  scenes: [scenes/wall.yaml]
  solvers: [occlusion-octree, {solver: bourne-octree, label: occlusion-octree}]
)");
  const std::string m1 = error_of([&] { read_suite_file(dup); });
  EXPECT_NE(m1.find("dup.yaml:4"), std::string::npos) << m1;
  EXPECT_NE(m1.find("duplicate"), std::string::npos) << m1;

  const std::string seeds = dir.write("seeds.yaml", R"(name: x
camera:
  scenes: [scenes/wall.yaml]
  solvers: [occlusion-octree]
  seeds: [1, -2]
)");
  const std::string m2 = error_of([&] { read_suite_file(seeds); });
  EXPECT_NE(m2.find("seeds.yaml:5"), std::string::npos) << m2;
  EXPECT_NE(m2.find("seed"), std::string::npos) << m2;
}

}  // namespace
}  // namespace sightline::experiments

namespace sightline::experiments {
namespace {

TEST(SuiteFile, ReferencesNameTheSuitesProblemsAndSolvers) {
  ScratchDir dir("suite-references");
  dir.write("refs.csv", "# reference values\n8-queens,0\n\n6-queens,0\n");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: refs
problems:
  instances: [{nqueens: [6, 8]}]
  solvers: [sls, bnb]
  references: {values: {8-queens: 0}, file: refs.csv, from: bnb, tolerance: 0.5}
)"));
  EXPECT_EQ(suite.references.at("8-queens"), 0);
  EXPECT_EQ(suite.references.at("6-queens"), 0);
  EXPECT_EQ(suite.reference_from, "bnb");
  EXPECT_EQ(suite.reference_tolerance, 0.5);

  auto refused = [&](const std::string& references, const std::string& words, int line) {
    try {
      read_suite_file(dir.write("bad.yaml", "name: bad\nproblems:\n  instances: [{nqueens: [6]}]\n"
                                            "  solvers: [sls]\n  references: " + references + "\n"));
      ADD_FAILURE() << "accepted " << references;
    } catch (const csp::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_EQ(e.where().line, line) << e.what();
    }
  };
  refused("{values: {9-queens: 0}}", "9-queens", 5);
  refused("{from: tabu}", "tabu", 5);
  refused("{tolerance: -1}", "tolerance", 5);
  dir.write("bad.csv", "6-queens,0\n7-queens,1\n");
  refused("{file: bad.csv}", "7-queens", 2);  // the file's own line
  dir.write("nan.csv", "6-queens,lots\n");
  refused("{file: nan.csv}", "reference value", 1);
}

}  // namespace
}  // namespace sightline::experiments
