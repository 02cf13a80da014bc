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
#include <algorithm>
#include <array>
#include <limits>
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
// Inline: a shot's `visible` properties test every sample's sight line against each box near.
inline bool segment_enters_interior(const Aabb& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // The points a + t (b - a), t in [0, 1], strictly inside every slab: the open intervals
  // (enter_i, leave_i) of t meet in (enter, leave), which meets [0, 1] iff enter < leave,
  // leave > 0 and enter < 1.
  double enter = -std::numeric_limits<double>::infinity();
  double leave = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double d = b[i] - a[i];
    if (d == 0) {
      if (!(box.min[i] < a[i] && a[i] < box.max[i])) return false;
      continue;
    }
    double t0 = (box.min[i] - a[i]) / d, t1 = (box.max[i] - a[i]) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter < leave && leave > 0 && enter < 1;
}

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
  // How many of person `own`'s samples (person_samples of their body) are clear() from p,
  // counting at most `enough` when it is > 0 (then stopping there). The same answer as
  // clear() sample by sample, faster: the boxes that can block any of the sight lines (those
  // touching the box round p and the body) are gathered once for all of them.
  int count_clear(const Eigen::Vector3d& p, int own, int enough = 0) const;
  // Distance from p to the nearest solid geometry or person's box (< 0 inside a box),
  // `limit` when nothing is nearer.
  double clearance(const Eigen::Vector3d& p, double limit) const;

 private:
  // Calls visit(const Aabb&) for each box that may hide person `own`'s samples (or
  // anything, own -1) along a segment lying in `span`: the movers touching it but own's,
  // the followed character's box unless own is the character, and, when the scene has no
  // world of its own (which answers for its solids), the scene's solid boxes touching it.
  template <class Visit>
  void for_each_box_near(const Aabb& span, int own, Visit&& visit) const;
  // The segment p-q meets no surface of the scene's world, or of its level (triangles).
  bool surfaces_clear(const Eigen::Vector3d& p, const Eigen::Vector3d& q) const;

  const Scene* scene_;
  double t_ = 0;
  std::vector<PersonAtTime> people_;
  std::vector<Aabb> movers_;  // every mover's box at t_ (actors' included)
};

}  // namespace sightline::camera
