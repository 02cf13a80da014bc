// Scene files: what a valid file gives, and that every kind of bad input is an InputError
// naming the right line and saying what was expected.
#include "sightline/domains/camera/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sightline/csp/files/yaml_spec.h"

namespace sightline::camera {
namespace {

// The example of FORMATS.md, verbatim.
const char* kFormatsExample = R"(name: crammed-doorway                 # required
description: two rooms joined by a narrow door   # optional
frame_rate: 60                        # optional, frames per second of the simulation (default 60)

character:                            # optional block, defaults shown
  size: [0.6, 1.8, 0.6]               # box extents along x, y, z; its origin is the centre of its feet
  look_at_height: 1.5                 # the point the camera aims at, this high above the feet

boxes:                                # solid, static, axis-aligned geometry
  - {name: north-wall, min: [-5, 0, 4.8], max: [5, 3, 5]}
  - {min: [2, 0, 2], max: [3, 3, 3]}  # name is optional

areas:                                # optional semantic volumes the camera reacts to
  - {name: room-a, kind: enclosed, min: [-5, 0, -5], max: [5, 3, 5]}   # kind: enclosed | semi-enclosed

trajectory:                           # required: the character's path as keyframes
  - {t: 0.0, position: [0, 0, -3], yaw: 0}
  - {t: 4.0, position: [0, 0, 3], yaw: 0}
  - {t: 6.0, position: [0, 0, 3], yaw: 180}   # turning on the spot is a keyframe pair

camera:                               # optional
  start: [0, 2.5, -7]                 # initial camera position (default: the profile's ideal spot)
  profile: default                    # a preset name, or an inline profile mapping
)";

Scene parse(const std::string& text, const std::string& dir = "") {
  return parse_scene(csp::parse_yaml(text, "scene.yaml"), dir);
}

TEST(SceneFile, ReadsTheFormatsExample) {
  const Scene s = parse(kFormatsExample);
  EXPECT_EQ(s.name(), "crammed-doorway");
  EXPECT_EQ(s.description(), "two rooms joined by a narrow door");
  EXPECT_EQ(s.frame_rate(), 60);
  ASSERT_EQ(s.solids().size(), 2u);
  EXPECT_EQ(s.solids()[0].name, "north-wall");
  EXPECT_EQ(s.solids()[0].where.line, 10);
  EXPECT_EQ(s.solids()[1].name, "");
  EXPECT_EQ(s.solids()[1].box.max, Eigen::Vector3d(3, 3, 3));
  ASSERT_EQ(s.areas().size(), 1u);
  EXPECT_EQ(s.areas()[0].kind, AreaKind::kEnclosed);
  EXPECT_EQ(s.trajectory().keyframes().size(), 3u);
  EXPECT_EQ(s.frame_count(), 361u);  // 6 s at 60 frames per second, both ends
  EXPECT_EQ(s.character().size, Eigen::Vector3d(0.6, 1.8, 0.6));
  ASSERT_TRUE(s.camera_start());
  EXPECT_EQ(*s.camera_start(), Eigen::Vector3d(0, 2.5, -7));
  // FORMATS.md's example says `profile: default`: the project's best camera.
  EXPECT_EQ(s.profile().name, "anticipating");
  EXPECT_EQ(s.profile_source(), "preset anticipating");
}

TEST(SceneFile, DefaultsApplyWhenOptionalBlocksAreAbsent) {
  const Scene s = parse("name: bare\ntrajectory:\n  - {t: 0, position: [0, 0, 0], yaw: 90}\n");
  EXPECT_EQ(s.frame_rate(), 60);
  EXPECT_TRUE(s.solids().empty());
  EXPECT_EQ(s.frame_count(), 1u);
  EXPECT_DOUBLE_EQ(s.character().look_at_height, 1.5);
  EXPECT_FALSE(s.camera_start());
  // Without camera.profile: the default camera (anticipating), whose ideal spot is 4 m
  // behind (facing +x, so at x = -4), 2.5 m up.
  EXPECT_EQ(s.profile().name, "anticipating");
  EXPECT_EQ(s.profile_source(), "preset anticipating");
  EXPECT_NEAR((s.start_camera_position() - Eigen::Vector3d(-4, 2.5, 0)).norm(), 0, 1e-12);
}

TEST(SceneFile, StandingOnTheFloorAndLeaningOnAWallAreAllowed) {
  const Scene s = parse(R"(name: touching
boxes:
  - {name: floor, min: [-5, -1, -5], max: [5, 0, 5]}
  - {name: wall, min: [0.3, 0, -5], max: [1, 3, 5]}
trajectory:
  - {t: 0, position: [0, 0, 0], yaw: 0}
  - {t: 1, position: [0, 0, 2], yaw: 0}
)");
  EXPECT_EQ(s.solids().size(), 2u);
}

struct BadScene {
  const char* name;
  std::string text;
  int line;             // expected line of the error
  const char* message;  // expected part of the message
};

void PrintTo(const BadScene& bad, std::ostream* os) { *os << bad.name; }

std::string with_trajectory(const std::string& head) {
  return head + "trajectory:\n  - {t: 0, position: [0, 0, 0], yaw: 0}\n";
}

class SceneFileErrors : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneFileErrors, NameTheLineAndWhatWasExpected) {
  const BadScene& bad = GetParam();
  try {
    parse(bad.text);
    FAIL() << "accepted: " << bad.text;
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().file, "scene.yaml");
    EXPECT_EQ(e.where().line, bad.line) << e.what();
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneFileErrors,
    ::testing::Values(
        BadScene{"UnknownTopLevelField", with_trajectory("name: x\nframe_rat: 30\n"), 2,
                 "unknown field 'frame_rat'"},
        BadScene{"MissingName", with_trajectory("description: no name\n"), 1,
                 "missing required field 'name'"},
        BadScene{"MissingTrajectory", "name: x\n", 1, "missing required field 'trajectory'"},
        BadScene{"EmptyTrajectory", "name: x\ntrajectory: []\n", 2, "at least one keyframe"},
        BadScene{"FrameRateZero", with_trajectory("name: x\nframe_rate: 0\n"), 2, "> 0"},
        BadScene{"FrameRateNotANumber", with_trajectory("name: x\nframe_rate: fast\n"), 2,
                 "the frame rate"},
        BadScene{"BoxWithMinNotBelowMax",
                 with_trajectory("name: x\nboxes:\n  - {name: w, min: [0, 0, 0], max: [1, 0, 1]}\n"),
                 3, "on y min is 0 and max is 0"},
        BadScene{"BoxCornerWithTwoNumbers",
                 with_trajectory("name: x\nboxes:\n  - {min: [0, 0], max: [1, 1, 1]}\n"), 3,
                 "[x, y, z] (3 numbers)"},
        BadScene{"BoxCornerNotFinite",
                 with_trajectory("name: x\nboxes:\n  - {min: [0, nan, 0], max: [1, 1, 1]}\n"), 3,
                 "finite"},
        BadScene{"BoxUnknownField",
                 with_trajectory("name: x\nboxes:\n  - {min: [0, 0, 0], max: [1, 1, 1], colour: red}\n"),
                 3, "unknown field 'colour'"},
        BadScene{"LevelNotAMapping", with_trajectory("name: x\nlevel: [a, b]\n"), 2,
                 "expected a level"},
        BadScene{"LevelWithoutFile", with_trajectory("name: x\nlevel: {scale: 1}\n"), 2, "file"},
        BadScene{"LevelFileMissing",
                 with_trajectory("name: x\nlevel: {file: /nonexistent/level.obj}\n"), 2,
                 "/nonexistent/level.obj"},
        BadScene{"LevelBadUpAxis",
                 with_trajectory("name: x\nlevel: {file: a.obj, up: x}\n"), 2, "y or z"},
        BadScene{"LevelBadScale",
                 with_trajectory("name: x\nlevel: {file: a.obj, scale: -1}\n"), 2, "scale"},
        BadScene{"LevelUnknownField",
                 with_trajectory("name: x\nlevel: {file: a.obj, colour: red}\n"), 2,
                 "unknown field 'colour'"},
        BadScene{"UnknownAreaKind",
                 with_trajectory("name: x\nareas:\n  - {name: r, kind: open, min: [0, 0, 0], max: [1, 1, 1]}\n"),
                 3, "enclosed or semi-enclosed"},
        BadScene{"KeyframeTimesNotIncreasing",
                 "name: x\ntrajectory:\n  - {t: 1, position: [0, 0, 0], yaw: 0}\n"
                 "  - {t: 1, position: [0, 0, 1], yaw: 0}\n",
                 4, "keyframe times to increase"},
        BadScene{"KeyframeWithoutYaw", "name: x\ntrajectory:\n  - {t: 0, position: [0, 0, 0]}\n",
                 3, "missing required field 'yaw'"},
        BadScene{"CharacterSizeNotPositive",
                 with_trajectory("name: x\ncharacter:\n  size: [0.6, -1, 0.6]\n"), 3, "> 0"},
        BadScene{"LookAtAboveTheHead",
                 with_trajectory("name: x\ncharacter:\n  look_at_height: 2.5\n"), 3,
                 "at most the character's height"},
        BadScene{"UnknownProfile", with_trajectory("name: x\ncamera:\n  profile: fancy\n"), 3,
                 "unknown camera profile 'fancy' (presets: anticipating, anticipating-path, close-follow, high-follow, thesis-default"},
        BadScene{"BadInlineProfileField",
                 with_trajectory("name: x\ncamera:\n  profile:\n    height: {desired: 2, wieght: 1}\n"),
                 4, "unknown field 'wieght'"},
        BadScene{"ProfileOrientationOutOfRange",
                 with_trajectory("name: x\ncamera:\n  profile:\n    orientation: {desired: 200}\n"),
                 4, "[0, 180]"},
        BadScene{"ExtraOfUnknownKind",
                 with_trajectory("name: x\ncamera:\n  profile:\n    extras:\n"
                                 "      - {kind: nonsense, scope: [cam_y]}\n"),
                 5, "unknown constraint kind 'nonsense'"},
        BadScene{"ExtraOverAnUnknownVariable",
                 with_trajectory("name: x\ncamera:\n  profile:\n    extras:\n"
                                 "      - {kind: expression, scope: [cam_w], formula: \"cam_w\"}\n"),
                 5, "unknown variable 'cam_w'"},
        BadScene{"CameraStartInsideABox",
                 with_trajectory("name: x\nboxes:\n  - {name: block, min: [4, 0, 4], max: [6, 3, 6]}\n"
                                 "camera:\n  start: [5, 1, 5]\n"),
                 5, "inside solid box 'block' (line 3)"},
        BadScene{"KeyframeInsideABox",
                 "name: x\nboxes:\n  - {name: pillar, min: [-1, 0, 4], max: [1, 3, 5]}\n"
                 "trajectory:\n  - {t: 0, position: [0, 0, 0], yaw: 0}\n"
                 "  - {t: 2, position: [0, 0, 4.5], yaw: 0}\n",
                 6, "keyframe #2 (t = 2) puts the character's box"},
        BadScene{"PathThroughAWall",
                 "name: x\nboxes:\n  - {name: wall, min: [-5, 0, 2], max: [5, 3, 2.2]}\n"
                 "trajectory:\n  - {t: 0, position: [0, 0, 0], yaw: 0}\n"
                 "  - {t: 2, position: [0, 0, 4], yaw: 0}\n",
                 5, "between keyframe #1 and keyframe #2 the character's box passes through solid box 'wall'"},
        BadScene{"MalformedYaml", "name: x\nboxes: [\n", 3, "malformed YAML"},
        // The alias is the trajectory holding it: a stack overflow in the YAML reader until
        // it bounded the nesting of expanded aliases (fuzz/README.md).
        BadScene{"AliasInsideTheNodeItsAnchorNames", "name: x\ntrajectory: &k\n  - *k\n", 2,
                 "nested more than 1000 deep"}),
    [](const ::testing::TestParamInfo<BadScene>& info) { return info.param.name; });

TEST(SceneFile, ProfileMayBeAFileNextToTheScene) {
  const auto dir = std::filesystem::temp_directory_path() / "sightline_scene_file_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "low.yaml") << "name: low\nheight: {desired: 1.2}\n";
  const Scene s = parse(with_trajectory("name: x\ncamera:\n  profile: low.yaml\n"), dir.string());
  EXPECT_EQ(s.profile().name, "low");
  EXPECT_DOUBLE_EQ(s.profile().height.desired, 1.2);
  EXPECT_DOUBLE_EQ(s.profile().distance.desired, 4.0);  // the rest from thesis-default
  EXPECT_EQ(s.profile_source(), "file " + (dir / "low.yaml").string());
  EXPECT_THROW(parse(with_trajectory("name: x\ncamera:\n  profile: missing.yaml\n"), dir.string()),
               csp::InputError);
  std::filesystem::remove_all(dir);
}

TEST(SceneFile, ErrorsInAProfileFileNameThatFile) {
  const auto dir = std::filesystem::temp_directory_path() / "sightline_scene_file_test2";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.yaml") << "name: bad\n\ndistance: {desired: -1}\n";
  try {
    parse(with_trajectory("name: x\ncamera:\n  profile: bad.yaml\n"), dir.string());
    FAIL();
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().file, (dir / "bad.yaml").string());
    EXPECT_EQ(e.where().line, 3);
  }
  std::filesystem::remove_all(dir);
}

TEST(SceneFile, UnreadableFileIsAnInputError) {
  EXPECT_THROW(read_scene_file("/nonexistent/scene.yaml"), csp::InputError);
}

// Every scene shipped with the project reads: the examples, the thesis experiments and the
// anticipation scenes (issue 13).
TEST(SceneFile, ShippedScenesAllRead) {
  int read = 0;
  for (const char* folder :
       {"/examples/scenes", "/experiments/scenes", "/experiments/scenes/anticipation"}) {
    const std::filesystem::path dir = std::string(SIGHTLINE_SOURCE_DIR) + folder;
    if (!std::filesystem::exists(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() != ".yaml") continue;
      SCOPED_TRACE(entry.path().string());
      const Scene s = read_scene_file(entry.path().string());
      EXPECT_GT(s.frame_count(), 0u);
      ++read;
    }
  }
  EXPECT_GE(read, 3);
}

}  // namespace
}  // namespace sightline::camera

namespace sightline::camera {
namespace {

// FORMATS.md: names are labels, not keys. Two boxes (the halves of a wall split by a door)
// and two areas may share a name; every box still blocks sight.
TEST(SceneFile, BoxesAndAreasMayShareANameAsFormatsAllows) {
  const Scene s = parse_scene(csp::parse_yaml(
      "name: split-wall\n"
      "boxes:\n"
      "  - {name: wall, min: [-5, 0, 4], max: [-0.5, 3, 4.2]}\n"
      "  - {name: wall, min: [0.5, 0, 4], max: [5, 3, 4.2]}\n"
      "areas:\n"
      "  - {name: room, kind: enclosed, min: [-5, 0, -5], max: [5, 3, 4]}\n"
      "  - {name: room, kind: semi-enclosed, min: [-5, 0, 4.2], max: [5, 3, 9]}\n"
      "trajectory:\n"
      "  - {t: 0, position: [0, 0, 0], yaw: 0}\n"
      "  - {t: 1, position: [0, 0, 1], yaw: 0}\n",
      "scene.yaml"), "");
  ASSERT_EQ(s.solids().size(), 2u);
  EXPECT_EQ(s.solids()[0].name, "wall");
  EXPECT_EQ(s.solids()[1].name, "wall");
  ASSERT_EQ(s.areas().size(), 2u);
  // Both halves block; the door between them does not.
  EXPECT_FALSE(s.line_of_sight({-3, 1, 3}, {-3, 1, 5}));
  EXPECT_FALSE(s.line_of_sight({3, 1, 3}, {3, 1, 5}));
  EXPECT_TRUE(s.line_of_sight({0, 1, 3}, {0, 1, 5}));
}

}  // namespace
}  // namespace sightline::camera
