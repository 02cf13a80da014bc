#include "sightline/domains/camera/level/level_transform.h"

namespace sightline::camera {

const char* to_string(UpAxis up) {
  switch (up) {
    case UpAxis::kY:
      return "y";
    case UpAxis::kZ:
      return "z";
  }
  return "?";
}

std::optional<UpAxis> up_axis_from_string(const std::string& text) {
  if (text == "y") return UpAxis::kY;
  if (text == "z") return UpAxis::kZ;
  return std::nullopt;
}

}  // namespace sightline::camera
