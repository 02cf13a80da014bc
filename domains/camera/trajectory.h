// Trajectory: the character's path through a scene, as timed keyframes, and its state at
// any time in between.
//
// Between keyframes the feet position is interpolated linearly and the yaw along the shorter
// arc (350 -> 10 degrees turns +20 through 0, not -340); a difference of exactly 180 degrees
// turns through increasing yaw. Before the first keyframe and after the last the character
// stands still at the end keyframe. The run covers the first to the last keyframe, one frame
// every 1 / frame_rate seconds with both ends included: when the duration is not a whole
// number of frame intervals the last frame is the last keyframe, a shorter interval after the
// one before.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <vector>

namespace sightline::camera {

struct Keyframe {
  double t = 0;                                        // seconds, strictly increasing
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of the feet, metres
  double yaw = 0;                                      // degrees, any finite value
};

// Yaw is a rotation about +y (y is up): yaw 0 faces +z, yaw 90 faces +x.
inline Eigen::Vector3d facing_from_yaw(double yaw_degrees);

struct CharacterState {
  double t = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // feet, metres
  double yaw = 0;                                      // degrees in [0, 360)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // metres per second
  // The horizontal unit vector the character faces: (sin yaw, 0, cos yaw).
  Eigen::Vector3d facing() const { return facing_from_yaw(yaw); }
};

// Normalises degrees into [0, 360).
double wrap_degrees(double degrees);
// The shorter signed turn from `from` to `to`, in (-180, 180].
double shortest_turn(double from, double to);

class Trajectory {
 public:
  Trajectory() = default;
  // Requires at least one keyframe and strictly increasing, finite times (the scene reader
  // checks and reports these with line numbers; here they are preconditions).
  explicit Trajectory(std::vector<Keyframe> keyframes);

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  double start_time() const { return keyframes_.front().t; }
  double end_time() const { return keyframes_.back().t; }
  double duration() const { return end_time() - start_time(); }

  // Position, yaw and velocity at time t. The velocity is that of the segment containing t;
  // at a keyframe it is the velocity of the segment that starts there (of the last segment
  // at the last keyframe). O(log keyframes), no allocation.
  CharacterState state_at(double t) const;
  // Index of the segment [keyframe i, keyframe i+1] holding t (clamped to the valid range).
  std::size_t segment_at(double t) const;

  // Frames from the first keyframe to the last, both included (see the header comment).
  std::size_t frame_count(double frame_rate) const;
  double frame_time(std::size_t frame, double frame_rate) const;

 private:
  std::vector<Keyframe> keyframes_;
};

inline Eigen::Vector3d facing_from_yaw(double yaw_degrees) {
  const double r = yaw_degrees * (3.14159265358979323846 / 180.0);
  return {std::sin(r), 0.0, std::cos(r)};
}

}  // namespace sightline::camera
