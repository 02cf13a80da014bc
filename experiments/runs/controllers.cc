#include "sightline/experiments/runs/controllers.h"

#include <stdexcept>

#include "sightline/domains/camera/baselines/pull_forward.h"
#include "sightline/domains/camera/baselines/spring_arm.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/composition/group_framing.h"
#include "sightline/domains/camera/composition/tracking_camera.h"
#include "sightline/domains/camera/control/camera_solvers.h"

namespace sightline::camera {

std::unique_ptr<CameraController> make_controller(const std::string& name, const Scene& scene,
                                                  const CameraProfile& profile,
                                                  const ChaseCameraOptions& options) {
  if (scene.shot() && name == "group-framing") {
    return std::make_unique<GroupFraming>(scene, options.max_speed);
  }
  if (scene.shot()) {
    // A scene with a shot: block is filmed as a tracking shot, by default with the
    // recommended composition solver (FORMATS.md "The follow command").
    TrackingOptions tracking;
    tracking.solver = name.empty() ? kRecommendedCompositionSolver : name;
    tracking.max_speed = options.max_speed;
    tracking.seed = options.seed;
    return std::make_unique<TrackingCamera>(scene, tracking);
  }
  if (!scene.has_character()) {
    throw std::invalid_argument("scene '" + scene.name() + "' has nobody to follow and no shot: "
                                "block to frame: a scene with only a script: or shots: is "
                                "filmed by `sightline edit`");
  }
  if (name == "spring-arm" || name == "pull-forward") {
    // The baselines have their own options (defaults); they share the smooth-motion bound
    // that decides what counts as a cut, and take no solver options.
    if (!options.solver_options.empty()) {
      throw std::invalid_argument("'" + name + "' is a baseline camera and takes no solver options");
    }
    if (name == "spring-arm") {
      SpringArmOptions arm;
      arm.max_speed = options.max_speed;
      return std::make_unique<SpringArm>(scene, profile, arm);
    }
    PullForwardOptions pull;
    pull.max_speed = options.max_speed;
    return std::make_unique<PullForward>(scene, profile, pull);
  }
  ChaseCameraOptions chase = options;
  chase.solver = name.empty() ? kRecommendedCameraSolver : name;
  return std::make_unique<ChaseCamera>(scene, profile, chase);
}

}  // namespace sightline::camera
