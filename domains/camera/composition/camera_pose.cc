#include "sightline/domains/camera/composition/camera_pose.h"

#include <Eigen/Geometry>
#include <cmath>

namespace sightline::camera {

namespace {
constexpr double kDegrees = 3.14159265358979323846 / 180.0;
}

Eigen::Vector3d direction_from_yaw_pitch(double yaw_degrees, double pitch_degrees) {
  const double yaw = yaw_degrees * kDegrees, pitch = pitch_degrees * kDegrees;
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

std::optional<View> View::of(const CameraPose& pose) {
  if (!pose.position.allFinite() || !pose.look_at.allFinite() || !std::isfinite(pose.roll) ||
      !(pose.fov > 0 && pose.fov < 180) || !(pose.aspect > 0) || !std::isfinite(pose.aspect)) {
    return std::nullopt;
  }
  const Eigen::Vector3d d = pose.look_at - pose.position;
  const double length = d.norm();
  if (!(length > 0)) return std::nullopt;
  View v;
  v.p_ = pose.position;
  v.f_ = d / length;
  const Eigen::Vector3d side = v.f_.cross(Eigen::Vector3d::UnitY());
  const double side_length = side.norm();
  if (!(side_length > 1e-12)) return std::nullopt;  // looking straight up or down
  const Eigen::Vector3d r0 = side / side_length;
  const Eigen::Vector3d u0 = r0.cross(v.f_);
  const double c = std::cos(pose.roll * kDegrees), s = std::sin(pose.roll * kDegrees);
  v.r_ = c * r0 + s * u0;
  v.u_ = c * u0 - s * r0;
  v.tan_half_ = std::tan(pose.fov * kDegrees / 2);
  v.aspect_ = pose.aspect;
  return v;
}

}  // namespace sightline::camera
