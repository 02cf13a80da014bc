// sightline/vec3.h: the plain 3-vector of sightline's public API, and its error type.
//
// The public headers name no third-party type: a game converts its own vectors at the
// boundary (three doubles, metres, y up).
#pragma once

#include <stdexcept>
#include <string>

namespace sightline {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

// Bad input to the public API (NaN, an unknown preset, a profile that does not parse, a world
// that reported an error); what() says what was expected.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace sightline
