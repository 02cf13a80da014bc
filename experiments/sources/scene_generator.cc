#include "sightline/experiments/sources/scene_generator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene_at_time.h"
#include "sightline/experiments/runs/independent_check.h"
#include "sightline/experiments/sources/scene_building.h"

namespace sightline::experiments {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Distance from the box to the segment a-b in the ground plane (x, z), 0 if they meet.
double ground_distance(const camera::Aabb& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // Sample finely enough for the margins used here (boxes are >= 0.3 m across).
  double best = 1e18;
  const double length = (b - a).norm();
  const int steps = std::max(1, static_cast<int>(length / 0.1));
  for (int i = 0; i <= steps; ++i) {
    const Eigen::Vector3d p = a + (b - a) * (static_cast<double>(i) / steps);
    const double dx = std::max({box.min.x() - p.x(), 0.0, p.x() - box.max.x()});
    const double dz = std::max({box.min.z() - p.z(), 0.0, p.z() - box.max.z()});
    best = std::min(best, std::hypot(dx, dz));
  }
  return best;
}

// Keyframes walking through `points` at `speed`, facing the way of travel, turning on the
// spot at each waypoint.
camera::Trajectory walk(const std::vector<Eigen::Vector3d>& points, double speed) {
  std::vector<camera::Keyframe> keys;
  double t = 0;
  double yaw = std::atan2(points[1].x() - points[0].x(), points[1].z() - points[0].z()) * 180 / kPi;
  keys.push_back({t, points[0], yaw});
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - points[i - 1];
    double heading = std::atan2(d.x(), d.z()) * 180 / kPi;
    double turn = std::remainder(heading - yaw, 360.0);
    if (std::abs(turn) > 1e-6) {
      t += 0.4 * std::max(1.0, std::abs(turn) / 90);
      yaw += turn;
      keys.push_back({t, points[i - 1], yaw});
    }
    t += d.norm() / speed;
    keys.push_back({t, points[i], yaw});
  }
  return camera::Trajectory(std::move(keys));
}

camera::Scene finish(std::string name, std::vector<camera::SolidBox> boxes,
                     std::vector<camera::Area> areas, const std::vector<Eigen::Vector3d>& path,
                     double speed, std::vector<camera::Mover> movers = {}) {
  camera::Scene scene(std::move(name), std::move(boxes), std::move(areas),
                      camera::CharacterShape{}, walk(path, speed), 60);
  scene.set_movers(std::move(movers));
  scene_building::place_camera_start(scene);
  return scene;
}

}  // namespace

camera::Scene generate_pillar_forest(const GeneratedSceneOptions& options) {
  std::mt19937_64 rng(options.seed);
  const double side = std::sqrt(options.area_per_box * static_cast<double>(options.boxes));
  std::uniform_real_distribution<double> coordinate(-side / 2, side / 2);
  std::uniform_real_distribution<double> unit(0, 1);
  // The walk: random waypoints in the middle of the world, each leg a few metres.
  std::vector<Eigen::Vector3d> path{{0, 0, 0}};
  const double walk_length = options.walk_seconds * options.walk_speed;
  double length = 0;
  const double inner = std::min(side / 2 - 2, 30.0);
  while (length < walk_length) {
    const double angle = unit(rng) * 2 * kPi;
    const double leg = 3 + 5 * unit(rng);
    Eigen::Vector3d next = path.back() + leg * Eigen::Vector3d(std::sin(angle), 0, std::cos(angle));
    next.x() = std::clamp(next.x(), -inner, inner);
    next.z() = std::clamp(next.z(), -inner, inner);
    if ((next - path.back()).norm() < 1) continue;
    length += (next - path.back()).norm();
    path.push_back(next);
  }
  std::vector<camera::SolidBox> boxes;
  boxes.reserve(options.boxes);
  while (boxes.size() < options.boxes) {
    const bool wall = unit(rng) < 0.25;
    const double w = wall ? 2 + 4 * unit(rng) : 0.4 + 0.8 * unit(rng);
    const double d = wall ? 0.2 + 0.2 * unit(rng) : 0.4 + 0.8 * unit(rng);
    const bool along_x = unit(rng) < 0.5;
    const double sx = along_x ? w : d, sz = along_x ? d : w;
    const double h = wall ? 1 + 2.5 * unit(rng) : 2 + 6 * unit(rng);
    const Eigen::Vector3d centre(coordinate(rng), 0, coordinate(rng));
    camera::Aabb box{{centre.x() - sx / 2, 0, centre.z() - sz / 2},
                     {centre.x() + sx / 2, h, centre.z() + sz / 2}};
    bool clear = true;
    for (std::size_t i = 1; i < path.size() && clear; ++i) {
      clear = ground_distance(box, path[i - 1], path[i]) > 0.8;
    }
    if (clear) boxes.push_back({"box-" + std::to_string(boxes.size()), box, {}});
  }
  return finish("pillar-forest-" + std::to_string(options.boxes) + "-seed-" +
                    std::to_string(options.seed),
                std::move(boxes), {}, path, options.walk_speed);
}

camera::Scene generate_city(const GeneratedSceneOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const double block = 12, street = 6;  // a block and its street repeat every 18 m
  const double pitch = block + street;
  const int per_side = std::max(2, static_cast<int>(std::ceil(std::sqrt(options.boxes / 2.0))));
  const double origin = -per_side * pitch / 2;
  std::vector<camera::SolidBox> boxes;
  std::vector<camera::Area> areas;
  // Streets run along x at z = origin + k * pitch - street / 2 and along z likewise.
  for (int i = 0; i < per_side && boxes.size() < options.boxes; ++i) {
    for (int j = 0; j < per_side && boxes.size() < options.boxes; ++j) {
      const double x0 = origin + i * pitch, z0 = origin + j * pitch;
      const double height = 4 + 12 * unit(rng);
      boxes.push_back({"building-" + std::to_string(i) + "-" + std::to_string(j),
                       {{x0, 0, z0}, {x0 + block, height, z0 + block}}, {}});
      if (boxes.size() < options.boxes && unit(rng) < 0.4) {
        // An upper floor overhanging the street by 1.5 m, its underside 3 m up.
        boxes.push_back({"overhang-" + std::to_string(i) + "-" + std::to_string(j),
                         {{x0, 3, z0 - 1.5}, {x0 + block, std::min(height, 6.0), z0}}, {}});
      }
      if (boxes.size() < options.boxes && unit(rng) < 0.15) {
        // A covered passage over the street south of the block.
        const double zs = z0 - street;
        boxes.push_back({"passage-roof-" + std::to_string(i) + "-" + std::to_string(j),
                         {{x0 + 3, 3.2, zs}, {x0 + 7, 3.5, z0}}, {}});
        areas.push_back({"passage-" + std::to_string(i) + "-" + std::to_string(j),
                         camera::AreaKind::kSemiEnclosed,
                         {{x0 + 3, 0, zs}, {x0 + 7, 3.5, z0}}, {}});
      }
    }
  }
  // The walk: along street centre lines, turning at random crossings.
  auto street_line = [&](int k) { return origin + k * pitch - street / 2; };
  int ix = per_side / 2, iz = per_side / 2;
  std::vector<Eigen::Vector3d> path{{street_line(ix), 0, street_line(iz)}};
  double length = 0;
  const double walk_length = options.walk_seconds * options.walk_speed;
  bool along_x = true;
  while (length < walk_length) {
    const int steps = 1 + static_cast<int>(unit(rng) * 2);
    const int dir = unit(rng) < 0.5 ? -1 : 1;
    int& k = along_x ? ix : iz;
    const int target = std::clamp(k + dir * steps, 1, per_side - 1);
    if (target == k) {
      along_x = !along_x;
      continue;
    }
    k = target;
    const Eigen::Vector3d next(street_line(ix), 0, street_line(iz));
    length += (next - path.back()).norm();
    path.push_back(next);
    along_x = !along_x;
  }
  return finish("city-" + std::to_string(options.boxes) + "-seed-" + std::to_string(options.seed),
                std::move(boxes), std::move(areas), path, options.walk_speed);
}

}  // namespace sightline::experiments

namespace sightline::experiments {
namespace {

camera::SolidBox wall(std::string name, double x0, double z0, double x1, double z1, double h) {
  return {std::move(name), {{x0, 0, z0}, {x1, h, z1}}, {}};
}

// Heading (unit, ground plane) turned by `degrees` about +y, the yaw convention.
Eigen::Vector3d turned(const Eigen::Vector3d& heading, double degrees) {
  const double r = degrees * kPi / 180, c = std::cos(r), s = std::sin(r);
  return Eigen::Vector3d(c * heading.x() + s * heading.z(), 0, -s * heading.x() + c * heading.z())
      .normalized();
}

}  // namespace

camera::Scene generate_switchback(const SwitchbackOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  const int lanes = std::uniform_int_distribution<int>(std::max(1, options.min_lanes),
                                                       std::max(1, options.max_lanes))(rng);
  const double length = between(options.min_length, options.max_length);
  const double height = between(options.min_wall_height, options.max_wall_height);
  // Lane k runs from z[k] to z[k + 1]; inner wall k (1..lanes-1) is centred on z[k].
  std::vector<double> z{0};
  for (int k = 0; k < lanes; ++k) {
    z.push_back(z.back() + between(options.min_lane_width, options.max_lane_width));
  }
  std::vector<double> gap(lanes + 1, 0);
  for (int k = 1; k < lanes; ++k) gap[k] = between(1.6, std::min(3.5, length / 3));
  const double top = z.back();
  std::vector<camera::SolidBox> boxes{
      wall("outer-south", -0.2, -0.2, length + 0.2, 0, height),
      wall("outer-north", -0.2, top, length + 0.2, top + 0.2, height),
      wall("outer-west", -0.2, 0, 0, top, height),
      wall("outer-east", length, 0, length + 0.2, top, height)};
  for (int k = 1; k < lanes; ++k) {
    // Odd walls leave their gap at the east end, even walls at the west: the walk zig-zags.
    const bool gap_east = k % 2 == 1;
    boxes.push_back(wall("divider-" + std::to_string(k), gap_east ? 0 : gap[k], z[k] - 0.1,
                         gap_east ? length - gap[k] : length, z[k] + 0.1, height));
  }
  // The walk: along each lane's centre line, up through the gap at its end into the next.
  const double margin = std::min(2.5, length / 4);
  std::vector<Eigen::Vector3d> path{{margin, 0, (z[0] + z[1]) / 2}};
  for (int k = 0; k < lanes; ++k) {
    const bool east = k % 2 == 0;
    const double centre = (z[k] + z[k + 1]) / 2;
    if (k + 1 < lanes) {
      const double x = east ? length - gap[k + 1] / 2 : gap[k + 1] / 2;
      path.push_back({x, 0, centre});
      path.push_back({x, 0, (z[k + 1] + z[k + 2]) / 2});
    } else {
      path.push_back({east ? length - margin : margin, 0, centre});
    }
  }
  camera::Scene scene = finish("switchback-seed-" + std::to_string(options.seed), std::move(boxes),
                               {}, path, options.walk_speed);
  char description[96];
  std::snprintf(description, sizeof description, "%d lanes %.1f m long between walls %.1f m high",
                lanes, length, height);
  scene.set_description(description);
  return scene;
}

camera::Scene generate_crossings(const CrossingOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  // The walk: random legs of 4-9 m on open ground, turning at most 100 degrees at a time.
  std::vector<Eigen::Vector3d> path{{0, 0, 0}};
  double heading = between(0, 360), length = 0;
  while (length < options.walk_seconds * options.walk_speed) {
    heading += between(-100, 100);
    const double leg = between(4, 9);
    Eigen::Vector3d next = path.back() + leg * camera::facing_from_yaw(heading);
    next.x() = std::clamp(next.x(), -25.0, 25.0);
    next.z() = std::clamp(next.z(), -25.0, 25.0);
    if ((next - path.back()).norm() < 1) continue;
    length += (next - path.back()).norm();
    path.push_back(next);
  }
  Eigen::Vector3d lo = path.front(), hi = path.front();
  for (const Eigen::Vector3d& p : path) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // Pillars more than 1 m from every leg, over the walk's bounds and 8 m around, widened to
  // 30 m^2 of ground a pillar when there are many (benchmarks ask for 1,000).
  const Eigen::Vector3d middle = (lo + hi) / 2;
  const double half = std::max({(hi - lo).maxCoeff() / 2 + 8,
                                std::sqrt(30.0 * static_cast<double>(options.pillars)) / 2});
  std::vector<camera::SolidBox> boxes;
  for (std::size_t attempt = 0; boxes.size() < options.pillars && attempt < 100 * options.pillars;
       ++attempt) {
    const double w = between(0.4, 1.0), d = between(0.4, 1.0);
    const Eigen::Vector3d c(between(middle.x() - half, middle.x() + half), 0,
                            between(middle.z() - half, middle.z() + half));
    const camera::Aabb box{{c.x() - w / 2, 0, c.z() - d / 2},
                           {c.x() + w / 2, between(2, 5), c.z() + d / 2}};
    bool clear = true;
    for (std::size_t i = 1; i < path.size() && clear; ++i) {
      clear = ground_distance(box, path[i - 1], path[i]) > 1.0;
    }
    if (clear) boxes.push_back({"pillar-" + std::to_string(boxes.size()), box, {}});
  }
  // A scene without movers first, to ask where the character is when.
  const camera::Scene walk_only("walk", boxes, {}, camera::CharacterShape{},
                                walk(path, options.walk_speed), 60);
  const double t0 = walk_only.trajectory().start_time(), t1 = walk_only.trajectory().end_time();
  const Eigen::Vector3d kVehicles[] = {{4.5, 1.5, 1.9}, {5.5, 2.6, 2.1}, {12, 3.2, 2.5}};
  // Before its first keyframe and after its last a mover stands still: where it stands must
  // be clear of her walk (a bus parked on her path would hide her for the rest of the walk),
  // and its straight walk must miss the pillars. A candidate that fails is drawn again (at
  // most 50 times; then the last one is kept, so the count is always what was asked).
  auto stands_clear = [&](const camera::Aabb& box) {
    for (std::size_t k = 1; k < path.size(); ++k) {
      if (ground_distance(box, path[k - 1], path[k]) < 1.5) return false;
    }
    return true;
  };
  auto misses_pillars = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) {
    for (const camera::SolidBox& pillar : boxes) {
      if (ground_distance(pillar.box, a, b) < radius) return false;
    }
    return true;
  };
  std::vector<camera::Mover> movers;
  for (std::size_t i = 0; i < options.movers; ++i) {
    for (int attempt = 0;; ++attempt) {
      const bool vehicle = unit(rng) < options.vehicle_fraction;
      const bool across_sight_line = unit(rng) < 2.0 / 3.0;
      const double speed = vehicle ? between(4, 12) : between(0.8, 2.0);
      const double t_cross = between(t0 + 1, std::max(t0 + 1, t1 - 1));
      Eigen::Vector3d point, ahead;
      if (across_sight_line) {
        // Where the line from her to a chase camera behind her is at t_cross.
        const camera::CharacterState c = walk_only.character_at(t_cross);
        point = c.position -
                between(vehicle ? 0.6 : 0.3, 0.95) * options.camera_distance * c.facing();
        ahead = c.facing();
      } else {
        // A point of her path she reaches 1.5-4 s before or after the mover crosses it.
        const double when =
            std::clamp(t_cross + (unit(rng) < 0.5 ? -1 : 1) * between(1.5, 4), t0, t1);
        const camera::CharacterState c = walk_only.character_at(when);
        point = c.position;
        ahead = c.facing();
      }
      Eigen::Vector3d direction = turned(ahead, (unit(rng) < 0.5 ? -1 : 1) * between(50, 130));
      Eigen::Vector3d size(0.5, between(1.6, 1.95), 0.5);
      if (vehicle) {
        // A vehicle's box is axis-aligned, so it drives along x or z: the axis most across her.
        const bool along_x = std::abs(ahead.x()) < std::abs(ahead.z());
        direction = along_x ? Eigen::Vector3d(direction.x() < 0 ? -1 : 1, 0, 0)
                            : Eigen::Vector3d(0, 0, direction.z() < 0 ? -1 : 1);
        const Eigen::Vector3d& v = kVehicles[std::uniform_int_distribution<int>(0, 2)(rng)];
        size = along_x ? v : Eigen::Vector3d(v.z(), v.y(), v.x());
      }
      const double half = between(8, 14) + (vehicle ? size.maxCoeff() / 2 : 0);
      const Eigen::Vector3d from = point - half * direction, to = point + half * direction;
      const bool fits = stands_clear(camera::Aabb::around_feet(from, size)) &&
                        stands_clear(camera::Aabb::around_feet(to, size)) &&
                        misses_pillars(from, to, std::max(size.x(), size.z()) / 2 + 0.1);
      if (!fits && attempt < 50) continue;
      std::vector<camera::MoverKeyframe> keys{{t_cross - half / speed, from},
                                              {t_cross + half / speed, to}};
      movers.emplace_back((vehicle ? "vehicle-" : "passer-by-") + std::to_string(i), size,
                          std::move(keys));
      break;
    }
  }
  return finish("crossings-" + std::to_string(options.movers) + "-seed-" +
                    std::to_string(options.seed),
                std::move(boxes), {}, path, options.walk_speed, std::move(movers));
}

}  // namespace sightline::experiments
