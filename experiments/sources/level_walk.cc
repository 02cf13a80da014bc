#include "sightline/experiments/sources/level_walk.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "sightline/experiments/sources/floor_probe.h"
#include "sightline/experiments/sources/navigation_mesh.h"

namespace sightline::experiments {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Floor samples along a straight stretch, this far apart: a stair's tread is 0.25 m or more.
constexpr double kSample = 0.1;
// Keyframes are dropped where linear interpolation stays this close to the sampled floor.
constexpr double kHeightTolerance = 0.1;
// The feet stand this far above the floor met by the probe: "on" it, without touching it.
constexpr double kFootLift = 0.01;
// A person slows over this stretch before and after a corner.
constexpr double kCornerStretch = 0.5;
// Of this many random goals, the one farthest along the mesh is walked to next.
constexpr int kGoalCandidates = 8;
// Goals whose route cannot be walked (probe and mesh disagree) are given up after this many.
constexpr int kMaxFailedGoals = 30;
constexpr double kMinRouteLength = 1.0;  // metres
// The person's body, looked at for solid matter: knees and chest above the feet, every
// kSolidSample metres along a leg (oa_thor's thinnest unseen slabs are 0.25 m thick).
constexpr double kSolidHeights[] = {0.5, 1.3};
constexpr double kSolidSample = 0.1;

double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * unit(rng); }

double horizontal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::hypot(b.x() - a.x(), b.z() - a.z());
}
// Yaw 0 faces +z, 90 faces +x: facing = (sin yaw, 0, cos yaw).
double yaw_towards(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  return camera::wrap_degrees(std::atan2(to.x() - from.x(), to.z() - from.z()) * 180 / kPi);
}

// Where a keyframe lies on its straight stretch: the speed there depends on it.
enum class Stretch { kLeaving, kCruising, kArriving, kShort };
struct Placed {
  Eigen::Vector3d feet;
  Stretch stretch;  // of the leg ending here
};
struct Straight {
  double yaw = 0;
  std::vector<Placed> keyframes;  // after the corner it starts at, up to the next one
};

class WalkMaker {
 public:
  WalkMaker(const NavigationMesh& nav, const FloorProbe& probe, const WalkOptions& options,
            const camera::SolidVolume* solid)
      : nav_(nav), probe_(probe), options_(options), solid_(solid) {}

  // Feet on the floor under `p`, looked for from above the highest a step could take them.
  std::optional<Eigen::Vector3d> feet_under(const Eigen::Vector3d& p, double previous_floor) const {
    const double top = std::max(p.y() + 0.5, previous_floor + options_.agent_step + 0.05);
    const double bottom = std::min(p.y(), previous_floor) - 1.0;
    const auto y = probe_.floor_below(p.x(), p.z(), top, bottom);
    if (!y) return std::nullopt;
    return Eigen::Vector3d(p.x(), *y + kFootLift, p.z());
  }

  LevelWalk walk(std::mt19937_64& rng) const;

 private:
  // True when the person would be inside the level's solid volume (if it has one) on the
  // way through `feet` (first_in_solid).
  bool in_solid(const std::vector<Eigen::Vector3d>& feet) const {
    return solid_ != nullptr && first_in_solid(feet, *solid_).has_value();
  }
  // The same on the way from `from` along `plan`.
  bool enters_solid(const Eigen::Vector3d& from, const std::vector<Straight>& plan) const {
    if (solid_ == nullptr) return false;
    std::vector<Eigen::Vector3d> feet = {from};
    for (const Straight& straight : plan) {
      for (const Placed& p : straight.keyframes) feet.push_back(p.feet);
    }
    return in_solid(feet);
  }

  std::optional<std::vector<Straight>> plan_route(
      const Eigen::Vector3d& from, const std::vector<NavigationMesh::RoutePoint>& route) const;
  std::optional<std::vector<Placed>> straight(const Eigen::Vector3d& from,
                                              const std::vector<NavigationMesh::RoutePoint>& route,
                                              std::size_t a, std::size_t b) const;

  const NavigationMesh& nav_;
  const FloorProbe& probe_;
  const WalkOptions& options_;
  const camera::SolidVolume* solid_;  // null: the level has no solid volume
};

// The keyframes of one straight stretch of a route, from the feet `from` (at route[a]) to
// route[b]. The floor is sampled every kSample metres under the line (the mesh's heights,
// from its polygon crossings, say where to look); then, greedily, each keyframe is followed
// by the farthest sample such that interpolating between them stays within
// kHeightTolerance of the floor at every sample in between, the person has headroom there,
// and knees to head pass clear of every surface on the way. A riser right next to a sample
// can make the next sample's leg clip the stair's edge; the one after then serves.
std::optional<std::vector<Placed>> WalkMaker::straight(
    const Eigen::Vector3d& from, const std::vector<NavigationMesh::RoutePoint>& route,
    std::size_t a, std::size_t b) const {
  const Eigen::Vector3d to = route[b].position;
  const double length = horizontal(from, to);
  std::vector<Placed> out;
  if (length < 1e-3) return out;
  // The mesh's height along the line: piecewise linear through the crossings.
  std::vector<double> at_s, at_y;
  for (std::size_t i = a; i <= b; ++i) {
    at_s.push_back(i == a ? 0.0 : std::min(length, horizontal(from, route[i].position)));
    at_y.push_back(route[i].position.y());
  }
  const auto mesh_height = [&](double s) {
    for (std::size_t i = 1; i < at_s.size(); ++i) {
      if (s <= at_s[i] || i + 1 == at_s.size()) {
        const double span = at_s[i] - at_s[i - 1];
        const double f = span > 1e-9 ? std::clamp((s - at_s[i - 1]) / span, 0.0, 1.0) : 1.0;
        return at_y[i - 1] + f * (at_y[i] - at_y[i - 1]);
      }
    }
    return at_y.back();
  };
  // Samples, with the ends of the slow stretches near the corners among them.
  std::vector<double> bounds = {0, length};
  std::vector<Stretch> kinds = {Stretch::kShort};
  if (length > 3 * kCornerStretch) {
    bounds = {0, kCornerStretch, length - kCornerStretch, length};
    kinds = {Stretch::kLeaving, Stretch::kCruising, Stretch::kArriving};
  }
  std::vector<std::optional<Eigen::Vector3d>> floor = {from};
  std::vector<Stretch> kind = {kinds[0]};  // of the leg ending at each sample
  std::vector<bool> boundary = {true};
  double previous = from.y() - kFootLift;
  for (std::size_t part = 0; part + 1 < bounds.size(); ++part) {
    const int n =
        std::max(1, static_cast<int>(std::ceil((bounds[part + 1] - bounds[part]) / kSample)));
    for (int k = 1; k <= n; ++k) {
      const double s = bounds[part] + (bounds[part + 1] - bounds[part]) * k / n;
      const Eigen::Vector3d p = from + (to - from) * (s / length);
      floor.push_back(feet_under({p.x(), mesh_height(s), p.z()}, previous));
      if (floor.back()) previous = floor.back()->y() - kFootLift;
      kind.push_back(kinds[part]);
      boundary.push_back(k == n);
    }
  }
  const std::size_t last = floor.size() - 1;
  std::size_t i = 0;
  while (i < last) {
    std::size_t limit = i + 1;
    while (!boundary[limit]) ++limit;
    std::size_t reach = i;
    for (std::size_t j = i + 1; j <= limit && floor[j]; ++j) {
      bool close = true;
      for (std::size_t k = i + 1; k < j && close; ++k) {
        const double f = static_cast<double>(k - i) / static_cast<double>(j - i);
        const double y = floor[i]->y() + f * (floor[j]->y() - floor[i]->y());
        close = floor[k] && std::abs(y - floor[k]->y()) <= kHeightTolerance;
      }
      if (!close) break;
      reach = j;
    }
    std::size_t chosen = 0;
    for (std::size_t j = reach; j > i && chosen == 0; --j) {
      if (probe_.has_headroom(*floor[j]) && probe_.body_clear(*floor[i], *floor[j])) chosen = j;
    }
    if (chosen == 0 && i + 2 <= limit && floor[i + 1] && floor[i + 2] &&
        probe_.has_headroom(*floor[i + 2]) && probe_.body_clear(*floor[i], *floor[i + 2])) {
      chosen = i + 2;
    }
    if (chosen == 0) return std::nullopt;
    out.push_back({*floor[chosen], kind[chosen]});
    i = chosen;
  }
  return out;
}

std::optional<std::vector<Straight>> WalkMaker::plan_route(
    const Eigen::Vector3d& from, const std::vector<NavigationMesh::RoutePoint>& route) const {
  std::vector<Straight> out;
  Eigen::Vector3d feet = from;
  std::size_t a = 0;
  for (std::size_t b = 1; b < route.size(); ++b) {
    if (!route[b].corner) continue;
    auto keyframes = straight(feet, route, a, b);
    if (!keyframes) return std::nullopt;
    if (!keyframes->empty()) {
      out.push_back({yaw_towards(feet, keyframes->back().feet), std::move(*keyframes)});
      feet = out.back().keyframes.back().feet;
    }
    a = b;
  }
  return out;
}

LevelWalk WalkMaker::walk(std::mt19937_64& rng) const {
  const double duration = uniform(rng, options_.min_seconds, options_.max_seconds);
  std::optional<Eigen::Vector3d> start;
  for (int attempt = 0; attempt < 100 && !start; ++attempt) {
    const Eigen::Vector3d p = nav_.random_point(rng);
    start = feet_under(p, p.y());
    if (start && !probe_.has_headroom(*start)) start.reset();
    if (start && in_solid({*start})) start.reset();
  }
  if (!start) {
    throw WalkError(
        "no point of the walkable region has floor under it and headroom above it "
        "(the navigation mesh and the level's triangles disagree)");
  }
  LevelWalk walk;
  std::vector<camera::Keyframe>& keys = walk.keyframes;
  double t = 0, yaw = 0;
  int failures = 0;
  Eigen::Vector3d here = *start;
  while (keys.empty() || keys.back().t < duration) {
    std::vector<std::pair<double, std::vector<NavigationMesh::RoutePoint>>> goals;
    for (int c = 0; c < kGoalCandidates; ++c) {
      auto route = nav_.route(here, nav_.random_point(rng));
      const double length = route_length(route);
      if (length >= kMinRouteLength) goals.emplace_back(length, std::move(route));
    }
    std::stable_sort(goals.begin(), goals.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    std::optional<std::vector<Straight>> plan;
    for (const auto& goal : goals) {
      plan = plan_route(here, goal.second);
      // A route through matter the triangles miss is refused like one that leaves the floor.
      if (plan && !plan->empty() && !enters_solid(here, *plan)) break;
      plan.reset();
      ++failures;
    }
    if (!plan) {
      if (++failures > kMaxFailedGoals) {
        throw WalkError("could not plan a walkable route after " + std::to_string(failures) +
                        " tries: the walkable region's routes leave the floor or clip surfaces");
      }
      continue;
    }
    const double speed = uniform(rng, options_.min_speed, options_.max_speed);
    for (std::size_t s = 0; s < plan->size(); ++s) {
      const Straight& straight = (*plan)[s];
      double turn_here = 0;
      if (keys.empty()) {
        keys.push_back({0.0, here, straight.yaw});
      } else {
        // The corner: turn towards the next stretch, or stop and turn on the spot.
        turn_here = camera::shortest_turn(yaw, straight.yaw);
        // At least 0.02 s: a turn of nothing still takes a keyframe pair apart in time.
        const double turn_time = std::max(std::abs(turn_here) / options_.turn_rate_degrees, 0.02);
        if (unit(rng) < options_.stop_probability) {
          const double pause = std::max(uniform(rng, 0.5, 2.0), turn_time + 0.05);
          keys.push_back({t + pause - turn_time, here, yaw});
          keys.push_back({t + pause, here, straight.yaw});
          t += pause;
          ++walk.stops;
        } else if (std::abs(turn_here) > 0.5) {
          t += turn_time;
          keys.push_back({t, here, straight.yaw});
        }
      }
      yaw = straight.yaw;
      // Slower into and out of a corner, the more so the sharper it is; a goal is met as a
      // turn about.
      const double turn_next =
          s + 1 < plan->size() ? camera::shortest_turn(yaw, (*plan)[s + 1].yaw) : 180.0;
      const auto slowing = [](double turn) { return 1 - 0.5 * std::abs(turn) / 180; };
      for (const Placed& p : straight.keyframes) {
        double v = speed;
        if (p.stretch == Stretch::kLeaving) v *= slowing(turn_here);
        if (p.stretch == Stretch::kArriving) v *= slowing(turn_next);
        if (p.stretch == Stretch::kShort) v *= std::min(slowing(turn_here), slowing(turn_next));
        t += std::max(horizontal(here, p.feet) / v, 1e-3);
        keys.push_back({t, p.feet, yaw});
        here = p.feet;
      }
    }
  }
  // Trim to the drawn duration: the last leg is cut where the time runs out, the cut point
  // put back on the floor; if it cannot stand there, the walk ends at a keyframe.
  std::size_t m = 0;
  while (keys[m].t < duration) ++m;
  // A cut within kMinCut of a keyframe would leave a leg of a few nanoseconds: end there.
  constexpr double kMinCut = 0.05;
  const bool near_before = m > 0 && duration - keys[m - 1].t < kMinCut;
  const bool near_after = keys[m].t - duration < kMinCut;
  if (near_before && keys[m - 1].t >= options_.min_seconds) {
    --m;
  } else if ((near_before || near_after) && keys[m].t <= options_.max_seconds) {
    // keys[m] ends the walk as it is
  } else if (keys[m].t > duration && m > 0) {
    const camera::Keyframe& before = keys[m - 1];
    const double f = (duration - before.t) / (keys[m].t - before.t);
    const Eigen::Vector3d p = before.position + f * (keys[m].position - before.position);
    const double cut_yaw =
        camera::wrap_degrees(before.yaw + f * camera::shortest_turn(before.yaw, keys[m].yaw));
    std::optional<Eigen::Vector3d> feet;
    if ((keys[m].position - before.position).norm() < 1e-9) {
      feet = p;
    } else {
      feet = feet_under(p, p.y());
      if (feet && !(probe_.has_headroom(*feet) && probe_.body_clear(before.position, *feet) &&
                    !in_solid({before.position, *feet}))) {
        feet.reset();
      }
    }
    if (feet) {
      keys[m] = {duration, *feet, cut_yaw};
    } else if (keys[m].t > options_.max_seconds) {
      --m;
    }
  }
  keys.resize(m + 1);
  for (std::size_t i = 1; i < keys.size(); ++i) {
    walk.length_metres += (keys[i].position - keys[i - 1].position).norm();
  }
  return walk;
}

std::string number(double v) {
  if (std::abs(v) < 5e-7) v = 0;  // no "-0.000000"
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", v);
  return text;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string WalkOptions::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(agent_radius)) return "agent_radius: must be a positive number of metres";
  if (!positive(agent_height)) return "agent_height: must be a positive number of metres";
  if (!(std::isfinite(agent_step) && agent_step >= 0 && agent_step < agent_height)) {
    return "agent_step: must be at least 0 and below agent_height";
  }
  if (!(max_slope_degrees > 0 && max_slope_degrees < 90)) {
    return "max_slope_degrees: must be above 0 and below 90";
  }
  if (!positive(cell_size)) return "cell_size: must be a positive number of metres";
  if (!positive(cell_height)) return "cell_height: must be a positive number of metres";
  if (!positive(min_speed)) return "min_speed: must be a positive number of m/s";
  if (!(std::isfinite(max_speed) && max_speed >= min_speed)) {
    return "max_speed: must be at least min_speed";
  }
  if (!positive(min_seconds)) return "min_seconds: must be a positive number of seconds";
  if (!(std::isfinite(max_seconds) && max_seconds >= min_seconds)) {
    return "max_seconds: must be at least min_seconds";
  }
  if (!(stop_probability >= 0 && stop_probability <= 1)) {
    return "stop_probability: must be within [0, 1]";
  }
  if (!positive(turn_rate_degrees)) return "turn_rate_degrees: must be a positive number of deg/s";
  if (walks < 1) return "walks: must be at least 1";
  return "";
}

LevelWalks generate_walks(const camera::TriangleMesh& mesh, const WalkOptions& options,
                          const std::vector<Eigen::Vector3d>& anchors,
                          const camera::SolidVolume* solid) {
  if (const std::string bad = options.validate(); !bad.empty()) throw std::invalid_argument(bad);
  const auto start = std::chrono::steady_clock::now();
  LevelWalks out;
  const NavigationMesh nav(mesh, options, anchors);
  out.navigation = nav.stats();
  const FloorProbe probe(mesh, options.agent_height);
  const WalkMaker maker(nav, probe, options, solid);
  for (int w = 0; w < options.walks; ++w) {
    // Each walk its own stream: walk k is the same whatever the number of walks.
    std::seed_seq seq{static_cast<std::uint32_t>(options.seed),
                      static_cast<std::uint32_t>(options.seed >> 32),
                      static_cast<std::uint32_t>(w)};
    std::mt19937_64 rng(seq);
    out.walks.push_back(maker.walk(rng));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::optional<std::size_t> first_in_solid(const std::vector<Eigen::Vector3d>& feet,
                                          const camera::SolidVolume& solid) {
  const auto body_in_solid = [&](const Eigen::Vector3d& at) {
    for (double h : kSolidHeights) {
      if (solid.solid_at(at + h * Eigen::Vector3d::UnitY())) return true;
    }
    return false;
  };
  if (feet.size() == 1) {
    if (body_in_solid(feet[0])) return 0;
    return std::nullopt;
  }
  for (std::size_t i = 0; i + 1 < feet.size(); ++i) {
    const Eigen::Vector3d& a = feet[i];
    const Eigen::Vector3d& b = feet[i + 1];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kSolidSample)));
    for (int k = 0; k <= n; ++k) {
      if (body_in_solid(a + (b - a) * (static_cast<double>(k) / n))) return i;
    }
  }
  return std::nullopt;
}

std::string walk_scene_yaml(const std::string& name, const std::string& description,
                            const std::string& level_file, const std::string& map,
                            const LevelWalk& walk, std::optional<double> scale,
                            std::optional<camera::UpAxis> up) {
  std::ostringstream out;
  out << "name: " << quoted(name) << "\n";
  if (!description.empty()) out << "description: " << quoted(description) << "\n";
  out << "\nlevel:\n  file: " << quoted(level_file) << "\n";
  if (!map.empty()) out << "  map: " << quoted(map) << "\n";
  if (scale) out << "  scale: " << number(*scale) << "\n";
  if (up) out << "  up: " << (*up == camera::UpAxis::kY ? "y" : "z") << "\n";
  out << "\ntrajectory:\n";
  for (const camera::Keyframe& k : walk.keyframes) {
    out << "  - {t: " << number(k.t) << ", position: [" << number(k.position.x()) << ", "
        << number(k.position.y()) << ", " << number(k.position.z()) << "], yaw: " << number(k.yaw)
        << "}\n";
  }
  return out.str();
}

}  // namespace sightline::experiments
