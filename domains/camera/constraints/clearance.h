// ClearanceConstraint: the camera, a sphere of radius r (default 0.2 m, about a near-plane
// distance), must not touch any solid box or level triangle, so it never sits in a wall and
// never sees both sides of one.
//
//   violation = max(0, r - d(camera)),   d = Scene::clearance: signed distance to the
//                                            nearest solid surface
//
// d is negative inside a box (minus the depth to its nearest face) and inside a level's
// solid volume (minus the distance to the nearest face), so the violation keeps
// growing the deeper the camera is inside geometry and search is led back out; it is 0 when
// the sphere is clear or exactly tangent. The BVH query is bounded by r, so a camera in the
// open costs little more than the root test. Hard by default. The gradient is exact almost
// everywhere: -grad d, where grad d is the unit vector from the nearest point of the nearest
// surface (outside) or the outward normal of the nearest box face (inside a box);
// Scene::nearest_surface computes both.
// Movers count, at the time of the SceneAtTime the constraint reads (the frame's time).
// Scope (cam_x, cam_y, cam_z); radius from the frame parameter clearance_radius.
#pragma once

#include "sightline/csp/constraint.h"
#include "sightline/domains/camera/constraints/frame_parameters.h"
#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::camera {

class ClearanceConstraint : public csp::Constraint {
 public:
  ClearanceConstraint(csp::VariableId cam_x, csp::VariableId cam_y, csp::VariableId cam_z,
                      const SceneAtTime& scene, const FrameParameters& frame, double weight = 1,
                      bool hard = true)
      : Constraint({cam_x, cam_y, cam_z}, weight, hard), scene_(&scene), frame_(frame) {}
  std::string_view kind() const override { return "camera.clearance"; }
  double query_cost() const override { return 4; }  // a nearest-surface query
  double violation(std::span<const double> values) const override;
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override;
  // smooth_hinge(r - d, s): 0 where the sphere is clear, C1 everywhere.
  double smooth_violation_and_gradient(std::span<const double> values, std::span<double> gradient,
                                       double smoothing) const override;

 private:
  // Writes d violation / d (r - d) times grad(r - d) = -slope x grad d into gradient.
  double evaluate(std::span<const double> values, std::span<double> gradient,
                  double smoothing) const;
  const SceneAtTime* scene_;
  FrameParameters frame_;
};

// The gradient of Aabb::signed_distance at p (a unit vector; on a tie between faces or at
// the surface, one valid choice).
Eigen::Vector3d signed_distance_gradient(const Aabb& box, const Eigen::Vector3d& p);

}  // namespace sightline::camera
