#include "sightline/experiments/sources/scene_families.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

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
using scene_building::walk;

namespace {

// A ceiling for corridors and junctions: none (walls 2.5-4 m, open above) in 2 of 5 scenes,
// low (2.2-3 m: the camera's 2.5 m height above the feet cannot be met) in 2 of 5, higher
// (3-4.5 m) in the rest. Returns {wall height, ceiling height or 0}.
std::pair<double, double> draw_ceiling(Draw& draw) {
  const double u = draw.between(0, 1);
  if (u < 0.4) return {draw.between(2.5, 4), 0};
  const double h = u < 0.8 ? draw.between(2.2, 3.0) : draw.between(3.0, 4.5);
  return {h + 0.2, h};
}

void build(const std::vector<Rect>& open, double thickness, std::pair<double, double> heights,
           std::vector<camera::SolidBox>& boxes) {
  carve_walls(open, thickness, 0, heights.first, boxes);
  if (heights.second > 0) add_ceiling(open, thickness, heights.second, boxes);
}

std::string ceiling_text(std::pair<double, double> heights) {
  char text[64];
  if (heights.second > 0) {
    std::snprintf(text, sizeof text, "ceiling %.2f m", heights.second);
  } else {
    std::snprintf(text, sizeof text, "open above walls %.1f m", heights.first);
  }
  return text;
}

}  // namespace

std::string to_string(SceneFamily family) {
  switch (family) {
    case SceneFamily::kCorridor:
      return "corridor";
    case SceneFamily::kJunction:
      return "junction";
    case SceneFamily::kRooms:
      return "rooms";
    case SceneFamily::kColonnade:
      return "colonnade";
    case SceneFamily::kTraffic:
      return "traffic";
    case SceneFamily::kStairs:
      return "stairs";
  }
  return "?";
}

const std::vector<SceneFamily>& all_scene_families() {
  static const std::vector<SceneFamily> all{SceneFamily::kCorridor, SceneFamily::kJunction,
                                            SceneFamily::kRooms,    SceneFamily::kColonnade,
                                            SceneFamily::kTraffic,  SceneFamily::kStairs};
  return all;
}

camera::Scene generate_family(SceneFamily family, std::uint64_t seed) {
  switch (family) {
    case SceneFamily::kCorridor:
      return generate_corridor(seed);
    case SceneFamily::kJunction:
      return generate_junction(seed);
    case SceneFamily::kRooms:
      return generate_rooms(seed);
    case SceneFamily::kColonnade:
      return generate_colonnade(seed);
    case SceneFamily::kTraffic:
      return generate_traffic(seed);
    case SceneFamily::kStairs:
      return generate_stairs(seed);
  }
  throw std::logic_error("unknown scene family");
}

// Legs along +z and x (each turn 90 degrees): an L (two legs), a U (+z, across, -z) or a
// zigzag (4-6 legs, +z between legs across in either direction). Each leg has its own
// width; legs that run side by side are kept a wall apart.
camera::Scene generate_corridor(std::uint64_t seed) {
  Draw draw(seed);
  const int kind = draw.integer(0, 2);
  const double thickness = draw.between(0.2, 0.4), speed = draw.between(1.2, 2.5);
  std::vector<Vector3d> dirs;
  const double side = draw.chance(0.5) ? 1 : -1;
  if (kind == 0) dirs = {{0, 0, 1}, {side, 0, 0}};
  if (kind == 1) dirs = {{0, 0, 1}, {side, 0, 0}, {0, 0, -1}};
  if (kind == 2) {
    const int legs = draw.integer(4, 6);
    for (int i = 0; i < legs; ++i) {
      dirs.push_back(i % 2 == 0 ? Vector3d(0, 0, 1) : Vector3d(draw.chance(0.5) ? 1 : -1, 0, 0));
    }
  }
  std::vector<double> width;
  for (std::size_t i = 0; i < dirs.size(); ++i) width.push_back(draw.between(1.5, 4));
  std::vector<Vector3d> path{{0, 0, 0}};
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    double length = draw.between(4, 14);
    // A leg between two others must part them by a wall: theirs are parallel.
    if (i > 0 && i + 1 < dirs.size()) {
      length = std::max(length, width[i - 1] / 2 + width[i + 1] / 2 + 2 * thickness + 0.3);
    }
    path.push_back(path.back() + length * dirs[i]);
  }
  std::vector<Rect> open;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const double before = i == 0 ? draw.between(0.5, 6) : width[i - 1] / 2;
    const double after = i + 1 == dirs.size() ? draw.between(0.5, 4) : width[i + 1] / 2;
    open.push_back(lane(path[i], path[i + 1], width[i], before, after));
  }
  const auto heights = draw_ceiling(draw);
  std::vector<camera::SolidBox> boxes;
  build(open, thickness, heights, boxes);
  const char* kinds[] = {"L turn", "U turn", "zigzag"};
  char text[160];
  std::snprintf(text, sizeof text, "%s corridor, %zu legs %.1f-%.1f m wide, %s, %.1f m/s",
                kinds[kind], dirs.size(), *std::min_element(width.begin(), width.end()),
                *std::max_element(width.begin(), width.end()), ceiling_text(heights).c_str(),
                speed);
  return finish(family_scene_name("corridor", seed), text, std::move(boxes), path, speed);
}

// A T met from its stem (she turns left or right), a T met along its bar (she turns into the
// stem), or an X (she turns left or right); every arm of its own width. She may walk on to a
// second corner (an L) after the junction.
camera::Scene generate_junction(std::uint64_t seed) {
  Draw draw(seed);
  const int kind = draw.integer(0, 2);
  const double thickness = draw.between(0.2, 0.4), speed = draw.between(1.2, 2.5);
  const double w_stem = draw.between(1.5, 4), w_bar = draw.between(1.5, 4),
               w_far = draw.between(1.5, 4);
  const double south = draw.between(6, 14), west = draw.between(5, 12), east = draw.between(5, 12),
               north = draw.between(5, 12);
  const double side = draw.chance(0.5) ? 1 : -1;
  std::vector<Rect> open;
  std::vector<Vector3d> path;
  if (kind == 1) {
    // Along the bar (z) and into the stem going +x or -x.
    open.push_back({-w_bar / 2, -south, w_bar / 2, north});
    open.push_back(side > 0 ? Rect{0, -w_stem / 2, east, w_stem / 2}
                            : Rect{-west, -w_stem / 2, 0, w_stem / 2});
    path = {{0, 0, -south + draw.between(0.5, 4)},
            {0, 0, 0},
            {side * ((side > 0 ? east : west) - 1.5), 0, 0}};
  } else {
    // Up the stem (z) to the bar (x), turning left or right; an X has the stem go on north.
    open.push_back({-w_stem / 2, -south, w_stem / 2, kind == 2 ? north : 0});
    open.push_back({-west, -w_bar / 2, east, w_bar / 2});
    if (kind == 2) open.push_back({-w_far / 2, 0, w_far / 2, north});
    path = {{0, 0, -south + draw.between(0.5, 4)},
            {0, 0, 0},
            {side * ((side > 0 ? east : west) - 1.5), 0, 0}};
  }
  // Half the time the arm she takes ends in a corner she turns too.
  if (draw.chance(0.5)) {
    const Vector3d end = path.back();
    const double w_arm = kind == 1 ? w_stem : w_bar, w_next = draw.between(1.5, 4);
    const double turn = draw.chance(0.5) ? 1 : -1, length = draw.between(4, 10);
    const Vector3d corner = end + Vector3d(side * (1.5 - w_next / 2 - 0.1), 0, 0);
    const Vector3d next = corner + Vector3d(0, 0, turn * length);
    path.back() = corner;
    path.push_back(next);
    open.push_back(lane(corner, next, w_next, w_arm / 2, draw.between(0.5, 3)));
  }
  const auto heights = draw_ceiling(draw);
  std::vector<camera::SolidBox> boxes;
  build(open, thickness, heights, boxes);
  const char* kinds[] = {"T from the stem", "T along the bar", "X"};
  char text[160];
  std::snprintf(text, sizeof text, "%s junction, arms %.1f/%.1f/%.1f m wide, %s, %.1f m/s",
                kinds[kind], w_stem, w_bar, w_far, ceiling_text(heights).c_str(), speed);
  return finish(family_scene_name("junction", seed), text, std::move(boxes), path, speed);
}

// Rooms of 3.5-9 m a side, each joined to the last through a doorway (0.9-1.6 m wide) in a
// wall of 0.2-0.4 m, on its north or its east side; a corridor stub before the first and
// after the last. She enters, crosses each room (sometimes by a point inside it), leaves.
camera::Scene generate_rooms(std::uint64_t seed) {
  Draw draw(seed);
  const double t = draw.between(0.2, 0.4), speed = draw.between(1.2, 2.5);
  const int rooms = draw.integer(2, 4);
  // Doorway k leads from room k-1 (the stub for k = 0) into room k, across +z (north) or +x.
  struct Door {
    bool north;
    double centre, width, wall;  // centre across the wall; `wall` = the wall's near face
  };
  std::vector<Rect> open;
  std::vector<Door> doors;
  Rect room{0, 0, draw.between(3.5, 9), draw.between(3.5, 9)};
  const double len = draw.between(4, 7);  // the stub before the first doorway
  {
    const double dw = draw.between(0.9, 1.6), sw = draw.between(1.8, 3);
    const double c = draw.between(room.x0 + dw / 2 + 0.4, room.x1 - dw / 2 - 0.4);
    open.push_back({c - sw / 2, -t - len, c + sw / 2, -t});
    doors.push_back({true, c, dw, -t});
  }
  open.push_back(room);
  for (int k = 1; k <= rooms; ++k) {
    const bool north = draw.chance(0.5), last = k == rooms;
    const double dw = draw.between(0.9, 1.6);
    // Across the wall: the next room's span overlaps this room's by at least dw + 0.8 and
    // starts no lower, so rooms never overlap earlier ones.
    const double lo = north ? room.x0 : room.z0, hi = north ? room.x1 : room.z1;
    const double span = last ? draw.between(1.8, 3) : draw.between(3.5, 9);
    double from = last ? 0 : draw.between(lo, std::max(lo, hi - dw - 0.8));
    if (last) {
      const double c = draw.between(lo + dw / 2 + 0.4, hi - dw / 2 - 0.4);
      from = c - span / 2;
    }
    const double a = std::max(lo, from) + dw / 2 + 0.4,
                 b = std::min(hi, from + span) - dw / 2 - 0.4;
    const double c = last ? from + span / 2 : draw.between(a, std::max(a, b));
    const double wall = north ? room.z1 : room.x1;
    const double depth = last ? draw.between(4, 7) : draw.between(3.5, 9);
    const Rect next = north ? Rect{from, wall + t, from + span, wall + t + depth}
                            : Rect{wall + t, from, wall + t + depth, from + span};
    doors.push_back({north, c, dw, wall});
    open.push_back(next);
    room = next;
  }
  for (const Door& d : doors) {
    open.push_back(d.north
                       ? Rect{d.centre - d.width / 2, d.wall, d.centre + d.width / 2, d.wall + t}
                       : Rect{d.wall, d.centre - d.width / 2, d.wall + t, d.centre + d.width / 2});
  }
  // The walk: 0.8 m before and after each doorway, straight across it; in between, inside
  // one room (convex), sometimes by a point 1 m or more from its walls.
  auto at = [&](const Door& d, double offset) {
    return d.north ? Vector3d(d.centre, 0, d.wall + offset)
                   : Vector3d(d.wall + offset, 0, d.centre);
  };
  std::vector<Vector3d> path{at(doors[0], -draw.between(2.5, len - 0.5))};
  for (std::size_t k = 0; k < doors.size(); ++k) {
    path.push_back(at(doors[k], -0.8));
    path.push_back(at(doors[k], t + 0.8));
    const Rect& r = open[k + 1];
    if (k + 1 < doors.size() && r.x1 - r.x0 > 2.5 && r.z1 - r.z0 > 2.5 && draw.chance(0.5)) {
      path.push_back({draw.between(r.x0 + 1, r.x1 - 1), 0, draw.between(r.z0 + 1, r.z1 - 1)});
    }
  }
  path.push_back(at(doors.back(), t + draw.between(2.5, 3.5)));
  std::pair<double, double> heights{draw.between(2.5, 4), 0};
  if (draw.chance(0.5)) {
    heights.second = draw.between(2.3, 3.5);
    heights.first = heights.second + 0.2;
  }
  std::vector<camera::SolidBox> boxes;
  build(open, t, heights, boxes);
  char text[160];
  std::snprintf(text, sizeof text, "%d rooms joined by doorways, walls %.2f m, %s, %.1f m/s", rooms,
                t, ceiling_text(heights).c_str(), speed);
  return finish(family_scene_name("rooms", seed), text, std::move(boxes), path, speed);
}

// A row of columns along z at random spacing (gaps 0.6-4 m, columns 0.3-1 m square), a
// second row or a wall on the other side, sometimes a roof over the walk between them. She
// walks along the inside and, through gaps of 1.3 m or more, steps out to walk outside the
// row and back in.
camera::Scene generate_colonnade(std::uint64_t seed) {
  Draw draw(seed);
  const double length = draw.between(20, 40), speed = draw.between(1.2, 2.5);
  const double row = draw.between(1.5, 3), other = draw.between(1.5, 3);
  const double outside = row + draw.between(1.5, 3);
  const bool roof = draw.chance(0.4), second_row = draw.chance(0.5);
  const double top = roof ? draw.between(3, 5) : 0;
  std::vector<camera::SolidBox> boxes;
  std::vector<double> gaps;  // middles of gaps wide enough to walk through
  double z = -draw.between(0, 3);
  double previous_face = -1e9;
  while (z < length + 4) {
    const double s = draw.between(0.3, 1.0), h = roof ? top : draw.between(3, 6);
    if (z - previous_face >= 1.3 && z > 2 && z < length - 2)
      gaps.push_back((z + previous_face) / 2);
    boxes.push_back({"column", {{row - s / 2, 0, z}, {row + s / 2, h, z + s}}, {}});
    previous_face = z + s;
    z += s + draw.between(0.6, 4);
  }
  if (second_row) {
    for (double zc = -draw.between(0, 3); zc < length + 4;) {
      const double s = draw.between(0.3, 1.0);
      boxes.push_back(
          {"column",
           {{-other - s / 2, 0, zc}, {-other + s / 2, roof ? top : draw.between(3, 6), zc + s}},
           {}});
      zc += s + draw.between(0.6, 4);
    }
  } else {
    boxes.push_back(
        {"wall", {{-other - 0.3, 0, -5}, {-other, draw.between(3, 8), length + 5}}, {}});
  }
  if (roof)
    boxes.push_back({"roof", {{-other - 0.6, top, -5}, {row + 0.6, top + 0.3, length + 5}}, {}});
  std::vector<Vector3d> path{{0, 0, 0}};
  bool out = false;
  double last_switch = 0;
  for (double g : gaps) {
    if (g - last_switch < 4 || !draw.chance(0.35)) continue;
    path.push_back({out ? outside : 0, 0, g});
    out = !out;
    path.push_back({out ? outside : 0, 0, g});
    last_switch = g;
  }
  path.push_back({out ? outside : 0, 0, length});
  char text[160];
  std::snprintf(text, sizeof text, "colonnade %.0f m, %s, %zu lane changes, %s, %.1f m/s", length,
                second_row ? "two rows" : "a row and a wall", (path.size() - 2) / 2,
                roof ? "roofed" : "open", speed);
  return finish(family_scene_name("colonnade", seed), text, std::move(boxes), path, speed);
}

// A street along z between rows of buildings, side streets across it. She walks along a
// pavement and sometimes crosses the street. Vehicles (cars, vans, buses) drive along the
// street and along the side streets; those on side streets cross just behind her, between a
// chase camera and her; a few people cross her pavement behind her. No mover comes within
// 0.3 m of her (one that would is drawn again, at most 50 times, then left out).
camera::Scene generate_traffic(std::uint64_t seed) {
  Draw draw(seed);
  const double road = draw.between(3, 5), pavement = draw.between(2, 4),
               speed = draw.between(1.2, 2.2);
  const double length = draw.between(50, 80), face = road + pavement;
  std::vector<camera::SolidBox> boxes;
  std::vector<double> side_streets;  // centre lines (z)
  std::vector<double> side_widths;
  for (double z = -10; z < length + 10;) {
    const double block = draw.between(12, 30), street = draw.between(6, 9);
    for (double s : {-1.0, 1.0}) {
      const double x0 = s > 0 ? face : -face - 12;
      boxes.push_back({"building", {{x0, 0, z}, {x0 + 12, draw.between(6, 25), z + block}}, {}});
    }
    z += block + street;
    side_streets.push_back(z - street / 2);
    side_widths.push_back(street);
  }
  const double lane_x = face - pavement / 2;
  std::vector<Vector3d> path{{lane_x, 0, 0}};
  double x = lane_x;
  for (double z = draw.between(8, 20); z < length - 8; z += draw.between(10, 25)) {
    if (!draw.chance(0.5)) continue;
    path.push_back({x, 0, z});
    x = -x;
    path.push_back({x, 0, z});
  }
  path.push_back({x, 0, length});
  const camera::Scene walk_only("walk", boxes, {}, camera::CharacterShape{}, walk(path, speed), 60);
  const double t1 = walk_only.trajectory().end_time();
  auto misses_her = [&](const camera::Mover& m) {
    for (double t = 0; t <= t1; t += 1.0 / 30) {
      const camera::Aabb body = walk_only.character().body_at(walk_only.character_at(t).position);
      const camera::Aabb box = m.box_at(t);
      const double gap = std::max({box.min.x() - body.max.x(), body.min.x() - box.max.x(),
                                   box.min.z() - body.max.z(), body.min.z() - box.max.z()});
      if (gap < 0.45) return false;
    }
    return true;
  };
  const Vector3d kinds[] = {{4.5, 1.5, 1.9}, {5.5, 2.6, 2.1}, {12, 3.2, 2.5}};
  std::vector<camera::Mover> movers;
  const int count = draw.integer(8, 16);
  for (int i = 0; i < count; ++i) {
    for (int attempt = 0; attempt < 50; ++attempt) {
      const int what = draw.integer(0, 9);  // 0-4 along the street, 5-7 a side street, 8-9 a person
      const double v = what < 8 ? draw.between(5, 13) : draw.between(0.8, 1.8);
      std::vector<camera::MoverKeyframe> keys;
      Vector3d size;
      if (what < 5) {
        const Vector3d k = kinds[draw.integer(0, 2)];
        size = {k.z(), k.y(), k.x()};
        // Right-hand traffic: the lane's centre half the road's half-width from the middle.
        const double dir = draw.chance(0.5) ? 1 : -1, lx = dir * road / 2;
        const double start = draw.between(-20, t1);
        keys = {{start, {lx, 0, dir > 0 ? -30 : length + 30}},
                {start + (length + 60) / v, {lx, 0, dir > 0 ? length + 30 : -30}}};
      } else {
        // Across her back line: a side street she has just passed (2-4 m behind her), or a
        // person crossing her pavement there.
        const double when = draw.between(1, t1 - 1);
        const camera::CharacterState c = walk_only.character_at(when);
        std::size_t k = 0;
        double behind = 1e9;
        for (std::size_t s = 0; s < side_streets.size(); ++s) {
          const double d = c.position.z() - side_streets[s];
          if (d > 0 && d < behind) behind = d, k = s;
        }
        double zc = c.position.z() - draw.between(2, 4);
        if (what < 8) {
          if (behind > 6) continue;  // no side street just behind her now
          const Vector3d kk = kinds[draw.integer(0, 1)];
          size = kk;
          zc = side_streets[k] + draw.between(-1, 1) * (side_widths[k] / 2 - kk.z() / 2 - 0.3);
        } else {
          size = {0.5, draw.between(1.6, 1.95), 0.5};
        }
        // A vehicle drives the side street's whole width of town; a person walks from the
        // building's face out into the road, or back.
        const double dir = draw.chance(0.5) ? 1 : -1, side = c.position.x() > 0 ? 1 : -1;
        const double half = what < 8 ? 40 : draw.between(2, 4);
        const double xc = what < 8 ? 0 : side * (face - 0.6 - half);
        keys = {{when - half / v, {xc - dir * half, 0, zc}},
                {when + half / v, {xc + dir * half, 0, zc}}};
      }
      camera::Mover m((what < 8 ? "vehicle-" : "person-") + std::to_string(i), size, keys);
      if (!misses_her(m)) continue;
      movers.push_back(std::move(m));
      break;
    }
  }
  char text[160];
  std::snprintf(text, sizeof text,
                "street %.0f m, road %.1f m, pavement %.1f m, %zu movers, %zu crossings, %.1f m/s",
                length, 2 * road, pavement, movers.size(), (path.size() - 2) / 2, speed);
  return finish(family_scene_name("traffic", seed), text, std::move(boxes), path, speed, std::move(movers));
}

}  // namespace sightline::experiments
