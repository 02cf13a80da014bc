// vector3.h: the example's own 3-vector, as a game has its own math library.
//
// sightline's API takes its plain sightline::Vec3 (three doubles, no operators); a game
// converts its own vectors at that boundary, and so does this example (to_sightline,
// from_sightline).
#pragma once

#include <cmath>

#include "sightline/vec3.h"

namespace example {

struct V3 {
  double x = 0, y = 0, z = 0;

  double operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  double& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
};

inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(double s, const V3& v) { return {s * v.x, s * v.y, s * v.z}; }
inline double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length_squared(const V3& v) { return dot(v, v); }
inline double length(const V3& v) { return std::sqrt(dot(v, v)); }

inline V3 from_sightline(const sightline::Vec3& v) { return {v.x, v.y, v.z}; }
inline sightline::Vec3 to_sightline(const V3& v) { return {v.x, v.y, v.z}; }

}  // namespace example
