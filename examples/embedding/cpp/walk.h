// walk.h: the character's walk, as a game would replay a recorded path: timed keyframes read
// from a CSV file, and the character's state at any time in between.
//
// The example has no game to drive the character, so it replays a walk made by
// `sightline level walk`. Between keyframes the feet move in a straight line and the yaw turns
// the shorter way round (a turn of exactly 180 degrees goes through increasing yaw). The
// frames run from the first keyframe to the last at a fixed rate; when the walk is not a whole
// number of frames long, one more, shorter frame ends exactly on the last keyframe.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "vector3.h"

namespace example {

struct Keyframe {
  double t = 0;    // seconds, strictly increasing
  V3 position;     // centre of the feet, metres
  double yaw = 0;  // degrees; 0 faces +z, 90 faces +x
};

struct WalkState {
  V3 position;
  V3 velocity;     // metres per second: the current segment's
  double yaw = 0;  // degrees in [0, 360)
};

class Walk {
 public:
  // Reads a file of `t,x,y,z,yaw` rows under that header line. Throws std::runtime_error
  // naming the file and line.
  static Walk read(const std::string& path);

  const std::vector<Keyframe>& keyframes() const { return keys_; }
  double start() const { return keys_.front().t; }
  double end() const { return keys_.back().t; }

  // The state at time t, in [start, end]. At a keyframe the velocity is that of the segment
  // starting there (of the last segment at the last keyframe).
  WalkState at(double t) const;

  // The number of frames at `rate` per second, both ends included, and the time of one.
  std::size_t frame_count(double rate) const;
  double frame_time(std::size_t frame, double rate) const;

 private:
  explicit Walk(std::vector<Keyframe> keys) : keys_(std::move(keys)) {}
  std::size_t segment_at(double t) const;

  std::vector<Keyframe> keys_;  // at least one
};

}  // namespace example
