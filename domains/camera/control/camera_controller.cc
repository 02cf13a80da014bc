#include "domains/camera/control/camera_controller.h"

#include "domains/camera/control/chase_camera.h"

namespace sightline::camera {

const char* to_string(CutReason reason) {
  switch (reason) {
    case CutReason::kNone: return "none";
    case CutReason::kLeftEnclosedArea: return "left an enclosed area";
    case CutReason::kBackedUpToObstacle: return "backed up to an obstacle";
    case CutReason::kVisibilityLost: return "no smooth move keeps the character visible";
    case CutReason::kStuck: return "stuck behind an obstacle";
  }
  return "?";
}

std::unique_ptr<CameraController> make_controller(const std::string& name, const Scene& scene,
                                                  const CameraProfile& profile,
                                                  const ChaseCameraOptions& options) {
  ChaseCameraOptions chase = options;
  chase.solver = name;
  return std::make_unique<ChaseCamera>(scene, profile, chase);
}

}  // namespace sightline::camera
