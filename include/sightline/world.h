// sightline/world.h: the camera's world, as an interface a game implements over its own
// physics.
//
// The camera asks its world five questions, each at a time t (seconds, on the clock the game
// passes to Camera::update) so that moving things can be placed: is the sight line a -> b
// clear, what does it hit first, how far is the nearest surface (signed: negative inside solid
// matter), which way is away from it, and is a point open space. A game answers them with its
// own ray casts and overlap/distance queries (PhysX, Jolt, Bullet, Chaos, Godot's physics
// server...); sightline answers them for its own geometry (make_geometry_world: boxes and
// triangles, through a bounding-volume tree and Embree) and for its experiment scenes.
//
// Only first_hit and clearance must be written; the others have correct defaults built on
// them, which a game may replace with faster ones (a boolean ray test for line_of_sight).
//
// Contract:
// - Units are metres and seconds; y is up (a game with z up swaps axes at the boundary).
// - The answers count everything that should block the camera and its view, and not the
//   bodies of the people the camera films: as a game's camera trace ignores the player's own
//   capsule. The people passed to Camera::update are placed by the camera itself.
// - A segment that starts inside solid matter or touches a surface is blocked.
// - Queries are const and called from the thread that calls Camera::update, several hundred
//   times a frame; they must not allocate if the frame budget matters. A world shared by
//   several cameras updated on several threads must answer concurrently.
// - An error (a physics query that failed) is reported by throwing; the camera passes it to
//   its caller (the C API turns it into an error code).
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sightline/vec3.h"

namespace sightline {

// What a segment a -> b hits first.
struct WorldHit {
  double fraction = 0;  // in [0, 1]: the hit is at a + fraction (b - a); 0 when a is inside
  Vec3 normal;          // unit normal facing a; zero when a is inside solid matter
};

// The nearest surface to a point.
struct NearestSurface {
  double signed_distance = 0;  // metres; negative inside solid matter
  Vec3 gradient;               // unit: the direction in which the distance grows fastest
};

class World {
 public:
  virtual ~World() = default;

  // The first surface on the segment a -> b at time t, or nullopt when the segment is clear.
  virtual std::optional<WorldHit> first_hit(const Vec3& a, const Vec3& b, double t) const = 0;
  // The signed distance from p to the nearest surface at time t, capped at `limit` (which may
  // be infinite): an answer of `limit` means "nothing nearer than limit". Negative inside solid
  // matter when the world knows inside from outside (0 or more otherwise).
  virtual double clearance(const Vec3& p, double limit, double t) const = 0;

  // True when nothing blocks a -> b at time t. Default: !first_hit(a, b, t).
  virtual bool line_of_sight(const Vec3& a, const Vec3& b, double t) const;
  // The nearest surface closer than `limit`, with the gradient of the signed distance (the
  // camera's smooth solvers use it); nullopt when nothing is that close. Default: clearance
  // and central differences of it (7 clearance queries).
  virtual std::optional<NearestSurface> nearest_surface(const Vec3& p, double limit,
                                                        double t) const;
  // False inside solid matter (every camera position must be open). Default: clearance(p, 0,
  // t) >= 0, a point on a surface being open.
  virtual bool open_at(const Vec3& p, double t) const;
};

// sightline's own geometry as a World: solid axis-aligned boxes and triangles. Triangles have
// no inside (a closed mesh is hollow for open_at), boxes do. Queries are O(log n), allocate
// nothing and are safe to call from several threads at once.
struct Box {
  Vec3 min, max;  // corners, min < max on every axis
};
struct WorldGeometry {
  std::vector<Box> boxes;
  std::vector<Vec3> vertices;           // metres, y up
  std::vector<unsigned> triangle_indices;  // three per triangle, into vertices
};

// Builds the world (the index is built here, once). Throws sightline::Error for NaN or
// infinite coordinates, an inverted box or an index past the vertices.
std::shared_ptr<const World> make_geometry_world(const WorldGeometry& geometry);

}  // namespace sightline
