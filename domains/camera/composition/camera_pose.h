// CameraPose and View: a camera's pose as FORMATS.md "Shots" defines it (position, look-at
// point, roll, vertical field of view, aspect) and the projection it makes.
//
// View axes: f = (a - p)/|a - p|; r0 = normalise(f x (0, 1, 0)); u0 = r0 x f;
// r = cos(roll) r0 + sin(roll) u0; u = cos(roll) u0 - sin(roll) r0. A point q with
// d = q - p and depth z = d.f is in front when z > 0.05 m and then projects to
// sx = (1 + (d.r) / (z tan(fov/2) aspect)) / 2, sy = (1 + (d.u) / (z tan(fov/2))) / 2:
// (0, 0) is the image's bottom-left corner, (1, 1) its top-right.
#pragma once

#include <Eigen/Core>
#include <optional>

namespace sightline::camera {

struct CameraPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d look_at = Eigen::Vector3d::UnitZ();
  double roll = 0;              // degrees
  double fov = 50;              // vertical field of view, degrees
  double aspect = 16.0 / 9.0;   // image width / height
};

// The pose's view direction from a yaw and a pitch in degrees (yaw 0 looks along +z, 90
// along +x, as a person's yaw; pitch > 0 looks up).
Eigen::Vector3d direction_from_yaw_pitch(double yaw_degrees, double pitch_degrees);

class View {
 public:
  static constexpr double kNearDepth = 0.05;  // metres: in front means deeper than this

  // nullopt for an invalid pose: the look-at point at the position, a vertical view
  // direction, a fov outside (0, 180) or an aspect <= 0, or anything not finite.
  static std::optional<View> of(const CameraPose& pose);

  const Eigen::Vector3d& position() const { return p_; }
  const Eigen::Vector3d& forward() const { return f_; }
  const Eigen::Vector3d& right() const { return r_; }
  const Eigen::Vector3d& up() const { return u_; }
  double depth(const Eigen::Vector3d& q) const { return (q - p_).dot(f_); }
  // The screen point of q, or nullopt when q is not in front (depth <= kNearDepth).
  // Inline: a shot's score projects every person's 27 samples once per property.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& q) const {
    const Eigen::Vector3d d = q - p_;
    const double z = d.dot(f_);
    if (!(z > kNearDepth)) return std::nullopt;
    return Eigen::Vector2d((1 + d.dot(r_) / (z * tan_half_ * aspect_)) / 2,
                           (1 + d.dot(u_) / (z * tan_half_)) / 2);
  }

 private:
  Eigen::Vector3d p_, f_, r_, u_;
  double tan_half_ = 1, aspect_ = 1;
};

}  // namespace sightline::camera
