// LevelTransform: file units and axes -> the scene's metres with y up (FORMATS.md):
// a file point (x, y, z) becomes (s x, s y, s z) with `up: y`, and (s x, s z, -s y) with
// `up: z`. Quake III maps are in inches-like units with z up: scale 0.03125, up z (32 units
// to the metre; a player is 56 units tall, 1.75 m).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

namespace sightline::camera {

enum class UpAxis { kY, kZ };
// "y", "z".
const char* to_string(UpAxis up);
std::optional<UpAxis> up_axis_from_string(const std::string& text);

struct LevelTransform {
  double scale = 1;  // metres per file unit, > 0 and finite
  UpAxis up = UpAxis::kY;

  template <class Scalar>
  Eigen::Matrix<Scalar, 3, 1> to_scene(const Eigen::Matrix<Scalar, 3, 1>& file) const {
    const auto s = static_cast<Scalar>(scale);
    if (up == UpAxis::kY) return s * file;
    return {s * file.x(), s * file.z(), -s * file.y()};
  }
  template <class Scalar>
  Eigen::Matrix<Scalar, 3, 1> to_file(const Eigen::Matrix<Scalar, 3, 1>& scene) const {
    const auto inv = static_cast<Scalar>(1.0 / scale);
    if (up == UpAxis::kY) return inv * scene;
    return {inv * scene.x(), -inv * scene.z(), inv * scene.y()};
  }
};

}  // namespace sightline::camera
