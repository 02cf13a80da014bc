// Camera profiles: presets, files and their errors, and the per-area switching of the
// desired height and distance (thesis table 9) on entering and leaving areas.
#include <gtest/gtest.h>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/area_profile_switch.h"
#include "sightline/domains/camera/profile_file.h"

namespace sightline::camera {
namespace {

CameraProfile parse(const std::string& text) {
  return parse_profile(csp::parse_yaml(text, "profile.yaml"));
}

TEST(CameraProfile, DefaultsAreValid) { EXPECT_EQ(CameraProfile{}.validate(), ""); }

TEST(CameraProfile, ShippedPresetsLoadAndValidate) {
  const auto names = preset_names();
  for (const char* wanted : {"thesis-default", "close-follow", "high-follow"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), wanted), names.end()) << wanted;
  }
  for (const auto& name : names) {
    const CameraProfile p = preset_profile(name);
    EXPECT_EQ(p.name, name);
    EXPECT_EQ(p.validate(), "") << name;
    EXPECT_FALSE(p.description.empty()) << name;
  }
}

TEST(CameraProfile, ThesisDefaultPresetIsTheBuiltInDefault) {
  const CameraProfile file = preset_profile("thesis-default");
  const CameraProfile code;
  EXPECT_EQ(file.height.desired, code.height.desired);
  EXPECT_EQ(file.height.weight, code.height.weight);
  EXPECT_EQ(file.distance.desired, code.distance.desired);
  EXPECT_EQ(file.distance.weight, code.distance.weight);
  EXPECT_EQ(file.orientation.desired, code.orientation.desired);
  EXPECT_EQ(file.orientation.weight, code.orientation.weight);
  EXPECT_EQ(file.frame_coherence_weight, code.frame_coherence_weight);
  EXPECT_EQ(file.look_at_hard, code.look_at_hard);
  EXPECT_EQ(file.look_at_weight, code.look_at_weight);
  EXPECT_EQ(file.visible_fraction_weight, code.visible_fraction_weight);
  EXPECT_EQ(file.clearance_radius, code.clearance_radius);
  EXPECT_EQ(file.clearance_hard, code.clearance_hard);
  EXPECT_EQ(file.clearance_weight, code.clearance_weight);
  EXPECT_EQ(file.search_half_size, code.search_half_size);
  EXPECT_EQ(file.enclosed, code.enclosed);
  EXPECT_EQ(file.semi_enclosed, code.semi_enclosed);
  // "default" is the project's best camera; the thesis' camera is also called "thesis".
  EXPECT_EQ(preset_profile("default").name, "anticipating");
  EXPECT_EQ(preset_profile("thesis").name, "thesis-default");
}

TEST(CameraProfile, AProfileOverridesOnlyWhatItWrites) {
  const CameraProfile p = parse(R"(name: mine
base: close-follow
height: {weight: 3}
areas:
  enclosed: {distance_fraction: 0.2}
)");
  const CameraProfile close = preset_profile("close-follow");
  EXPECT_EQ(p.name, "mine");
  EXPECT_EQ(p.height.desired, close.height.desired);  // kept
  EXPECT_EQ(p.height.weight, 3);                       // replaced
  EXPECT_EQ(p.distance.desired, close.distance.desired);
  // An area entry replaces the base's entry for that kind as a whole.
  EXPECT_FALSE(p.enclosed.ceiling_margin);
  EXPECT_EQ(p.enclosed.distance_fraction, 0.2);
  EXPECT_EQ(p.semi_enclosed, close.semi_enclosed);
}

TEST(CameraProfile, ExtrasAreKeptWithTheirLocations) {
  const CameraProfile p = parse(R"(name: with-extra
extras:
  - {kind: expression, scope: [cam_y], formula: "2 - cam_y"}
)");
  ASSERT_EQ(p.extras.size(), 1u);
  EXPECT_EQ(p.extras[0].where().line, 3);
}

struct BadProfile {
  const char* name;
  const char* text;
  int line;
  const char* message;
};
void PrintTo(const BadProfile& bad, std::ostream* os) { *os << bad.name; }

class CameraProfileErrors : public ::testing::TestWithParam<BadProfile> {};

TEST_P(CameraProfileErrors, NameTheLineAndWhatWasExpected) {
  const BadProfile& bad = GetParam();
  try {
    parse(bad.text);
    FAIL() << "accepted: " << bad.text;
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().line, bad.line) << e.what();
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CameraProfileErrors,
    ::testing::Values(
        BadProfile{"UnknownField", "name: p\nhieght: {desired: 2}\n", 2, "unknown field 'hieght'"},
        BadProfile{"NegativeWeight", "name: p\ndistance: {weight: -1}\n", 2, ">= 0"},
        BadProfile{"NegativeDistance", "name: p\ndistance: {desired: -3}\n", 2, "[0, 1e+06]"},
        BadProfile{"OrientationAbove180", "name: p\norientation: {desired: 270}\n", 2,
                   "[0, 180]"},
        BadProfile{"ZeroSearchBox", "name: p\nsearch: {half_size: 0}\n", 2, "> 0"},
        BadProfile{"FractionAboveOne",
                   "name: p\nareas:\n  enclosed: {distance_fraction: 1.5}\n", 3, "(0, 1]"},
        BadProfile{"UnknownAreaKind", "name: p\nareas:\n  open: {distance_fraction: 0.5}\n", 3,
                   "unknown field 'open'"},
        BadProfile{"HardNotABoolean", "name: p\nclearance: {hard: maybe}\n", 2, "true or false"},
        BadProfile{"UnknownBase", "name: p\nbase: fancy\n", 2, "unknown camera profile 'fancy'"},
        BadProfile{"ExtraNotAMapping", "name: p\nextras:\n  - cam_y > 1\n", 3,
                   "expected a constraint entry"},
        BadProfile{"NotAMapping", "- 1\n- 2\n", 1, "expected a camera profile"}),
    [](const ::testing::TestParamInfo<BadProfile>& info) { return info.param.name; });

// A scene with an enclosed room (ceiling 2.8 m, 6 m x 10 m), a courtyard right next to it
// and a small alcove inside the room.
Scene areas_scene() {
  std::vector<Area> areas = {
      {"room", AreaKind::kEnclosed, {{0, 0, 0}, {6, 2.8, 10}}, {}},
      {"courtyard", AreaKind::kSemiEnclosed, {{6, 0, 0}, {20, 4, 10}}, {}},
      {"alcove", AreaKind::kEnclosed, {{0, 0, 8}, {2, 2.2, 10}}, {}},
  };
  return Scene("areas", {}, std::move(areas), {}, Trajectory({{0, {-5, 0, 5}, 90}}));
}

TEST(AreaProfileSwitch, AdaptsOnEnteringAndRestoresOnLeaving) {
  const Scene scene = areas_scene();
  const CameraProfile profile;  // thesis-default: 2.5 m up, 4 m back
  const SceneAtTime at(scene);
  AreaProfileSwitch areas(at, profile);

  AreaTransition t = areas.update({-5, 0, 5});  // outside
  EXPECT_FALSE(t.changed());
  EXPECT_FALSE(areas.current().area);
  EXPECT_EQ(areas.current().desired_height, 2.5);
  EXPECT_EQ(areas.current().desired_distance, 4.0);

  t = areas.update({3, 0, 5});  // into the room
  EXPECT_FALSE(t.left);
  ASSERT_TRUE(t.entered);
  EXPECT_EQ(*t.entered, 0u);
  // height: min(2.5, 2.8 - 0.5 - 0) = 2.3; distance: min(4, 0.35 x min(6, 10)) = 2.1.
  EXPECT_DOUBLE_EQ(areas.current().desired_height, 2.3);
  EXPECT_DOUBLE_EQ(areas.current().desired_distance, 2.1);
  EXPECT_EQ(areas.current().desired_orientation, 0.0);  // never adapted

  t = areas.update({3, 0.5, 6});  // still in the room, on a step: the ceiling is nearer
  EXPECT_FALSE(t.changed());
  EXPECT_DOUBLE_EQ(areas.current().desired_height, 1.8);

  t = areas.update({-1, 0, 5});  // out again
  ASSERT_TRUE(t.left);
  EXPECT_EQ(*t.left, 0u);
  EXPECT_FALSE(t.entered);
  EXPECT_EQ(areas.current().desired_height, 2.5);
  EXPECT_EQ(areas.current().desired_distance, 4.0);
}

TEST(AreaProfileSwitch, StepsStraightFromOneAreaIntoTheNext) {
  const Scene scene = areas_scene();
  const CameraProfile profile;
  const SceneAtTime at(scene);
  AreaProfileSwitch areas(at, profile);
  areas.update({3, 0, 5});
  const AreaTransition t = areas.update({10, 0, 5});
  ASSERT_TRUE(t.left && t.entered);
  EXPECT_EQ(*t.left, 0u);
  EXPECT_EQ(*t.entered, 1u);
  // The courtyard: a high ceiling leaves the height alone (4 - 0.5 > 2.5); distance
  // min(4, 0.5 x min(14, 10)) = 4.
  EXPECT_EQ(areas.current().desired_height, 2.5);
  EXPECT_EQ(areas.current().desired_distance, 4.0);
}

TEST(AreaProfileSwitch, TheInnermostAreaWins) {
  const Scene scene = areas_scene();
  const CameraProfile profile;
  const SceneAtTime at(scene);
  AreaProfileSwitch areas(at, profile);
  areas.update({3, 0, 5});
  const AreaTransition t = areas.update({1, 0, 9});  // the alcove, inside the room
  ASSERT_TRUE(t.entered);
  EXPECT_EQ(*t.entered, 2u);
  EXPECT_DOUBLE_EQ(areas.current().desired_height, 1.7);    // 2.2 - 0.5
  EXPECT_DOUBLE_EQ(areas.current().desired_distance, 0.7);  // 0.35 x 2
}

TEST(AreaProfileSwitch, AnAreaKindWithoutAdaptationChangesNothing) {
  const Scene scene = areas_scene();
  CameraProfile profile;
  profile.enclosed = {};
  const SceneAtTime at(scene);
  AreaProfileSwitch areas(at, profile);
  const AreaTransition t = areas.update({3, 0, 5});
  EXPECT_TRUE(t.entered);  // transitions are still reported
  EXPECT_EQ(areas.current().desired_height, 2.5);
  EXPECT_EQ(areas.current().desired_distance, 4.0);
}

}  // namespace
}  // namespace sightline::camera
