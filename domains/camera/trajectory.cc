#include "sightline/domains/camera/trajectory.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace sightline::camera {

double wrap_degrees(double degrees) {
  double w = std::fmod(degrees, 360.0);
  if (w < 0) w += 360.0;
  if (w >= 360.0) w -= 360.0;  // fmod of a tiny negative number plus 360 can round to 360
  return w;
}

double shortest_turn(double from, double to) {
  double d = wrap_degrees(to - from);  // [0, 360)
  if (d > 180.0) d -= 360.0;           // (-180, 180]
  return d;
}

Trajectory::Trajectory(std::vector<Keyframe> keyframes) : keyframes_(std::move(keyframes)) {
  assert(!keyframes_.empty());
}

std::size_t Trajectory::segment_at(double t) const {
  if (keyframes_.size() < 2) return 0;
  // First keyframe strictly after t; the segment starts at the one before it.
  auto it = std::upper_bound(keyframes_.begin(), keyframes_.end(), t,
                             [](double value, const Keyframe& k) { return value < k.t; });
  std::size_t after = static_cast<std::size_t>(it - keyframes_.begin());
  if (after == 0) return 0;
  return std::min(after - 1, keyframes_.size() - 2);
}

CharacterState Trajectory::state_at(double t) const {
  CharacterState s;
  s.t = t;
  if (keyframes_.size() == 1) {
    s.position = keyframes_[0].position;
    s.yaw = wrap_degrees(keyframes_[0].yaw);
    return s;
  }
  const std::size_t i = segment_at(t);
  const Keyframe& a = keyframes_[i];
  const Keyframe& b = keyframes_[i + 1];
  const double span = b.t - a.t;
  const double u = std::clamp((t - a.t) / span, 0.0, 1.0);
  s.position = a.position + u * (b.position - a.position);
  s.yaw = wrap_degrees(a.yaw + u * shortest_turn(a.yaw, b.yaw));
  // Standing still outside [first, last]; otherwise the segment's constant velocity.
  if (t >= keyframes_.front().t && t <= keyframes_.back().t) {
    s.velocity = (b.position - a.position) / span;
  }
  return s;
}

std::size_t Trajectory::frame_count(double frame_rate) const {
  // Frames at start + k / rate for k = 0 .. floor(duration * rate), plus the last keyframe
  // when it is not (within a millionth of a frame) on that grid.
  const double frames = duration() * frame_rate;
  const auto whole = static_cast<std::size_t>(std::floor(frames + 1e-6));
  const bool extra = frames - static_cast<double>(whole) > 1e-6;
  return whole + 1 + (extra ? 1 : 0);
}

double Trajectory::frame_time(std::size_t frame, double frame_rate) const {
  return std::min(start_time() + static_cast<double>(frame) / frame_rate, end_time());
}

}  // namespace sightline::camera
