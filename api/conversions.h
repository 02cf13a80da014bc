// Conversions between the public API's plain vectors and the library's Eigen vectors, and
// the check every public entry point makes of them.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "sightline/vec3.h"

namespace sightline {

inline Eigen::Vector3d to_eigen(const Vec3& v) { return {v.x, v.y, v.z}; }
inline Vec3 to_vec3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace sightline
