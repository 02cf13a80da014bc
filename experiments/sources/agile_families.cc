#include "sightline/experiments/sources/agile_families.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "sightline/experiments/sources/scene_building.h"

namespace sightline::experiments {

using Eigen::Vector3d;
using scene_building::add_ceiling;
using scene_building::carve_walls;
using scene_building::Draw;
using scene_building::family_scene_name;
using scene_building::finish;
using scene_building::lane;
using scene_building::Rect;

namespace {

constexpr double kPi = 3.14159265358979323846;

double yaw_of(const Vector3d& d) { return std::atan2(d.x(), d.z()) * 180 / kPi; }

// Keyframes built move by move; yaws unwrapped so each change turns the short way.
struct Keys {
  std::vector<camera::Keyframe> keys;
  double t = 0;
  Keys(const Vector3d& p, double yaw) { keys.push_back({0, p, yaw}); }
  const Vector3d& at() const { return keys.back().position; }
  double yaw() const { return keys.back().yaw; }
  double unwrap(double to) const { return yaw() + std::remainder(to - yaw(), 360.0); }
  // Turns on the spot to `yaw` at `degrees_per_second`.
  void turn(double to, double degrees_per_second) {
    const double y = unwrap(to);
    const double seconds = std::abs(y - yaw()) / degrees_per_second;
    if (seconds < 1e-3) return;
    t += seconds;
    keys.push_back({t, at(), y});
  }
  // Moves to p at `speed`, facing `yaw` on arrival (turning while it moves).
  void move(const Vector3d& p, double speed, double to) {
    const double d = (p - at()).norm();
    if (d < 1e-6) return;
    t += d / speed;
    keys.push_back({t, p, unwrap(to)});
  }
  camera::Trajectory trajectory() const { return camera::Trajectory(keys); }
};

// Square pillars scattered over [-half, half]^2, none within `keep` of the path.
std::vector<camera::SolidBox> pillars(Draw& draw, int count, double half,
                                      const std::vector<Vector3d>& path, double keep) {
  std::vector<camera::SolidBox> boxes;
  for (int tries = 0; static_cast<int>(boxes.size()) < count && tries < 400; ++tries) {
    const double x = draw.between(-half, half), z = draw.between(-half, half);
    const double w = draw.between(0.2, 0.6), h = draw.between(2.5, 4.5);
    bool clear = true;
    for (std::size_t i = 0; i + 1 < path.size() && clear; ++i) {
      for (double u = 0; u <= 1.0 && clear; u += 0.05) {
        const Vector3d q = path[i] + u * (path[i + 1] - path[i]);
        const double dx = std::max(0.0, std::abs(q.x() - x) - w), dz = std::max(0.0, std::abs(q.z() - z) - w);
        clear = std::hypot(dx, dz) > keep;
      }
    }
    if (clear) boxes.push_back({"pillar", {{x - w, 0, z - w}, {x + w, h, z + w}}, {}});
  }
  return boxes;
}

camera::Scene strafe(std::uint64_t seed) {
  Draw draw(seed);
  const double speed = draw.between(2.5, 5.0), half = 12;
  std::vector<Vector3d> path{{0, 0, 0}};
  const int legs = draw.integer(5, 9);
  for (int i = 0; i < legs; ++i) {
    Vector3d next;
    do {
      next = Vector3d(draw.between(-half + 2, half - 2), 0, draw.between(-half + 2, half - 2));
    } while ((next - path.back()).norm() < 3);
    path.push_back(next);
  }
  // Each leg: facing the way (1 in 4), sideways (left or right) or diagonally.
  Keys keys(path[0], 0);
  int sideways = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double travel = yaw_of(path[i] - path[i - 1]);
    const int mode = draw.integer(0, 3);
    const double offset = mode == 0 ? 0 : mode == 1 ? 90 : mode == 2 ? -90 : (draw.chance(0.5) ? 45 : -45);
    sideways += mode != 0;
    keys.turn(travel + offset, 360);
    keys.move(path[i], speed, travel + offset);
  }
  auto boxes = pillars(draw, draw.integer(8, 20), half, path, 1.0);
  char text[160];
  std::snprintf(text, sizeof text, "strafing among %zu pillars: %d legs, %d sideways or diagonal, %.1f m/s",
                boxes.size(), legs, sideways, speed);
  return finish(family_scene_name("strafe", seed), text, std::move(boxes), keys.trajectory());
}

camera::Scene run(std::uint64_t seed) {
  // A zigzag of 6-10 corridor legs of 8-20 m (each turn 90 degrees), run at 6-8 m/s.
  Draw draw(seed);
  const double speed = draw.between(6, 8), thickness = 0.3;
  const int legs = draw.integer(6, 10);
  std::vector<Vector3d> dirs;
  for (int i = 0; i < legs; ++i) {
    dirs.push_back(i % 2 == 0 ? Vector3d(0, 0, 1) : Vector3d(draw.chance(0.5) ? 1 : -1, 0, 0));
  }
  std::vector<double> width;
  for (int i = 0; i < legs; ++i) width.push_back(draw.between(2, 4));
  std::vector<Vector3d> path{{0, 0, 0}};
  for (int i = 0; i < legs; ++i) {
    double length = draw.between(8, 20);
    if (i > 0 && i + 1 < legs) {
      length = std::max(length, width[i - 1] / 2 + width[i + 1] / 2 + 2 * thickness + 0.3);
    }
    path.push_back(path.back() + length * dirs[i]);
  }
  std::vector<Rect> open;
  for (int i = 0; i < legs; ++i) {
    const double before = i == 0 ? 3 : width[i - 1] / 2;
    const double after = i + 1 == legs ? 3 : width[i + 1] / 2;
    open.push_back(lane(path[i], path[i + 1], width[i], before, after));
  }
  std::vector<camera::SolidBox> boxes;
  const bool roof = draw.chance(0.4);
  const double height = roof ? draw.between(2.6, 3.5) : draw.between(2.5, 4);
  carve_walls(open, thickness, 0, height + (roof ? 0.2 : 0), boxes);
  if (roof) add_ceiling(open, thickness, height, boxes);
  // A runner turns while running: no stop at the corners (a quarter turn in 0.15 s).
  Keys keys(path[0], 0);
  for (int i = 0; i < legs; ++i) {
    keys.turn(yaw_of(dirs[i]), 600);
    keys.move(path[i + 1], speed, yaw_of(dirs[i]));
  }
  char text[160];
  std::snprintf(text, sizeof text, "running at %.1f m/s through a zigzag of %d legs %.1f-%.1f m wide, %s",
                speed, legs, *std::min_element(width.begin(), width.end()),
                *std::max_element(width.begin(), width.end()),
                roof ? "under a ceiling" : "open above");
  return finish(family_scene_name("run", seed), text, std::move(boxes), keys.trajectory());
}

camera::Scene reverse(std::uint64_t seed) {
  Draw draw(seed);
  const double width = draw.between(2.5, 5), walk = draw.between(1.4, 3), back = draw.between(1, 2);
  const double a = draw.between(6, 12), b = draw.between(3, 6), c = draw.between(4, 10);
  // Along +z: forward a, back b (facing +z), forward c, a 180 on the spot, back to the start.
  Keys keys({0, 0, 0}, 0);
  keys.move({0, 0, a}, walk, 0);
  keys.move({0, 0, a - b}, back, 0);
  keys.move({0, 0, a - b + c}, walk, 0);
  keys.turn(180, draw.between(400, 900));
  keys.move({0, 0, draw.between(-1, 2)}, walk, 180);
  const double far = a - b + c;
  std::vector<Rect> open{lane({0, 0, 0}, {0, 0, far}, width, 4, 4)};
  std::vector<camera::SolidBox> boxes;
  const bool roof = draw.chance(0.5);
  const double ceiling = draw.between(2.4, 3.5);
  carve_walls(open, 0.3, 0, roof ? ceiling + 0.2 : draw.between(2.5, 4), boxes);
  if (roof) add_ceiling(open, 0.3, ceiling, boxes);
  char text[200];
  std::snprintf(text, sizeof text,
                "backing up in a %.1f m corridor%s: %.1f m on at %.1f m/s, %.1f m back facing on at "
                "%.1f m/s, %.1f m on, a 180 on the spot and back",
                width, roof ? " with a ceiling" : "", a, walk, b, back, c);
  return finish(family_scene_name("reverse", seed), text, std::move(boxes), keys.trajectory());
}

camera::Scene vertical(std::uint64_t seed) {
  Draw draw(seed);
  const double step = draw.between(0.5, 1.0), rise = draw.between(0.6, 1.2);
  const double w = draw.between(3, 5), l1 = draw.between(2, 4), l2 = draw.between(4, 8);
  const double speed = draw.between(1.5, 3.5), climb = draw.between(0.35, 0.6);
  const double top = step + rise;
  // Along +z: ground, a ledge of `step` from z = 0, a platform of `top` from z = l1, its far
  // edge at z = l1 + l2, ground beyond (a drop of `top`).
  const double half = scene_building::kHalfBody;
  std::vector<camera::SolidBox> boxes{
      {"ledge", {{-w / 2, 0, 0}, {w / 2, step, l1}}, {}},
      {"platform", {{-w / 2, 0, l1}, {w / 2, top, l1 + l2}}, {}}};
  Keys keys({0, 0, -draw.between(3, 6)}, 0);
  keys.move({0, 0, -half}, speed, 0);                   // to the ledge's face
  keys.t += climb; keys.keys.push_back({keys.t, {0, step, -half}, 0});  // up
  keys.move({0, step, half}, speed, 0);                 // onto it
  keys.move({0, step, l1 - half}, speed, 0);            // to the platform's face
  keys.t += climb; keys.keys.push_back({keys.t, {0, top, l1 - half}, 0});
  keys.move({0, top, l1 + half}, speed, 0);
  keys.move({0, top, l1 + l2 + half}, speed, 0);        // the body past the edge
  const double fall = std::sqrt(2 * top / 9.81);
  keys.t += fall; keys.keys.push_back({keys.t, {0, 0, l1 + l2 + half + 0.3 * speed * fall}, 0});
  const double turn = draw.chance(0.5) ? 90 : -90;
  keys.move({0, 0, l1 + l2 + draw.between(3, 6)}, speed, 0);
  keys.turn(turn, 300);
  keys.move(keys.at() + draw.between(3, 6) * Vector3d(std::sin(turn * kPi / 180), 0, std::cos(turn * kPi / 180)), speed, turn);
  // Walls on either side at times: the camera cannot swing wide round the drop.
  if (draw.chance(0.5)) {
    const double wall = draw.between(2, 5);
    boxes.push_back({"wall", {{w / 2 + 1.0, 0, -6}, {w / 2 + 1.3, wall, l1 + l2 + 2}}, {}});
  }
  char text[200];
  std::snprintf(text, sizeof text,
                "climbing a %.2f m ledge and a %.2f m step onto a platform, dropping %.2f m off "
                "its edge (%.2f s fall), %.1f m/s",
                step, rise, top, fall, speed);
  return finish(family_scene_name("vertical", seed), text, std::move(boxes), keys.trajectory());
}

camera::Scene orbit(std::uint64_t seed) {
  Draw draw(seed);
  const double p = draw.between(0.4, 1.2), r = p * std::sqrt(2.0) + draw.between(0.7, 1.6);
  const double speed = draw.between(2, 4), laps = draw.chance(0.5) ? 1 : 2;
  const bool face_pillar = draw.chance(0.4);
  const double turn = draw.chance(0.5) ? 1 : -1;
  std::vector<camera::SolidBox> boxes{{"pillar", {{-p, 0, -p}, {p, draw.between(3, 6), p}}, {}}};
  if (draw.chance(0.5)) {  // a second pillar a little way off
    const double a = draw.between(0, 2 * kPi), d = r + draw.between(2, 4), q = draw.between(0.3, 0.8);
    boxes.push_back({"pillar", {{d * std::cos(a) - q, 0, d * std::sin(a) - q}, {d * std::cos(a) + q, 4, d * std::sin(a) + q}}, {}});
  }
  auto point = [&](double angle) { return Vector3d(r * std::cos(angle), 0, r * std::sin(angle)); };
  const double start = draw.between(0, 2 * kPi);
  // Walk in to the circle, then round it in 15-degree steps.
  const Vector3d in = point(start) + Vector3d(std::cos(start), 0, std::sin(start)) * draw.between(3, 6);
  auto facing = [&](double angle) {
    const Vector3d tangent(-std::sin(angle) * turn, 0, std::cos(angle) * turn);
    return face_pillar ? yaw_of(-point(angle)) : yaw_of(tangent);
  };
  Keys keys(in, yaw_of(point(start) - in));
  keys.move(point(start), speed, yaw_of(point(start) - in));
  keys.turn(facing(start), 360);
  const int steps = static_cast<int>(24 * laps);
  for (int i = 1; i <= steps; ++i) {
    const double angle = start + turn * i * kPi / 12;
    keys.move(point(angle), speed, facing(angle));
  }
  char text[200];
  std::snprintf(text, sizeof text, "%.0f lap%s round a %.1f m pillar at %.1f m, %.1f m/s, facing %s",
                laps, laps > 1 ? "s" : "", 2 * p, r, speed, face_pillar ? "the pillar" : "the way");
  // The second pillar must keep off the circle and the walk in.
  std::vector<camera::SolidBox> kept{boxes[0]};
  for (std::size_t i = 1; i < boxes.size(); ++i) {
    const camera::Aabb& b = boxes[i].box;
    bool clear = true;
    for (std::size_t k = 1; k < keys.keys.size(); ++k) {
      for (double u = 0; u <= 1.0; u += 0.05) {
        const Vector3d q = keys.keys[k - 1].position + u * (keys.keys[k].position - keys.keys[k - 1].position);
        const double dx = std::max({b.min.x() - q.x(), q.x() - b.max.x(), 0.0});
        const double dz = std::max({b.min.z() - q.z(), q.z() - b.max.z(), 0.0});
        clear = clear && std::hypot(dx, dz) > 1.0;
      }
    }
    if (clear) kept.push_back(boxes[i]);
  }
  return finish(family_scene_name("orbit", seed), text, std::move(kept), keys.trajectory());
}

camera::Scene tight_rooms(std::uint64_t seed) {
  Draw draw(seed);
  const int rooms = draw.integer(2, 3);
  const double ceiling = draw.between(2.2, 2.6), door = draw.between(0.9, 1.2), wall = 0.2;
  const double speed = draw.between(1.2, 3.0);
  std::vector<Rect> open;
  std::vector<Vector3d> path;
  double z = 0;
  for (int i = 0; i < rooms; ++i) {
    const double wx = draw.between(3, 4.5), wz = draw.between(3, 4.5);
    const Rect room{-wx / 2, z, wx / 2, z + wz};
    open.push_back(room);
    // Round the room near its walls (0.7 m in), then on to the door in its far wall.
    const double m = 0.7;
    const bool clockwise = draw.chance(0.5);
    std::vector<Vector3d> corners{{room.x0 + m, 0, room.z0 + m}, {room.x1 - m, 0, room.z0 + m},
                                  {room.x1 - m, 0, room.z1 - m}, {room.x0 + m, 0, room.z1 - m}};
    if (clockwise) std::reverse(corners.begin(), corners.end());
    path.push_back({0, 0, room.z0 + m});
    for (const Vector3d& c : corners) path.push_back(c);
    path.push_back({0, 0, room.z1 - m});
    if (i + 1 < rooms) {
      // A doorway through a wall `wall` thick, then the next room.
      open.push_back({-door / 2, room.z1 - 0.01, door / 2, room.z1 + wall + 0.01});
      z = room.z1 + wall;
    }
  }
  std::vector<camera::SolidBox> boxes;
  carve_walls(open, wall, 0, ceiling + 0.2, boxes);
  add_ceiling(open, wall, ceiling, boxes);
  char text[160];
  std::snprintf(text, sizeof text, "%d small rooms under a %.2f m ceiling, doorways %.2f m, %.1f m/s",
                rooms, ceiling, door, speed);
  return finish(family_scene_name("tight-rooms", seed), text, std::move(boxes), path, speed);
}

}  // namespace

std::string to_string(AgileFamily family) {
  switch (family) {
    case AgileFamily::kStrafe: return "strafe";
    case AgileFamily::kRun: return "run";
    case AgileFamily::kReverse: return "reverse";
    case AgileFamily::kVertical: return "vertical";
    case AgileFamily::kOrbit: return "orbit";
    case AgileFamily::kTightRooms: return "tight-rooms";
  }
  return "?";
}

const std::vector<AgileFamily>& all_agile_families() {
  static const std::vector<AgileFamily> all{AgileFamily::kStrafe,   AgileFamily::kRun,
                                            AgileFamily::kReverse,  AgileFamily::kVertical,
                                            AgileFamily::kOrbit,    AgileFamily::kTightRooms};
  return all;
}

camera::Scene generate_agile(AgileFamily family, std::uint64_t seed) {
  switch (family) {
    case AgileFamily::kStrafe: return strafe(seed);
    case AgileFamily::kRun: return run(seed);
    case AgileFamily::kReverse: return reverse(seed);
    case AgileFamily::kVertical: return vertical(seed);
    case AgileFamily::kOrbit: return orbit(seed);
    case AgileFamily::kTightRooms: return tight_rooms(seed);
  }
  throw std::logic_error("unknown agile family");
}

}  // namespace sightline::experiments
