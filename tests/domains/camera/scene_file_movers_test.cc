// Scene files' `movers:` block (FORMATS.md): what a well-formed block gives, read back exactly,
// and that every kind of bad mover is an InputError naming the line and what was expected.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

Scene parse(const std::string& text) {
  return parse_scene(csp::parse_yaml(text, "scene.yaml"), "");
}

const char* kTrajectory = "trajectory:\n  - {t: 0, position: [0, 0, 0], yaw: 0}\n";

// "name: x\nmovers:\n" + the block + a trajectory: the block starts on line 3.
std::string with_movers(const std::string& block) {
  return "name: x\nmovers:\n" + block + kTrajectory;
}

// The movers example of FORMATS.md, verbatim, in a scene.
const char* kFormatsMovers = R"(name: crossing
movers:                               # optional: solid boxes that move (doors, people, vehicles)
  - name: passer-by                   # optional label
    size: [0.6, 1.8, 0.6]             # box extents along x, y, z; origin at the centre of its base
    path:                             # keyframes, interpolated linearly; before the first and after
      - {t: 2.0, position: [-6, 0, 1]}    # the last keyframe the mover stays where they put it
      - {t: 6.0, position: [6, 0, 1]}

trajectory:
  - {t: 0.0, position: [0, 0, -3], yaw: 0}
  - {t: 4.0, position: [0, 0, 3], yaw: 0}
)";

TEST(SceneFileMovers, ReadsTheFormatsExample) {
  const Scene s = parse(kFormatsMovers);
  ASSERT_EQ(s.movers().size(), 1u);
  const Mover& m = s.movers()[0];
  EXPECT_EQ(m.name(), "passer-by");
  EXPECT_EQ(m.size(), Eigen::Vector3d(0.6, 1.8, 0.6));
  ASSERT_EQ(m.path().size(), 2u);
  EXPECT_EQ(m.path()[0].t, 2.0);
  EXPECT_EQ(m.path()[0].position, Eigen::Vector3d(-6, 0, 1));
  EXPECT_EQ(m.path()[1].t, 6.0);
  EXPECT_EQ(m.path()[1].position, Eigen::Vector3d(6, 0, 1));
  EXPECT_EQ(m.where().file, "scene.yaml");
  EXPECT_EQ(m.where().line, 3);
  // Halfway along its path at t = 4 the passer-by stands at x = 0, across the walk.
  const Aabb box = m.box_at(4.0);
  EXPECT_NEAR((box.min - Eigen::Vector3d(-0.3, 0, 0.7)).norm(), 0, 1e-12);
  EXPECT_NEAR((box.max - Eigen::Vector3d(0.3, 1.8, 1.3)).norm(), 0, 1e-12);
}

TEST(SceneFileMovers, AbsentOrEmptyBlockMeansNoMovers) {
  EXPECT_TRUE(parse(std::string("name: x\n") + kTrajectory).movers().empty());
  EXPECT_TRUE(parse(std::string("name: x\nmovers:\n") + kTrajectory).movers().empty());
  EXPECT_TRUE(parse(std::string("name: x\nmovers: []\n") + kTrajectory).movers().empty());
}

// FORMATS allows: no name, a repeated name, one keyframe (a mover standing still), negative
// times, and a mover crossing the character (movers are never checked against it).
TEST(SceneFileMovers, AcceptsEverythingFormatsAllows) {
  const Scene s = parse(with_movers(
      "  - {size: [1, 2, 3], path: [{t: 0, position: [5, 0, 5]}]}\n"
      "  - {name: car, size: [4, 1.5, 2], path: [{t: -2, position: [0, 0, -3]}, "
      "{t: 1, position: [0, 0, 3]}]}\n"
      "  - {name: car, size: [4, 1.5, 2], path: [{t: 0, position: [9, 0, 9]}, "
      "{t: 0.5, position: [9, 0, 9]}, {t: 7, position: [-9, 0, 9]}]}\n"));
  ASSERT_EQ(s.movers().size(), 3u);
  EXPECT_EQ(s.movers()[0].name(), "");
  EXPECT_EQ(s.movers()[0].path().size(), 1u);
  EXPECT_EQ(s.movers()[0].position_at(-100), Eigen::Vector3d(5, 0, 5));
  EXPECT_EQ(s.movers()[0].position_at(100), Eigen::Vector3d(5, 0, 5));
  EXPECT_EQ(s.movers()[1].name(), "car");
  EXPECT_EQ(s.movers()[2].name(), "car");
  EXPECT_EQ(s.movers()[1].path()[0].t, -2);
  EXPECT_EQ(s.movers()[2].path().size(), 3u);
  EXPECT_EQ(s.movers()[2].where().line, 5);
}

std::string exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// Random well-formed blocks, written with every digit, read back bit for bit.
TEST(SceneFileMovers, RandomBlocksReadBackExactly) {
  std::mt19937 rng(1313);
  std::uniform_real_distribution<double> coord(-50, 50), extent(0.01, 10), step(1e-3, 5);
  std::uniform_int_distribution<int> count(0, 6), keys(1, 5);
  for (int round = 0; round < 40; ++round) {
    std::vector<Mover> written;
    std::string block;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d size(extent(rng), extent(rng), extent(rng));
      std::vector<MoverKeyframe> path;
      double t = coord(rng);
      for (int k = keys(rng); k > 0; --k) {
        path.push_back({t, Eigen::Vector3d(coord(rng), coord(rng), coord(rng))});
        t += step(rng);
      }
      const std::string name = i % 3 == 0 ? "" : "m" + std::to_string(i % 2);
      block += "  - ";
      if (!name.empty()) block += "name: " + name + "\n    ";
      block += "size: [" + exact(size.x()) + ", " + exact(size.y()) + ", " + exact(size.z()) +
               "]\n    path:\n";
      for (const MoverKeyframe& k : path) {
        block += "      - {t: " + exact(k.t) + ", position: [" + exact(k.position.x()) + ", " +
                 exact(k.position.y()) + ", " + exact(k.position.z()) + "]}\n";
      }
      written.emplace_back(name, size, path);
    }
    const Scene s = parse(with_movers(block));
    ASSERT_EQ(s.movers().size(), written.size()) << block;
    for (std::size_t i = 0; i < written.size(); ++i) {
      const Mover& got = s.movers()[i];
      EXPECT_EQ(got.name(), written[i].name());
      EXPECT_EQ(got.size(), written[i].size());
      ASSERT_EQ(got.path().size(), written[i].path().size());
      for (std::size_t k = 0; k < got.path().size(); ++k) {
        EXPECT_EQ(got.path()[k].t, written[i].path()[k].t);
        EXPECT_EQ(got.path()[k].position, written[i].path()[k].position);
      }
    }
  }
}

struct BadMovers {
  const char* name;
  std::string text;
  int line;             // expected line of the error
  const char* message;  // expected part of the message
};

void PrintTo(const BadMovers& bad, std::ostream* os) { *os << bad.name; }

class SceneFileMoverErrors : public ::testing::TestWithParam<BadMovers> {};

TEST_P(SceneFileMoverErrors, NameTheLineAndWhatWasExpected) {
  const BadMovers& bad = GetParam();
  try {
    parse(bad.text);
    FAIL() << "accepted: " << bad.text;
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().file, "scene.yaml");
    EXPECT_EQ(e.where().line, bad.line) << e.what();
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.what();
  }
}

// A block-style mover named a: name on line 3, size on 4, path on 5, keyframes from 6.
std::string mover_a(const std::string& size, const std::string& keyframes) {
  return with_movers("  - name: a\n    size: " + size + "\n    path:\n" + keyframes);
}
const char* kStill = "      - {t: 0, position: [0, 0, 0]}\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneFileMoverErrors,
    ::testing::Values(
        BadMovers{"NotAList", "name: x\nmovers: {size: [1, 1, 1]}\n" + std::string(kTrajectory),
                  2, "expected a list of movers"},
        BadMovers{"EntryNotAMapping", with_movers("  - 3\n"), 3, "expected a mover"},
        BadMovers{"UnknownField",
                  with_movers("  - {size: [1, 1, 1], colour: red, path: [{t: 0, position: [0, 0, 0]}]}\n"),
                  3, "unknown field 'colour'"},
        BadMovers{"NameNotAString", with_movers("  - {name: [a], size: [1, 1, 1], path: []}\n"), 3,
                  "a mover name"},
        BadMovers{"MissingSize", with_movers("  - name: a\n    path:\n" + std::string(kStill)), 3,
                  "missing required field 'size'"},
        BadMovers{"SizeZero", mover_a("[1, 0, 1]", kStill), 4,
                  "the size of mover 'a' as 3 numbers > 0, but on y it is 0"},
        BadMovers{"SizeNegative", mover_a("[-1, 1, 1]", kStill), 4, "on x it is -1"},
        BadMovers{"SizeNaN", mover_a("[1, nan, 1]", kStill), 4, "finite"},
        BadMovers{"SizeInfinite", mover_a("[1, 1, inf]", kStill), 4, "finite"},
        BadMovers{"SizeNotANumber", mover_a("[1, big, 1]", kStill), 4,
                  "y of the size of mover 'a'"},
        BadMovers{"SizeTwoNumbers", mover_a("[1, 1]", kStill), 4,
                  "the size of mover 'a' as [x, y, z] (3 numbers), got [1, 1]"},
        BadMovers{"SizeFourNumbers", mover_a("[1, 1, 1, 1]", kStill), 4, "got [1, 1, 1, 1]"},
        BadMovers{"SizeNotAList", mover_a("2", kStill), 4, "the size of mover 'a' as [x, y, z]"},
        BadMovers{"UnnamedMoverIsNumbered",
                  with_movers("  - {size: [1, 1, 1], path: [{t: 0, position: [0, 0, 0]}]}\n"
                              "  - {size: [1, 0, 1], path: [{t: 0, position: [0, 0, 0]}]}\n"),
                  4, "mover #2"},
        BadMovers{"MissingPath", with_movers("  - {name: a, size: [1, 1, 1]}\n"), 3,
                  "missing required field 'path'"},
        BadMovers{"EmptyPath", with_movers("  - {name: a, size: [1, 1, 1], path: []}\n"), 3,
                  "at least one keyframe in the path of mover 'a'"},
        BadMovers{"PathWithNothingAfterIt", mover_a("[1, 1, 1]", ""), 3,
                  "at least one keyframe in the path of mover 'a'"},
        BadMovers{"PathNotAList",
                  with_movers("  - name: a\n    size: [1, 1, 1]\n    path: {t: 0, position: [0, 0, 0]}\n"),
                  5, "the path of mover 'a' as a list of keyframes"},
        BadMovers{"KeyframeNotAMapping", mover_a("[1, 1, 1]", "      - [0, 0, 0]\n"), 6,
                  "keyframe #1 of mover 'a' as {t: s, position: [x, y, z]}"},
        BadMovers{"KeyframeMissingT", mover_a("[1, 1, 1]", "      - {position: [0, 0, 0]}\n"), 6,
                  "missing required field 't'"},
        BadMovers{"KeyframeMissingPosition",
                  mover_a("[1, 1, 1]", std::string(kStill) + "      - {t: 1}\n"), 7,
                  "missing required field 'position'"},
        BadMovers{"KeyframeUnknownField",
                  mover_a("[1, 1, 1]", "      - {t: 0, position: [0, 0, 0], yaw: 90}\n"), 6,
                  "unknown field 'yaw'"},
        BadMovers{"KeyframeTimeNaN", mover_a("[1, 1, 1]", "      - {t: nan, position: [0, 0, 0]}\n"),
                  6, "the time of keyframe #1 of mover 'a' (seconds) (a finite number)"},
        BadMovers{"KeyframeTimeNotANumber",
                  mover_a("[1, 1, 1]", "      - {t: soon, position: [0, 0, 0]}\n"), 6,
                  "the time of keyframe #1 of mover 'a'"},
        BadMovers{"KeyframePositionInfinite",
                  mover_a("[1, 1, 1]", "      - {t: 0, position: [0, -inf, 0]}\n"), 6, "finite"},
        BadMovers{"KeyframePositionTwoNumbers",
                  mover_a("[1, 1, 1]", "      - {t: 0, position: [0, 0]}\n"), 6,
                  "the position of keyframe #1 of mover 'a' as [x, y, z] (3 numbers)"},
        BadMovers{"TimesEqual",
                  mover_a("[1, 1, 1]", std::string(kStill) + "      - {t: 0, position: [1, 0, 0]}\n"),
                  7,
                  "keyframe times of mover 'a' to increase strictly: keyframe #2 (line 7) has "
                  "t = 0 but keyframe #1 (line 6) has t = 0"},
        BadMovers{"TimesDecreasing",
                  mover_a("[1, 1, 1]", "      - {t: 0, position: [0, 0, 0]}\n"
                                       "      - {t: 2, position: [1, 0, 0]}\n"
                                       "      - {t: 1.5, position: [2, 0, 0]}\n"),
                  8, "keyframe #3 (line 8) has t = 1.5 but keyframe #2 (line 7) has t = 2"}),
    [](const ::testing::TestParamInfo<BadMovers>& info) { return info.param.name; });

}  // namespace
}  // namespace sightline::camera
