// SphereProbe: sweeps a sphere along a segment through a scene and reports where it first
// touches a solid box: the "probe" of a game spring arm (Unreal's SweepSingleByChannel with a
// sphere shape), which the spring-arm baseline uses to pull the camera in front of walls.
//
// A sphere of radius r centred on the segment touches a box exactly when the segment enters
// the box grown by r with rounded edges and corners (the Minkowski sum). Two steps find that
// first contact exactly:
//   1. broad phase: the first hit of the segment against the boxes grown by r on every side
//      (square corners, a BoxTree built once here). The grown box contains the rounded one,
//      so the segment before that hit is certainly clear, and on a face the hit is exact;
//   2. from there, sphere tracing on the scene's signed distance d: the sphere centred at p
//      is clear when d(p) >= r, and since d changes by at most the distance moved (it is
//      1-Lipschitz), stepping by d(p) - r along the segment never passes through geometry.
//      Near an edge or corner of a grown box this walks on to the true (rounded) contact.
// A contact is reported to within `kContactTolerance` (except after kMaxTraceSteps, see
// there); every centre reported has d >= r up to rounding, so a camera placed there never
// sits inside geometry. Movers count: the probe asks a SceneAtTime, and its broad phase
// also meets the movers' boxes (at that time) grown by r.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "sightline/domains/camera/geometry/box_tree.h"
#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::camera {

class SphereProbe {
 public:
  static constexpr double kContactTolerance = 1e-7;  // metres
  // Sphere tracing converges slowly where the segment grazes a rounded edge (the gap shrinks
  // by little each step); after this many steps it stops, conservatively: the centre there
  // is clear, just short of where the true contact (or near miss) is.
  static constexpr int kMaxTraceSteps = 256;

  // `scene` must outlive the probe; the probe sees it at whatever time its owner set. radius
  // > 0 metres. Builds a BoxTree over the grown static boxes (allocates; once per camera,
  // not per frame).
  SphereProbe(const SceneAtTime& scene, double radius);

  double radius() const { return radius_; }
  // The segment parameter t in [0, 1] at which the sphere moving from `a` to `b` first
  // touches a box (0 when it already touches one at `a`), or nullopt when it reaches `b`
  // untouched. No allocation.
  std::optional<double> first_contact(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

 private:
  const SceneAtTime* scene_;
  double radius_;
  BoxTree grown_;
};

}  // namespace sightline::camera
