// walk.cc: reading a walk's keyframes and replaying it frame by frame (see walk.h).
#include "walk.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <stdexcept>

namespace example {
namespace {

constexpr const char* kHeader = "t,x,y,z,yaw";

// Parses "t,x,y,z,yaw": five finite numbers and nothing else.
std::optional<Keyframe> parse_row(const std::string& line) {
  double v[5];
  const char* p = line.c_str();
  for (int i = 0; i < 5; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(p, &end);
    if (end == p || !std::isfinite(v[i])) return std::nullopt;
    p = end;
    if (*p != (i < 4 ? ',' : '\0')) return std::nullopt;
    ++p;
  }
  return Keyframe{v[0], {v[1], v[2], v[3]}, v[4]};
}

double wrap_degrees(double degrees) {
  double w = std::fmod(degrees, 360.0);
  if (w < 0) w += 360.0;
  return w >= 360.0 ? w - 360.0 : w;  // a tiny negative plus 360 can round to 360
}

// The shorter signed turn from `from` to `to`, in (-180, 180].
double shortest_turn(double from, double to) {
  const double d = wrap_degrees(to - from);
  return d > 180.0 ? d - 360.0 : d;
}

}  // namespace

Walk Walk::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::size_t number = 1;
  const auto fail = [&](const std::string& problem) {
    return std::runtime_error(path + ":" + std::to_string(number) + ": " + problem);
  };
  std::string line;
  const auto next_line = [&] {
    if (!std::getline(in, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  };
  if (!next_line() || line != kHeader) {
    throw fail(std::string("the first line must be '") + kHeader + "'");
  }
  std::vector<Keyframe> keys;
  while (next_line()) {
    ++number;
    if (line.empty()) continue;
    const std::optional<Keyframe> k = parse_row(line);
    if (!k) throw fail(std::string("expected five numbers: ") + kHeader);
    if (!keys.empty() && !(k->t > keys.back().t)) throw fail("t must increase");
    keys.push_back(*k);
  }
  if (in.bad()) throw fail("read error");
  if (keys.empty()) throw fail("no keyframes");
  return Walk(std::move(keys));
}

// The segment [keys_[i], keys_[i + 1]] holding t: the last keyframe at or before t, clamped
// to the segments there are.
std::size_t Walk::segment_at(double t) const {
  const auto after = std::upper_bound(keys_.begin(), keys_.end(), t,
                                      [](double value, const Keyframe& k) { return value < k.t; });
  const auto i = static_cast<std::size_t>(after - keys_.begin());
  return std::min(i == 0 ? 0 : i - 1, keys_.size() - 2);
}

WalkState Walk::at(double t) const {
  if (keys_.size() == 1) return WalkState{keys_[0].position, {}, wrap_degrees(keys_[0].yaw)};
  const std::size_t i = segment_at(t);
  const Keyframe& a = keys_[i];
  const Keyframe& b = keys_[i + 1];
  const double span = b.t - a.t;
  const double u = std::clamp((t - a.t) / span, 0.0, 1.0);
  const V3 delta = b.position - a.position;
  return WalkState{a.position + u * delta, (1 / span) * delta,
                   wrap_degrees(a.yaw + u * shortest_turn(a.yaw, b.yaw))};
}

std::size_t Walk::frame_count(double rate) const {
  // Frames at start + k / rate for k = 0 .. floor(duration * rate), plus the last keyframe
  // when it is not (within a millionth of a frame) on that grid.
  const double frames = (end() - start()) * rate;
  const double whole = std::floor(frames + 1e-6);
  return static_cast<std::size_t>(whole) + 1 + (frames - whole > 1e-6 ? 1 : 0);
}

double Walk::frame_time(std::size_t frame, double rate) const {
  return std::min(start() + static_cast<double>(frame) / rate, end());
}

}  // namespace example
