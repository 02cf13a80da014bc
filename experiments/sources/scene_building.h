// Building blocks of the generated scene families (scene_families.h): a seeded draw, open
// rectangles and the walls carved round them, a walk through waypoints, and the checked
// scene. Kept apart so each generator reads as the layout it draws.
//
// Walls are carved: the open space is a union of rectangles, and the walls are the ring of a
// given thickness round it that lies in no rectangle, so corridors of different widths, rooms
// and junctions need no special cases.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"

namespace sightline::experiments::scene_building {

// The default character's half width (a 0.6 m square body).
constexpr double kHalfBody = 0.3;

// Uniform draws from one seeded generator.
struct Draw {
  explicit Draw(std::uint64_t seed) : rng(seed) {}
  double between(double lo, double hi) { return lo + (hi - lo) * unit(rng); }
  bool chance(double p) { return unit(rng) < p; }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  std::mt19937_64 rng;
  std::uniform_real_distribution<double> unit{0, 1};
};

// A rectangle of open ground (x, z).
struct Rect {
  double x0, z0, x1, z1;
  Rect grown(double by) const { return {x0 - by, z0 - by, x1 + by, z1 + by}; }
  bool holds(double x, double z) const { return x > x0 && x < x1 && z > z0 && z < z1; }
};

// The rectangle a walk from a to b (along x or z) sweeps with `width`, extended by `ea`
// behind a and `eb` beyond b.
Rect lane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double width, double ea, double eb);

// Walls of `thickness` round the union of `open`: every cell of the grid the rectangles'
// edges make that lies in some rectangle grown by `thickness` but in none of `open`, merged
// into boxes column by column, from y0 to y1; appended to `boxes`.
void carve_walls(const std::vector<Rect>& open, double thickness, double y0, double y1,
                 std::vector<camera::SolidBox>& boxes);

// A ceiling slab over each open rectangle (grown by the walls' thickness), its underside at y.
void add_ceiling(const std::vector<Rect>& open, double thickness, double y,
                 std::vector<camera::SolidBox>& boxes);

// Keyframes through `points` at `speed` (along the 3-D path), facing the way of travel in
// the ground plane (a vertical move keeps the yaw), turning on the spot at each waypoint at
// 225 deg/s (0.4 s for a quarter turn, at least 0.4 s).
camera::Trajectory walk(const std::vector<Eigen::Vector3d>& points, double speed);

// Starts the camera 4 m behind and 1 m above the look-at point at the first frame, drawn in
// toward it until it is clear (0.4 m, movers included where they stand then) and in sight;
// left as the scene's default when no such point is found. Every generated scene does this.
void place_camera_start(camera::Scene& scene);

// A generated scene's name: "<family>-seed-<seed>".
std::string family_scene_name(const char* family, std::uint64_t seed);

// The scene, checked: the body never overlaps a solid box at any frame (the scene reader's
// rule), no mover comes within 0.3 m of the body (std::logic_error otherwise: a generator
// bug); the camera starts 4 m behind and 1 m above the look-at point, drawn in toward it
// until clear and in sight.
camera::Scene finish(std::string name, std::string description, std::vector<camera::SolidBox> boxes,
                     const std::vector<Eigen::Vector3d>& path, double speed,
                     std::vector<camera::Mover> movers = {});

// The same for a trajectory made by hand (facing and timing of the generator's choosing:
// strafing, backing up, falling).
camera::Scene finish(std::string name, std::string description, std::vector<camera::SolidBox> boxes,
                     camera::Trajectory trajectory, std::vector<camera::Mover> movers = {});

}  // namespace sightline::experiments::scene_building
