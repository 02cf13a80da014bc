// ShotWorld: what a shot is measured against at one time: the people (the followed
// character under its name, then the actors), their boxes, aim points and yaws, and the
// solid geometry (boxes, movers, other people, the level or a game's world).
//
// Sight is FORMATS.md's rule for the `visible` property, not the chase camera's: a segment
// is blocked only by the *interior* of a box (touching a face, edge or corner does not
// block), by any level triangle, and never by the box of the person whose samples are
// looked at. set_time() re-places everyone without allocating.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sightline/domains/camera/geometry/aabb.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

struct PersonAtTime {
  std::string name;
  Aabb body;
  Eigen::Vector3d aim = Eigen::Vector3d::Zero();  // feet + look_at_height
  double yaw = 0;                                 // degrees
  int mover = -1;  // its mover in scene.movers() (an actor), or -1 (the followed character)
};

inline constexpr int kPersonSamples = 27;

// True when the closed segment a-b meets the open interior of `box`.
bool segment_enters_interior(const Aabb& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// The 27 points min + (i, j, k) (max - min), i, j, k in {0.1, 0.5, 0.9} (FORMATS.md).
std::array<Eigen::Vector3d, kPersonSamples> person_samples(const Aabb& body);

class ShotWorld {
 public:
  // `scene` must outlive the world. The followed character is a person when the scene has
  // one (named scene.character_name()).
  ShotWorld(const Scene& scene, double t);
  // Everyone where they are at t, or, with lead > 0, where they will be `lead` seconds
  // later if they keep their velocity at t (a forecast: a game knows no more).
  void set_time(double t, double lead = 0);
  double time() const { return t_; }
  const Scene& scene() const { return *scene_; }

  const std::vector<PersonAtTime>& people() const { return people_; }
  std::optional<int> find(const std::string& name) const;

  // The segment p-q passes through no solid geometry; person `own`'s box (an index into
  // people(), or -1) does not count.
  bool clear(const Eigen::Vector3d& p, const Eigen::Vector3d& q, int own) const;
  // Distance from p to the nearest solid geometry or person's box (< 0 inside a box),
  // `limit` when nothing is nearer.
  double clearance(const Eigen::Vector3d& p, double limit) const;

 private:
  const Scene* scene_;
  double t_ = 0;
  std::vector<PersonAtTime> people_;
  std::vector<Aabb> movers_;  // every mover's box at t_ (actors' included)
};

}  // namespace sightline::camera
