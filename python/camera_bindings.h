// The Python module's cameras and shots: sightline.Scene (a scene read once), load_scene,
// follow (a film, or an edited one), compose (a shot at one instant), evaluate_pose and
// evaluate_trace (a pose, or every frame of a film, judged by the shot's measures).
// sightline_module.cc, which holds problems, solvers and suites, adds them to the module.
#pragma once

#include <pybind11/pybind11.h>

namespace sightline::python {

void add_camera_bindings(pybind11::module_& m);

}  // namespace sightline::python
