// The pose file reader (pose_reading.h): what `compose` writes reads back exactly; what
// FORMATS.md allows (more fields, any order, any spacing) is read; the rest is refused with
// the file, line and what was expected.
#include <gtest/gtest.h>

#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/pose_file.h"
#include "sightline/domains/camera/composition/pose_reading.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

const Scene& two_people() {
  static const Scene scene = parse_scene(csp::parse_yaml(
      "name: two\n"
      "actors:\n"
      "  - {name: ann, trajectory: [{t: 0, position: [0, 0, 0], yaw: 0}]}\n"
      "  - {name: bob, trajectory: [{t: 0, position: [1.5, 0, 0], yaw: 270}]}\n"
      "shot:\n"
      "  region: {min: [-10, 0.5, -10], max: [10, 8, 10]}\n"
      "  properties:\n"
      "    - {kind: visible, target: ann}\n"
      "    - {kind: framed, target: bob, rect: [0.1, 0.1, 0.9, 0.9]}\n",
      "two.yaml"));
  return scene;
}

// The error's message and line, or "" and -1 when the text is read.
std::pair<std::string, int> refusal(const std::string& text) {
  try {
    parse_pose_json(text, "pose.json");
  } catch (const csp::InputError& e) {
    return {e.what(), e.where().line};
  }
  return {"", -1};
}

TEST(PoseReading, WhatComposeWritesReadsBackExactly) {
  const Scene& scene = two_people();
  const CompositionProblem problem(scene, *scene.shot(), 0);
  CameraPose pose;
  pose.position = Eigen::Vector3d(0.1234567890123, 1.7, -4.000000000001);
  pose.look_at = Eigen::Vector3d(0.75, 1.55, 1.0 / 3.0);
  pose.roll = -2.5;
  pose.fov = 43.21;
  pose.aspect = 16.0 / 9.0;
  const std::string text = pose_json(pose, problem, problem.evaluate(pose), {0, "test", 0.001});
  const CameraPose back = parse_pose_json(text, "pose.json");
  EXPECT_EQ(back.position, pose.position);
  EXPECT_EQ(back.look_at, pose.look_at);
  EXPECT_EQ(back.roll, pose.roll);
  EXPECT_EQ(back.fov, pose.fov);
  EXPECT_EQ(back.aspect, pose.aspect);
  // And it is judged the same.
  EXPECT_EQ(problem.evaluate(back).satisfaction, problem.evaluate(pose).satisfaction);
}

TEST(PoseReading, ReadsAnyOrderAnySpacingAndIgnoresOtherFields) {
  const CameraPose p = parse_pose_json(
      "{\"fov\":60,\"aspect\":1.5,\"note\":{\"by\":\"another tool\",\"position\":[1]},\n"
      "\t\"roll\" : 10 , \"look_at\":[1,2,3],\"position\":[4e0,5,-6.5]}",
      "pose.json");
  EXPECT_EQ(p.position, Eigen::Vector3d(4, 5, -6.5));
  EXPECT_EQ(p.look_at, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(p.roll, 10);
  EXPECT_EQ(p.fov, 60);
  EXPECT_EQ(p.aspect, 1.5);
}

TEST(PoseReading, RefusesWhatIsNotAPoseNamingTheLine) {
  const std::string good_tail = "\"roll\": 0,\n\"fov\": 50,\n\"aspect\": 1.5\n}";
  auto with = [&](const std::string& position, const std::string& look_at) {
    return "{\n\"position\": " + position + ",\n\"look_at\": " + look_at + ",\n" + good_tail;
  };
  EXPECT_EQ(refusal(with("[0, 1, 0]", "[0, 1, 5]")).second, -1);  // the good one reads

  auto [message, line] = refusal(with("[0, 1]", "[0, 1, 5]"));
  EXPECT_EQ(line, 2);
  EXPECT_NE(message.find("position: expected a point [x, y, z]"), std::string::npos) << message;
  std::tie(message, line) = refusal(with("[0, 1, 0]", "[0, \"one\", 5]"));
  EXPECT_EQ(line, 3);
  EXPECT_NE(message.find("look_at"), std::string::npos) << message;
  // The look-at point at the position, or straight below it: no view.
  std::tie(message, line) = refusal(with("[0, 1, 0]", "[0, 1, 0]"));
  EXPECT_NE(message.find("not a view"), std::string::npos) << message;
  std::tie(message, line) = refusal(with("[0, 5, 0]", "[0, 1, 0]"));
  EXPECT_NE(message.find("not a view"), std::string::npos) << message;

  const std::string pose = "{\"position\": [0, 1, 0], \"look_at\": [0, 1, 5], ";
  std::tie(message, line) = refusal(pose + "\"roll\": 0, \"fov\": 0, \"aspect\": 1.5}");
  EXPECT_NE(message.find("fov: expected degrees in (0, 180)"), std::string::npos) << message;
  std::tie(message, line) = refusal(pose + "\"roll\": 0, \"fov\": 180, \"aspect\": 1.5}");
  EXPECT_NE(message.find("fov"), std::string::npos) << message;
  std::tie(message, line) = refusal(pose + "\"roll\": 0, \"fov\": 50, \"aspect\": 0}");
  EXPECT_NE(message.find("aspect: expected"), std::string::npos) << message;
  std::tie(message, line) = refusal(pose + "\"roll\": \"level\", \"fov\": 50, \"aspect\": 1}");
  EXPECT_NE(message.find("roll: expected a roll in degrees"), std::string::npos) << message;
  std::tie(message, line) = refusal(pose + "\"fov\": 50, \"aspect\": 1}");
  EXPECT_NE(message.find("missing \"roll\""), std::string::npos) << message;
  std::tie(message, line) = refusal(pose + "\"roll\": 0, \"roll\": 1, \"fov\": 50, \"aspect\": 1}");
  EXPECT_NE(message.find("key 'roll' is given twice"), std::string::npos) << message;
  // Not JSON, with the position where it stops being JSON; not an object; a number too
  // big for a double.
  std::tie(message, line) = refusal("{\n\"position\": [0, 1, 0],\n\"look_at\": [0, 1, 5,\n}");
  EXPECT_EQ(line, 4);
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
  std::tie(message, line) = refusal("[0, 1, 2]");
  EXPECT_NE(message.find("expected a JSON object"), std::string::npos) << message;
  std::tie(message, line) = refusal(pose + "\"roll\": 1e999, \"fov\": 50, \"aspect\": 1}");
  EXPECT_NE(message.find("pose.json:1:"), std::string::npos) << message;
  EXPECT_NE(message.find("too large for a double"), std::string::npos) << message;
  std::tie(message, line) = refusal("");
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
}

TEST(PoseReading, AMissingFileIsAnInputErrorNamingIt) {
  try {
    read_pose_file("/nonexistent/pose.json");
    FAIL() << "read a file that does not exist";
  } catch (const csp::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/pose.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sightline::camera
