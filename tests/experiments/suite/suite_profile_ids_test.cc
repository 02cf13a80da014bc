// Run ids follow what a camera run's profile says, not only where it came from: editing an
// inline profile, a profile file or a file it inherits from changes the ids of exactly the
// runs with that profile; a rewrite that says the same (same bytes, keys reordered, a comment
// added, 2 written 2.0) keeps them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/profile_text.h"
#include "sightline/experiments/suite/suite.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

using testing::ScratchDir;

// One scene, one solver, four profiles: inline, a file that names another file as its base
// and a preset.
std::string suite_text(const std::string& inline_profile) {
  return R"(name: profile-ids
camera:
  scenes: [scenes/wall.yaml]
  solvers: [occlusion-octree]
  profiles:
    - scene
    - {label: mine, profile: )" +
         inline_profile + R"(}
    - profiles/child.yaml
    - close-follow
)";
}

const char* kInline = "{height: {desired: 2.0, weight: 1}, distance: {desired: 3}}";
const char* kChild = R"(name: child
base: close-follow
height: {desired: 1.7}
cuts: {stuck: false}
)";

// The ids of the runs, one per profile, in the suite's order.
std::vector<std::string> ids(const ScratchDir& dir, const std::string& inline_profile) {
  const Suite suite = read_suite_file(dir.write("suite.yaml", suite_text(inline_profile)));
  std::vector<std::string> out;
  for (const SuiteRun& run : expand_runs(suite)) out.push_back(run.id);
  return out;
}

// Which of two id lists' entries differ.
std::vector<bool> differing(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  EXPECT_EQ(a.size(), b.size());
  std::vector<bool> out;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) out.push_back(a[i] != b[i]);
  return out;
}

TEST(SuiteProfileIds, EditingAnInlineProfileChangesOnlyItsRuns) {
  ScratchDir dir("profile-ids-inline");
  dir.write("profiles/child.yaml", kChild);
  const auto before = ids(dir, kInline);
  ASSERT_EQ(before.size(), 4u);
  const auto after = ids(dir, "{height: {desired: 2.0, weight: 1}, distance: {desired: 3.5}}");
  EXPECT_EQ(differing(before, after), (std::vector<bool>{false, true, false, false}));
  // An extra constraint is part of the profile too.
  const auto extra = ids(dir, std::string(kInline).insert(1, "extras: [{kind: expression, "
                                                             "scope: [cam_y], formula: \"cam_y\"}], "));
  EXPECT_EQ(differing(before, extra), (std::vector<bool>{false, true, false, false}));
}

TEST(SuiteProfileIds, RewritingAnInlineProfileThatSaysTheSameKeepsTheIds) {
  ScratchDir dir("profile-ids-inline-same");
  dir.write("profiles/child.yaml", kChild);
  const auto before = ids(dir, kInline);
  EXPECT_EQ(ids(dir, kInline), before);
  // Keys reordered, 1 written 1.0, 3 written 3.00.
  EXPECT_EQ(ids(dir, "{distance: {desired: 3.00}, height: {weight: 1.0, desired: 2}}"), before);
}

TEST(SuiteProfileIds, EditingAProfileFileOrTheFileItInheritsFromChangesItsRuns) {
  ScratchDir dir("profile-ids-file");
  dir.write("profiles/child.yaml", kChild);
  const auto before = ids(dir, kInline);

  // A field of the file itself.
  dir.write("profiles/child.yaml", std::string(kChild) + "clearance: {radius: 0.25}\n");
  const auto edited = ids(dir, kInline);
  EXPECT_EQ(differing(before, edited), (std::vector<bool>{false, false, true, false}));

  // What the file inherits: a `base:` is a preset (compiled in, so not editable here); the
  // base's fields are in the resolved profile, so naming another base changes the ids even
  // though the file's own fields are unchanged.
  dir.write("profiles/child.yaml", R"(name: child
base: high-follow
height: {desired: 1.7}
cuts: {stuck: false}
)");
  const auto rebased = ids(dir, kInline);
  EXPECT_EQ(differing(before, rebased), (std::vector<bool>{false, false, true, false}));

  // Same content again, reordered, with a comment: the original ids come back.
  dir.write("profiles/child.yaml", R"(# the child profile, written differently
cuts: {stuck: false}
height: {desired: 1.70}
base: close-follow
name: child
)");
  EXPECT_EQ(ids(dir, kInline), before);
}

TEST(SuiteProfileIds, EditingTheProfileFileASceneNamesChangesItsSceneProfileRuns) {
  ScratchDir dir("profile-ids-scene");
  dir.write("profiles/child.yaml", kChild);
  const std::string wall = testing::read_text(dir.path("scenes/wall.yaml"));
  dir.write("scenes/wall.yaml", wall + "camera: {profile: ../profiles/scene-own.yaml}\n");
  dir.write("profiles/scene-own.yaml", "name: own\ndistance: {desired: 3}\n");
  const auto before = ids(dir, kInline);
  dir.write("profiles/scene-own.yaml", "name: own\ndistance: {desired: 3.2}\n");
  const auto after = ids(dir, kInline);
  // The scene file's bytes did not change; only the "scene" profile's run did.
  EXPECT_EQ(differing(before, after), (std::vector<bool>{true, false, false, false}));
}

TEST(ProfileText, IncludesWhatAProfileInheritsFromItsBase) {
  const camera::CameraProfile close = camera::preset_profile("close-follow");
  const camera::CameraProfile high = camera::preset_profile("high-follow");
  const auto on = [](const char* base) {
    return camera::parse_profile(
        csp::Spec::map({{"base", csp::Spec::string(base)}, {"name", csp::Spec::string("x")}}));
  };
  EXPECT_EQ(camera::profile_text(on("close-follow")), camera::profile_text(close));
  EXPECT_EQ(camera::profile_text(on("high-follow")), camera::profile_text(high));
  EXPECT_NE(camera::profile_text(close), camera::profile_text(high));
}

TEST(ProfileText, ChangesWithEveryFieldThatAffectsARun) {
  using camera::CameraProfile;
  const CameraProfile base;
  const std::string text = camera::profile_text(base);
  EXPECT_EQ(camera::profile_text(base), text);
  // Label-only fields change nothing.
  CameraProfile renamed = base;
  renamed.name = "other";
  renamed.description = "words";
  EXPECT_EQ(camera::profile_text(renamed), text);

  // Each edit below must change the text (a field left out of it would not).
  std::vector<void (*)(CameraProfile&)> edits = {
      [](CameraProfile& p) { p.height.desired += 1e-12; },
      [](CameraProfile& p) { p.height.weight += 0.5; },
      [](CameraProfile& p) { p.distance.desired += 0.5; },
      [](CameraProfile& p) { p.distance.weight += 0.5; },
      [](CameraProfile& p) { p.orientation.desired += 0.5; },
      [](CameraProfile& p) { p.orientation.weight += 0.5; },
      [](CameraProfile& p) { p.frame_coherence_weight += 0.5; },
      [](CameraProfile& p) { p.look_at_hard = !p.look_at_hard; },
      [](CameraProfile& p) { p.look_at_weight += 0.5; },
      [](CameraProfile& p) { p.visible_fraction_weight += 0.5; },
      [](CameraProfile& p) { p.clearance_radius += 0.5; },
      [](CameraProfile& p) { p.clearance_hard = !p.clearance_hard; },
      [](CameraProfile& p) { p.clearance_weight += 0.5; },
      [](CameraProfile& p) { p.search_half_size += 0.5; },
      [](CameraProfile& p) { p.enclosed.ceiling_margin.reset(); },
      [](CameraProfile& p) { p.enclosed.distance_fraction = 0.9; },
      [](CameraProfile& p) { p.semi_enclosed.ceiling_margin = 0.1; },
      [](CameraProfile& p) { p.semi_enclosed.distance_fraction.reset(); },
      [](CameraProfile& p) { p.sensing.enabled = !p.sensing.enabled; },
      [](CameraProfile& p) { p.sensing.ceiling_probe += 0.5; },
      [](CameraProfile& p) { p.sensing.behind_probe += 0.5; },
      [](CameraProfile& p) { p.sensing.wall_margin += 0.5; },
      [](CameraProfile& p) { p.sensing.min_distance += 0.5; },
      [](CameraProfile& p) { p.sensing.smoothing += 0.5; },
      [](CameraProfile& p) { p.anticipation.lookahead = camera::Lookahead::kPath; },
      [](CameraProfile& p) { p.anticipation.horizon += 0.5; },
      [](CameraProfile& p) { p.anticipation.samples += 1; },
      [](CameraProfile& p) { p.anticipation.weight += 0.5; },
      [](CameraProfile& p) { p.anticipation.decay += 0.5; },
      [](CameraProfile& p) { p.anticipation.plan_seconds += 0.5; },
      [](CameraProfile& p) { p.anticipation.max_jerk += 0.5; },
      [](CameraProfile& p) { p.cuts.leave_enclosed = !p.cuts.leave_enclosed; },
      [](CameraProfile& p) { p.cuts.backing_up = !p.cuts.backing_up; },
      [](CameraProfile& p) { p.cuts.stuck = !p.cuts.stuck; },
      [](CameraProfile& p) { p.cuts.smooth_escape = !p.cuts.smooth_escape; },
      [](CameraProfile& p) { p.cuts.cut_ahead = !p.cuts.cut_ahead; },
      [](CameraProfile& p) { p.extras.push_back(csp::Spec::map({{"kind", csp::Spec::string("x")}})); },
  };
  for (std::size_t i = 0; i < edits.size(); ++i) {
    CameraProfile edited = base;
    edits[i](edited);
    EXPECT_NE(camera::profile_text(edited), text) << "edit " << i << " left the text as it was";
  }
  // Two fields swapped must not read as the same profile.
  CameraProfile swapped = base;
  std::swap(swapped.height.desired, swapped.distance.desired);
  EXPECT_NE(camera::profile_text(swapped), text);
}

TEST(ProfileText, ExtrasAreReadAsValuesNotAsWritten) {
  using csp::Spec;
  camera::CameraProfile a, b, c;
  a.extras.push_back(Spec::map({{"kind", Spec::string("expression")}, {"weight", Spec::string("2")}}));
  b.extras.push_back(Spec::map({{"weight", Spec::string("2.0")}, {"kind", Spec::string("expression")}}));
  c.extras.push_back(Spec::map({{"kind", Spec::string("expression")}, {"weight", Spec::string("3")}}));
  EXPECT_EQ(camera::profile_text(a), camera::profile_text(b));
  EXPECT_NE(camera::profile_text(a), camera::profile_text(c));
  // A string that merely looks like structure is still a string.
  camera::CameraProfile d, e;
  d.extras.push_back(Spec::map({{"formula", Spec::string("a,b")}}));
  e.extras.push_back(Spec::map({{"formula", Spec::string("a")}, {"b", Spec::null({})}}));
  EXPECT_NE(camera::profile_text(d), camera::profile_text(e));
}

}  // namespace
}  // namespace sightline::experiments
