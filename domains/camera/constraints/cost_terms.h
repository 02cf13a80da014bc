// The chase camera's smooth cost terms, written once as templated functors.
//
// Each functor takes the values of its constraint's scope (in scope order) and the frame's
// parameters as plain doubles, and returns the term's signed residual r; the constraint's
// violation is |r| and its cost weight x |r| (Bourne & Sattar's equations, thesis tables
// 5-7). Written for any scalar T, the same code gives plain evaluation (T = double) and exact
// derivatives (T = ceres::Jet, in gradients.cc), as Ceres' AutoDiffCostFunction does.
//
// Where a term is not differentiable because the geometry degenerates (camera exactly above
// the character, camera not moving), the functor returns a constant: a zero (sub)gradient
// instead of the NaN that sqrt'(0) or atan2(0, 0) would give.
#pragma once

#include <cmath>

namespace sightline::camera::terms {

// The value part of a scalar: the number itself, or a Jet's value (member `a`).
inline double value_of(double x) { return x; }
template <class T>
double value_of(const T& jet) {
  return jet.a;
}

constexpr double kDegreesPerRadian = 57.295779513082320876798;

// Height (table 5, table 6):  r = Height_desired - (Camera_y - Character_y).
// Scope: (cam_y).
struct HeightTerm {
  double char_y;
  double desired;
  template <class T>
  T operator()(const T* cam_y) const {
    return T(desired) - (cam_y[0] - char_y);
  }
};

// Distance (table 5, table 6), horizontal only:
//   r = Distance_desired - sqrt((Camera_x - Character_x)^2 + (Camera_z - Character_z)^2).
// Scope: (cam_x, cam_z).
struct DistanceTerm {
  double char_x, char_z;
  double desired;
  template <class T>
  T operator()(const T* cam_xz) const {
    using std::sqrt;
    const T dx = cam_xz[0] - char_x;
    const T dz = cam_xz[1] - char_z;
    const T squared = dx * dx + dz * dz;
    if (value_of(squared) == 0) return T(desired);  // camera right above: sqrt'(0) is infinite
    return T(desired) - sqrt(squared);
  }
};

// Orientation (table 5): r = Orientation_desired - angle, the angle in degrees between the
// character's facing f = (sin yaw, 0, cos yaw) and the horizontal direction d from the camera
// to the character. The thesis takes acos of the normalised dot product; we compute the same
// angle as
//     angle = atan2(|f x d|_y, f . d),   (f x d)_y = f_z d_x - f_x d_z,
// which needs no normalisation and, unlike acos, keeps a bounded derivative (1 / horizontal
// distance, per radian) next to 0 and 180 degrees, where acos'(+-1) is infinite. At exactly
// 0 and 180 degrees the angle has a kink (|.| of the signed angle); its derivative there is
// a one-sided one, which is a valid subgradient. With the camera exactly above the
// character, d = 0 and the angle is undefined: it is then taken as 90 degrees, the mean
// angle over all directions, with zero gradient.
// Scope: (cam_x, cam_z).
struct OrientationTerm {
  double char_x, char_z;
  double char_yaw_degrees;
  double desired_degrees;
  template <class T>
  T operator()(const T* cam_xz) const {
    return at(facing(), cam_xz);
  }
  // The character's facing, (sin, cos) of her yaw: the same for every camera position, so a
  // search pricing many positions in one frame takes it once and calls at().
  struct Facing {
    double x, z;
  };
  Facing facing() const {
    const double yaw = char_yaw_degrees / kDegreesPerRadian;
    return {std::sin(yaw), std::cos(yaw)};
  }
  template <class T>
  T at(const Facing& facing, const T* cam_xz) const {
    using std::abs;
    using std::atan2;
    const double fx = facing.x;
    const double fz = facing.z;
    const T dx = char_x - cam_xz[0];
    const T dz = char_z - cam_xz[1];
    if (value_of(dx) == 0 && value_of(dz) == 0) return T(desired_degrees - 90.0);
    const T cross = fz * dx - fx * dz;
    const T dot = fx * dx + fz * dz;
    return T(desired_degrees) - atan2(abs(cross), dot) * kDegreesPerRadian;
  }
};

// Frame coherence (table 7): the camera's speed,
//   speed = |Camera - Camera_last_frame| / Frame_interval   (3-D distance, metres/second),
// which is already >= 0: the violation is the speed itself (the term has no desired value).
// Scope: (cam_x, cam_y, cam_z).
struct FrameCoherenceTerm {
  double last_x, last_y, last_z;
  double dt;  // seconds, > 0
  template <class T>
  T operator()(const T* cam) const {
    using std::sqrt;
    const T dx = cam[0] - last_x;
    const T dy = cam[1] - last_y;
    const T dz = cam[2] - last_z;
    const T squared = dx * dx + dy * dy + dz * dz;
    if (value_of(squared) == 0) return T(0.0);  // not moving: |.|'(0) has no single value
    return sqrt(squared) / dt;
  }
};

}  // namespace sightline::camera::terms
