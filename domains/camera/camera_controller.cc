#include "sightline/domains/camera/camera_controller.h"

namespace sightline::camera {

const char* to_string(CutReason reason) {
  switch (reason) {
    case CutReason::kNone: return "none";
    case CutReason::kLeftEnclosedArea: return "left an enclosed area";
    case CutReason::kBackedUpToObstacle: return "backed up to an obstacle";
    case CutReason::kVisibilityLost: return "no smooth move keeps the character visible";
    case CutReason::kStuck: return "stuck behind an obstacle";
    case CutReason::kTooFast: return "moved faster than smooth motion allows";
  }
  return "?";
}

}  // namespace sightline::camera
