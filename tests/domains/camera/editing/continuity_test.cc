// The rules of continuity editing as geometry, on cases worked out by hand: the line of
// action from the script, the side of the line, crossing it, and jump cuts.
#include "sightline/domains/camera/editing/continuity.h"

#include <gtest/gtest.h>

namespace sightline::camera {
namespace {

CameraPose looking(Eigen::Vector3d from, Eigen::Vector3d at) {
  CameraPose p;
  p.position = from;
  p.look_at = at;
  return p;
}

ScriptEntry line(double t0, double t1, const char* speaker, const char* to) {
  ScriptEntry e;
  e.t0 = t0;
  e.t1 = t1;
  e.speaker = speaker;
  e.to = to;
  return e;
}

TEST(Continuity, TheLineOfActionIsTheLineUnderWayElseTheLastThatEnded) {
  ScriptEntry action;
  action.t0 = 5;
  action.t1 = 6;
  action.action = "bob";
  const std::vector<ScriptEntry> script = {line(1, 3, "ann", "bob"), line(2.5, 4, "bob", "ann"),
                                           action, line(7, 9, "cat", "ann")};
  EXPECT_FALSE(line_of_action_entry(script, 0.5));  // before the first line
  EXPECT_EQ(*line_of_action_entry(script, 1.0), 0u);
  EXPECT_EQ(*line_of_action_entry(script, 2.7), 1u);  // overlapping: the latest begun
  EXPECT_EQ(*line_of_action_entry(script, 3.0), 1u);  // [t0, t1) half-open: ann's ended
  EXPECT_EQ(*line_of_action_entry(script, 5.5), 1u);  // an action is not a line
  EXPECT_FALSE(line_under_way(script, 5.5));
  EXPECT_EQ(*line_of_action_entry(script, 9.0), 3u);
}

TEST(Continuity, SidesOfTheLineAndCrossingIt) {
  const Eigen::Vector3d ann(-1, 1.5, 0), bob(1, 1.5, 0);  // the line: the x axis
  // ((b - a) x (p - a)).y = dz qx - dx qz = -2 qz: z > 0 is the negative side.
  EXPECT_DOUBLE_EQ(side_of_line({0, 1.5, 3}, ann, bob), -3);
  EXPECT_DOUBLE_EQ(side_of_line({5, 9, -2}, ann, bob), 2);
  EXPECT_DOUBLE_EQ(side_of_line({0, 0, 3}, ann, ann), 0);
  const ContinuityRules rules;
  EXPECT_TRUE(crosses_line({0, 1.5, 3}, {2, 1.5, -3}, ann, bob, rules));
  EXPECT_FALSE(crosses_line({0, 1.5, 3}, {-4, 1.5, 1}, ann, bob, rules));
  EXPECT_FALSE(crosses_line({0, 1.5, 3}, {8, 1.5, 0.01}, ann, bob, rules));  // on the line
  // The same cut seen against the line drawn the other way round.
  EXPECT_TRUE(crosses_line({0, 1.5, 3}, {2, 1.5, -3}, bob, ann, rules));
}

TEST(Continuity, ATwentyDegreeCutToTheSameSizeIsAJumpCut) {
  const ContinuityRules rules;
  const Eigen::Vector3d subject(0, 1.5, 0);
  const CameraPose a = looking({0, 1.5, 4}, subject);
  // 20 degrees round the subject, same distance.
  const double r = 20 * M_PI / 180;
  const CameraPose b = looking({4 * std::sin(r), 1.5, 4 * std::cos(r)}, subject);
  EXPECT_NEAR(view_turn_degrees(a, b), 20, 1e-9);
  EXPECT_TRUE(is_jump_cut(a, 0.5, b, 0.55, rules));
  EXPECT_FALSE(is_jump_cut(a, 0.5, b, 0.8, rules));  // a size step (x 1.6)
  const double r40 = 40 * M_PI / 180;
  const CameraPose c = looking({4 * std::sin(r40), 1.5, 4 * std::cos(r40)}, subject);
  EXPECT_FALSE(is_jump_cut(a, 0.5, c, 0.5, rules));  // 40 degrees: a new angle
  EXPECT_FALSE(is_jump_cut(a, 0, b, 0.5, rules));    // nobody shown before
}

}  // namespace
}  // namespace sightline::camera
