// Conversions between the public API's plain vectors and the library's Eigen vectors.
#pragma once

#include <Eigen/Core>

#include "sightline/vec3.h"

namespace sightline {

inline Eigen::Vector3d to_eigen(const Vec3& v) { return {v.x, v.y, v.z}; }
inline Vec3 to_vec3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace sightline
