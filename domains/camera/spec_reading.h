// Small typed readers shared by the scene and profile readers: numbers with a range, and
// 3-vectors. Each throws csp::InputError at the offending node saying what was expected.
#pragma once

#include <Eigen/Core>
#include <cstdio>
#include <string>

#include "sightline/csp/spec.h"

namespace sightline::camera::detail {

// A finite number; `what` describes it ("the frame rate (frames per second, > 0)").
inline double read_finite(const csp::Spec& field, const std::string& what) {
  return field.as_number(what);
}
// A finite number > 0.
inline double read_positive(const csp::Spec& field, const std::string& what) {
  const double v = field.as_number(what);
  if (!(v > 0)) field.fail("expected " + what + ", a number > 0, got " + field.preview());
  return v;
}
// A finite number >= 0.
inline double read_non_negative(const csp::Spec& field, const std::string& what) {
  const double v = field.as_number(what);
  if (!(v >= 0)) field.fail("expected " + what + ", a number >= 0, got " + field.preview());
  return v;
}
// A number as people write it: 0.5, 180, 1e-06.
inline std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}
// A finite number in [lo, hi] (or (lo, hi] when lo_open).
inline double read_in_range(const csp::Spec& field, const std::string& what, double lo,
                            double hi, bool lo_open = false) {
  const double v = field.as_number(what);
  if ((lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi)) {
    field.fail("expected " + what + ", a number in " + (lo_open ? "(" : "[") +
               format_number(lo) + ", " + format_number(hi) + "], got " + field.preview());
  }
  return v;
}
// [x, y, z]: a list of exactly three finite numbers.
inline Eigen::Vector3d read_vector3(const csp::Spec& field, const std::string& what) {
  const auto& items = field.items(what + " as [x, y, z]");
  if (items.size() != 3) {
    field.fail("expected " + what + " as [x, y, z] (3 numbers), got " + field.preview());
  }
  return {items[0].as_number("x of " + what), items[1].as_number("y of " + what),
          items[2].as_number("z of " + what)};
}

}  // namespace sightline::camera::detail
