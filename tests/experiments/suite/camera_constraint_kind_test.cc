// Camera constraint kinds (domains/camera/constraints/camera_constraint_kinds.h): a kind
// registered from this test file alone, used from a suite file through a profile's
// `extras:`, moves the camera as it asks; its fields are checked with the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"
#include "sightline/csp/kinds/constraint_entry.h"
#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/constraints/camera_constraint_kinds.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/execution/suite_runner.h"
#include "sightline/experiments/runs/trace.h"
#include "sightline/experiments/suite/suite.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

// A toy camera constraint: the camera at least `above` metres high. violation = the
// shortfall; it reads only cam_y of the context.
class KeepAbove : public csp::Constraint {
 public:
  KeepAbove(const camera::CameraConstraintContext& c, double above, double weight, bool hard)
      : Constraint({c.cam_y}, weight, hard), above_(above) {}
  std::string_view kind() const override { return "test.keep_above"; }
  double violation(std::span<const double> values) const override {
    return std::max(0.0, above_ - values[scope()[0]]);
  }

 private:
  double above_;
};

void register_keep_above() {
  camera::CameraConstraintKinds& kinds = camera::CameraConstraintKinds::global();
  if (kinds.find("test.keep_above")) return;
  camera::CameraConstraintKind kind;
  kind.name = "test.keep_above";
  kind.description = "the camera at least `above` metres high (a test's own)";
  kind.fields = {"above"};
  kind.make = [](const camera::CameraConstraintContext& c, const csp::Spec& entry) {
    return std::make_unique<KeepAbove>(c, entry.at("above").as_number("a height"),
                                       csp::read_weight(entry), csp::read_hard(entry));
  };
  kinds.add(std::move(kind));
}

double mean_camera_height(const std::string& trace_path) {
  const std::vector<TraceRow> trace = read_trace_csv(trace_path);
  double sum = 0;
  for (const TraceRow& r : trace) sum += r.camera.y();
  return sum / static_cast<double>(trace.size());
}

TEST(CameraConstraintKinds, AKindRegisteredByATestIsUsedFromASuiteFile) {
  register_keep_above();
  testing::ScratchDir dir("camera-kinds");
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: kinds
camera:
  scenes: [scenes/wall.yaml]
  solvers: [occlusion-octree]
  profiles:
    - thesis-default
    - {label: high, profile: {name: high, base: thesis-default,
                              extras: [{kind: test.keep_above, above: 4.0, weight: 20}]}}
)"));
  RunnerOptions options;
  options.out_dir = dir.path("out");
  options.progress = false;
  const SuiteOutcome outcome = run_suite(suite, options);
  ASSERT_EQ(outcome.results.size(), 2u);
  double plain = 0, high = 0;
  for (const RunResult& r : outcome.results) {
    ASSERT_EQ(r.status, "ok") << r.note;
    const double h = mean_camera_height(run_file_base(options.out_dir, r.id) + ".trace.csv");
    (r.profile == "high" ? high : plain) = h;
  }
  // The profile's desired height is 2.5 m; the extra constraint lifts the camera toward 4.
  EXPECT_GT(high, plain + 0.5) << "plain " << plain << ", high " << high;
  std::printf("mean camera height: plain %.2f m, with test.keep_above 4 m: %.2f m\n", plain, high);
}

TEST(CameraConstraintKinds, FieldsAreCheckedWithTheLine) {
  register_keep_above();
  testing::ScratchDir dir("camera-kinds-bad");
  const camera::Scene scene = camera::read_scene_file(dir.path("scenes/wall.yaml"));
  auto refused = [&](const std::string& extras, int line, const std::string& words) {
    const camera::CameraProfile profile = camera::parse_profile(
        csp::parse_yaml("name: p\nbase: thesis-default\nextras:\n" + extras, "p.yaml"));
    try {
      camera::CameraProblem problem(scene, profile);
      ADD_FAILURE() << "accepted " << extras;
    } catch (const csp::InputError& e) {
      EXPECT_EQ(e.where().line, line) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused("  - {kind: test.keep_above, above: 1, mood: calm}\n", 4, "mood");
  refused("  - {kind: test.keep_above}\n", 4, "above");
  refused("  - {kind: camera.keep_point_in_view, point: [1, 2]}\n", 4, "point");
}

TEST(CameraConstraintKinds, KeepPointInViewCountsWhatHidesThePoint) {
  testing::ScratchDir dir("camera-kinds-point");
  const camera::Scene scene = camera::read_scene_file(dir.path("scenes/wall.yaml"));
  const camera::CameraProfile profile = camera::parse_profile(csp::parse_yaml(
      "name: p\nbase: thesis-default\nextras:\n  - {kind: camera.keep_point_in_view, point: [0, 1, 5]}\n",
      "p.yaml"));
  const camera::CameraProblem problem(scene, profile);
  const csp::Problem& p = problem.problem();
  const csp::ConstraintId id = p.num_constraints() - 1;
  ASSERT_EQ(p.constraint(id).kind(), "camera.keep_point_in_view");
  // The wall spans x in [-3, 3], z in [2, 2.3], 3 m high: from z = -2 at 1 m it hides
  // (0, 1, 5); from 8 m up the line passes over it.
  const double behind[3] = {0, 1, -2}, above[3] = {0, 8, -2};
  EXPECT_EQ(p.constraint(id).violation(behind), 1.0);
  EXPECT_EQ(p.constraint(id).violation(above), 0.0);
}

}  // namespace
}  // namespace sightline::experiments
