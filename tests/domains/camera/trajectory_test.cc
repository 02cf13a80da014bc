// The character's state between keyframes: linear position, shorter-arc yaw, piecewise
// constant velocity, and the frame grid with both ends included.
#include "sightline/domains/camera/trajectory.h"

#include <gtest/gtest.h>

namespace sightline::camera {
namespace {

Trajectory walk() {
  return Trajectory({{0.0, {0, 0, 0}, 0}, {2.0, {2, 0, 4}, 0}, {3.0, {2, 0, 4}, 90}});
}

TEST(Trajectory, InterpolatesThePositionLinearly) {
  const CharacterState s = walk().state_at(0.5);
  EXPECT_DOUBLE_EQ(s.position.x(), 0.5);
  EXPECT_DOUBLE_EQ(s.position.z(), 1.0);
  EXPECT_DOUBLE_EQ(s.velocity.x(), 1.0);  // (2, 0, 4) over 2 s
  EXPECT_DOUBLE_EQ(s.velocity.z(), 2.0);
}

TEST(Trajectory, TurnsOnTheSpotBetweenAKeyframePair) {
  const CharacterState s = walk().state_at(2.5);
  EXPECT_DOUBLE_EQ(s.position.x(), 2.0);
  EXPECT_DOUBLE_EQ(s.yaw, 45.0);
  EXPECT_EQ(s.velocity, Eigen::Vector3d::Zero());
}

TEST(Trajectory, YawTakesTheShorterArcAcrossNorth) {
  const Trajectory t({{0.0, {0, 0, 0}, 350}, {1.0, {0, 0, 0}, 10}});
  EXPECT_NEAR(t.state_at(0.25).yaw, 355.0, 1e-12);
  EXPECT_NEAR(t.state_at(0.5).yaw, 0.0, 1e-12);
  EXPECT_NEAR(t.state_at(0.75).yaw, 5.0, 1e-12);
  // And the other way round: 10 -> 350 turns through 0, not through 180.
  const Trajectory back({{0.0, {0, 0, 0}, 10}, {1.0, {0, 0, 0}, 350}});
  EXPECT_NEAR(back.state_at(0.75).yaw, 355.0, 1e-12);
}

TEST(Trajectory, AHalfTurnGoesThroughIncreasingYaw) {
  const Trajectory t({{0.0, {0, 0, 0}, 0}, {1.0, {0, 0, 0}, 180}});
  EXPECT_DOUBLE_EQ(t.state_at(0.5).yaw, 90.0);
  const Trajectory u({{0.0, {0, 0, 0}, 180}, {1.0, {0, 0, 0}, 0}});
  EXPECT_DOUBLE_EQ(u.state_at(0.5).yaw, 270.0);
}

TEST(Trajectory, YawIsReportedInZeroTo360WhateverWasWritten) {
  const Trajectory t({{0.0, {0, 0, 0}, -90}, {1.0, {0, 0, 0}, 725}});
  EXPECT_DOUBLE_EQ(t.state_at(0.0).yaw, 270.0);
  EXPECT_NEAR(t.state_at(1.0).yaw, 5.0, 1e-9);
}

TEST(Trajectory, StandsStillOutsideItsKeyframes) {
  const CharacterState before = walk().state_at(-1);
  EXPECT_EQ(before.position, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(before.velocity, Eigen::Vector3d::Zero());
  const CharacterState after = walk().state_at(10);
  EXPECT_EQ(after.position, Eigen::Vector3d(2, 0, 4));
  EXPECT_DOUBLE_EQ(after.yaw, 90.0);
  EXPECT_EQ(after.velocity, Eigen::Vector3d::Zero());
}

TEST(Trajectory, VelocityAtAKeyframeIsThatOfTheSegmentStartingThere) {
  EXPECT_DOUBLE_EQ(walk().state_at(0.0).velocity.x(), 1.0);
  EXPECT_EQ(walk().state_at(2.0).velocity, Eigen::Vector3d::Zero());  // the turn starts here
  EXPECT_EQ(walk().state_at(3.0).velocity, Eigen::Vector3d::Zero());  // last: the last segment's
}

TEST(Trajectory, FramesCoverBothEnds) {
  const Trajectory t({{1.0, {0, 0, 0}, 0}, {2.0, {1, 0, 0}, 0}});
  ASSERT_EQ(t.frame_count(60), 61u);
  EXPECT_DOUBLE_EQ(t.frame_time(0, 60), 1.0);
  EXPECT_DOUBLE_EQ(t.frame_time(1, 60), 1.0 + 1.0 / 60);
  EXPECT_DOUBLE_EQ(t.frame_time(60, 60), 2.0);
}

TEST(Trajectory, ALastPartialIntervalEndsOnTheLastKeyframe) {
  const Trajectory t({{0.0, {0, 0, 0}, 0}, {1.05, {1, 0, 0}, 0}});
  ASSERT_EQ(t.frame_count(10), 12u);  // 0, 0.1, ..., 1.0 and then 1.05
  EXPECT_NEAR(t.frame_time(10, 10), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.frame_time(11, 10), 1.05);
}

TEST(Trajectory, ASingleKeyframeIsOneFrame) {
  const Trajectory t({{3.0, {1, 2, 3}, 45}});
  EXPECT_EQ(t.frame_count(60), 1u);
  EXPECT_EQ(t.state_at(3.0).position, Eigen::Vector3d(1, 2, 3));
}

TEST(Yaw, FacingVectorFollowsTheConvention) {
  EXPECT_NEAR((facing_from_yaw(0) - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
  EXPECT_NEAR((facing_from_yaw(90) - Eigen::Vector3d(1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((facing_from_yaw(-90) - Eigen::Vector3d(-1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_DOUBLE_EQ(shortest_turn(350, 10), 20);
  EXPECT_DOUBLE_EQ(shortest_turn(10, 350), -20);
  EXPECT_DOUBLE_EQ(shortest_turn(0, 180), 180);
  EXPECT_DOUBLE_EQ(wrap_degrees(-1e-18), 0.0);  // never 360
}

}  // namespace
}  // namespace sightline::camera
