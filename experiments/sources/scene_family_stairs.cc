#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "sightline/experiments/sources/scene_building.h"
#include "sightline/experiments/sources/scene_families.h"

// The stairs family (scene_families.h): flights of stairs, straight, L or U with landings,
// walled or not, some under a ceiling, climbed or descended. In a file of its own because
// the steps, landings and the walk over them are most of it.
namespace sightline::experiments {

using Eigen::Vector3d;
using scene_building::add_ceiling;
using scene_building::carve_walls;
using scene_building::Draw;
using scene_building::family_scene_name;
using scene_building::finish;
using scene_building::kHalfBody;
using scene_building::Rect;
using scene_building::walk;

namespace {

// One flight of `steps` steps up along `d` (an axis) from `origin` (the foot of the flight,
// on its centre line, at floor height y0), `width` wide: solid steps from the ground up, and
// the walk up it. The body's front edge reaches each step as the feet reach its top, so the
// body never dips into a step (each point: front edge at the step's start, feet on its top).
void flight(const Vector3d& origin, const Vector3d& d, double width, int steps, double rise,
            double tread, std::vector<camera::SolidBox>& boxes, std::vector<Vector3d>& path) {
  const Vector3d l(std::abs(d.z()), 0, std::abs(d.x()));
  for (int j = 1; j <= steps; ++j) {
    const Vector3d p = origin + (j - 1) * tread * d - width / 2 * l;
    const Vector3d q = origin + j * tread * d + width / 2 * l;
    boxes.push_back({"step",
                     {{std::min(p.x(), q.x()), 0, std::min(p.z(), q.z())},
                      {std::max(p.x(), q.x()), origin.y() + j * rise, std::max(p.z(), q.z())}},
                     {}});
    path.push_back(origin + ((j - 1) * tread - kHalfBody) * d + Vector3d(0, j * rise, 0));
  }
}

Rect ground_rect(const Vector3d& a, const Vector3d& b) {
  return {std::min(a.x(), b.x()), std::min(a.z(), b.z()), std::max(a.x(), b.x()),
          std::max(a.z(), b.z())};
}

}  // namespace

// Two flights of stairs (6-14 steps each, rise 0.14-0.2 m, tread 0.25-0.35 m, 1.1-2.5 m
// wide): straight with a landing between, turning 90 degrees (an L) or 180 degrees (a U,
// a wall between the flights) on the landing; a floor on top. In 3 of 5 scenes walls round
// the whole stairwell, sometimes under a ceiling 2.2-3 m above the top floor. She climbs
// (descends in 2 of 5 scenes: the same walk reversed).
camera::Scene generate_stairs(std::uint64_t seed) {
  Draw draw(seed);
  const int kind = draw.integer(0, 2), n1 = draw.integer(6, 14), n2 = draw.integer(6, 14);
  const double rise = draw.between(0.14, 0.2), tread = draw.between(0.25, 0.35),
               width = draw.between(1.1, 2.5), speed = draw.between(1.0, 1.8);
  const double side = draw.chance(0.5) ? 1 : -1, before = draw.between(3, 6);
  std::vector<camera::SolidBox> boxes;
  std::vector<Rect> open;
  const Vector3d z(0, 0, 1), x(side, 0, 0);
  std::vector<Vector3d> path{{0, 0, -before}};
  open.push_back({-std::max(width / 2, 1.5), -before - 1, std::max(width / 2, 1.5), 0});
  path.push_back({0, 0, -kHalfBody - tread});  // level ground up to the first step
  flight({0, 0, 0}, z, width, n1, rise, tread, boxes, path);
  const double top1 = n1 * rise, end1 = n1 * tread;
  Vector3d origin2, d2;
  if (kind == 0) {
    const double landing = draw.between(1, 2.5);
    boxes.push_back({"landing", {{-width / 2, 0, end1}, {width / 2, top1, end1 + landing}}, {}});
    origin2 = {0, top1, end1 + landing};
    d2 = z;
    path.push_back(origin2 - (kHalfBody + tread) * d2);
  } else if (kind == 1) {
    boxes.push_back({"landing", {{-width / 2, 0, end1}, {width / 2, top1, end1 + width}}, {}});
    const Vector3d centre(0, top1, end1 + width / 2);
    path.push_back(centre);
    d2 = x;
    origin2 = centre + width / 2 * d2;
  } else {
    const double gap = 0.2, across = width + gap;
    const Vector3d far = Vector3d(0, 0, end1) + across * x;
    const Rect landing =
        ground_rect(Vector3d(0, 0, end1) - width / 2 * x, far + width / 2 * x + width * z);
    boxes.push_back({"landing", {{landing.x0, 0, landing.z0}, {landing.x1, top1, landing.z1}}, {}});
    const Rect divider = ground_rect(Vector3d(0, 0, 0) + width / 2 * x,
                                     Vector3d(0, 0, end1) + (width / 2 + gap) * x);
    boxes.push_back({"divider",
                     {{divider.x0, 0, divider.z0}, {divider.x1, top1 + n2 * rise + 1, divider.z1}},
                     {}});
    const Vector3d centre(0, top1, end1 + width / 2);
    path.push_back(centre);
    path.push_back(centre + across * x);
    d2 = -z;
    origin2 = Vector3d(far.x(), top1, end1);
  }
  flight(origin2, d2, width, n2, rise, tread, boxes, path);
  const double top2 = top1 + n2 * rise, floor_length = draw.between(4, 8);
  const Vector3d end2 = origin2 + n2 * tread * d2;
  const Vector3d l2(std::abs(d2.z()), 0, std::abs(d2.x()));
  // Beside a U's second flight lies the first: its floor keeps to the flight's width.
  const double floor_half = kind == 2 ? width / 2 : std::max(width / 2, 2.0);
  const Rect floor =
      ground_rect(end2 - floor_half * l2, end2 + floor_length * d2 + floor_half * l2);
  boxes.push_back({"floor", {{floor.x0, 0, floor.z0}, {floor.x1, top2, floor.z1}}, {}});
  path.push_back(Vector3d(end2.x(), top2, end2.z()) + (floor_length - 1.5) * d2);
  // The stairwell in plan: flights, landing and floor, for the walls round it.
  const std::size_t solid = boxes.size();
  for (std::size_t i = 0; i < solid; ++i) {
    const camera::Aabb& b = boxes[i].box;
    if (boxes[i].name != "divider") open.push_back({b.min.x(), b.min.z(), b.max.x(), b.max.z()});
  }
  const bool walls = draw.chance(0.6), ceiling = walls && draw.chance(0.5);
  const double headroom = draw.between(2.2, 3.0);
  if (walls) {
    carve_walls(open, 0.25, 0, top2 + (ceiling ? headroom + 0.2 : draw.between(1.5, 3.5)), boxes);
    if (ceiling) add_ceiling(open, 0.25, top2 + headroom, boxes);
  }
  const bool down = draw.chance(0.4);
  if (down) std::reverse(path.begin(), path.end());
  const char* kinds[] = {"straight", "L", "U"};
  char text[160];
  std::snprintf(text, sizeof text,
                "%s stairs %s, %d+%d steps of %.2f/%.2f m, %.1f m wide, %s, %.1f m/s", kinds[kind],
                down ? "down" : "up", n1, n2, rise, tread, width,
                !walls    ? "no walls"
                : ceiling ? "walled, ceiling"
                          : "walled",
                speed);
  return finish(family_scene_name("stairs", seed), text, std::move(boxes), path, speed);
}

}  // namespace sightline::experiments
