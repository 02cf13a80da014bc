// make_controller: a camera controller by name, for the tools and the experiments.
// "spring-arm" and "pull-forward" are the baselines games ship (domains/camera/baselines/);
// any other name is a solver or pipeline of the registry driving a ChaseCamera.
#pragma once

#include <memory>
#include <string>

#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/control/chase_camera.h"

namespace sightline::camera {

// `options.solver` is replaced by `name`; an empty name is the recommended solver: the
// composition solver for a scene with a shot: block (filmed by a TrackingCamera), else the
// camera solver. Throws solvers::OptionError /
// std::invalid_argument for bad names or options.
std::unique_ptr<CameraController> make_controller(const std::string& name, const Scene& scene,
                                                  const CameraProfile& profile,
                                                  const ChaseCameraOptions& options);

}  // namespace sightline::camera
