// FrameParameters: the named per-frame numbers every camera constraint reads.
//
// The camera problem is re-parameterised every frame, never rebuilt: the controller writes
// the character's state, the look-at point, last frame's camera position, the frame interval
// and the (area-adapted) desired values into the problem's csp::Parameters, and each
// constraint reads them through the ParameterRefs below. The same names are visible to the
// profile's `extras` (an expression such as "char_y + 1 - cam_y" reads them live).
//
//   char_x char_y char_z     feet of the character, metres
//   char_yaw                 degrees (0 faces +z, 90 faces +x)
//   char_vx char_vy char_vz  velocity, metres per second
//   look_x look_y look_z     the point the camera aims at
//   last_cam_x .. _z         the camera position chosen last frame
//   dt                       seconds since last frame (> 0)
//   t                        simulation time, seconds
//   desired_height desired_distance desired_orientation   the profile's values, adapted to
//                            the area the character is in
//   clearance_radius         metres
#pragma once

#include <Eigen/Core>

#include "sightline/csp/parameters.h"

namespace sightline::camera {

// One frame's values, as FrameParameters::write stores them.
struct FrameValues {
  Eigen::Vector3d feet = Eigen::Vector3d::Zero();
  double yaw = 0;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d look_at = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_camera = Eigen::Vector3d::Zero();
  double dt = 1.0 / 60.0;
  double t = 0;
  double desired_height = 0, desired_distance = 0, desired_orientation = 0;
  double clearance_radius = 0.2;
};

struct FrameParameters {
  csp::ParameterRef char_x, char_y, char_z, char_yaw;
  csp::ParameterRef char_vx, char_vy, char_vz;
  csp::ParameterRef look_x, look_y, look_z;
  csp::ParameterRef last_cam_x, last_cam_y, last_cam_z;
  csp::ParameterRef dt, t;
  csp::ParameterRef desired_height, desired_distance, desired_orientation;
  csp::ParameterRef clearance_radius;

  // Adds every parameter above (named as in the header comment) to `table`, with neutral
  // values (dt = 1/60), and returns the handles. Throws std::invalid_argument if a name is
  // already taken.
  static FrameParameters add_to(csp::Parameters& table);
  // Writes one frame into `table` (the table given to add_to). O(1), no allocation.
  void write(csp::Parameters& table, const FrameValues& values) const;

  std::size_t first = 0;  // index of char_x; the others follow in the order above
};

}  // namespace sightline::camera
