// The independent judge of a camera run for the camera-control tests: frames where the
// independent check (experiments/runs/independent_check.h for boxes, independent_triangles.h for
// a level's triangles: no BVH, no Embree) sees the look-at point hidden, the camera within
// the clearance radius, or a move longer than smooth motion allows without the cut flag;
// plus, on a level with solid volumes, frames with the camera inside solid matter or
// outside the world. The first few of each are reported as test failures.
#pragma once

#include <gtest/gtest.h>

#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/metrics.h"

namespace sightline {

struct Violations {
  int hidden = 0, too_close = 0, unflagged = 0, in_solid = 0;
};

inline Violations independent_violations(const camera::Scene& scene,
                                         const camera::ChaseCameraOptions& options,
                                         const experiments::CameraRun& run) {
  const experiments::MetricsInput input =
      experiments::metrics_input(scene, scene.profile(), options.max_speed / scene.frame_rate());
  Violations v;
  for (std::size_t i = 0; i < run.trace.size(); ++i) {
    const auto& row = run.trace[i];
    if (experiments::segment_blocked(input, row.camera, row.target, row.t)) {
      if (v.hidden++ < 5) ADD_FAILURE() << "look-at hidden at frame " << i << " t=" << row.t;
    }
    if (experiments::distance_to_geometry(input, row.camera, row.t) <
        scene.profile().clearance_radius - 1e-6) {
      if (v.too_close++ < 5) ADD_FAILURE() << "camera within clearance at frame " << i << " t=" << row.t;
    }
    if (input.solid_at && input.solid_at(row.camera)) {
      if (v.in_solid++ < 5) ADD_FAILURE() << "camera inside solid matter at frame " << i << " t=" << row.t;
    }
    if (i > 0 && !row.cut &&
        (row.camera - run.trace[i - 1].camera).norm() >
            options.max_speed / scene.frame_rate() + 1e-9) {
      if (v.unflagged++ < 5) ADD_FAILURE() << "unflagged jump at frame " << i;
    }
  }
  return v;
}

}  // namespace sightline
