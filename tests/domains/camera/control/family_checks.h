// Checks shared by the tests of generated scene families (generated_families_test.cc,
// agile_families_test.cc): a generated walk is valid (checked here, independently of the
// generators), and a camera run judged by the independent checker (never the controller's
// flag): frames with the look-at point hidden, frames within the clearance radius, moves
// longer than max_speed x dt without the cut flag, cuts.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/independent_check.h"
#include "sightline/experiments/runs/metrics.h"

namespace sightline {

// The walk is valid: the body's box never shares interior with a static box at any frame
// (touching is allowed, as standing on a step), no mover comes within 0.3 m of it, and the
// camera starts outside every box. Written here, not shared with the generator.
inline void expect_valid_walk(const camera::Scene& scene) {
  const experiments::MetricsInput input = experiments::metrics_input(scene, scene.profile(), 1);
  const Eigen::Vector3d half(scene.character().size.x() / 2, 0, scene.character().size.z() / 2);
  std::vector<experiments::SolidBox> movers;
  int bad = 0;
  for (std::size_t f = 0; f < scene.frame_count() && bad < 3; ++f) {
    const double t = scene.frame_time(f);
    const Eigen::Vector3d feet = scene.character_at(t).position;
    const Eigen::Vector3d lo = feet - half,
                          hi = feet + half + Eigen::Vector3d(0, scene.character().size.y(), 0);
    for (const experiments::SolidBox& b : input.boxes) {
      const bool overlap =
          (lo.array() < b.max.array() - 1e-9).all() && (b.min.array() + 1e-9 < hi.array()).all();
      if (overlap && bad++ < 3) ADD_FAILURE() << scene.name() << ": body inside a box at t=" << t;
    }
    experiments::moving_boxes_at(input.movers, t, movers);
    for (const experiments::SolidBox& b : movers) {
      const double gap = std::max({(b.min - hi).maxCoeff(), (lo - b.max).maxCoeff()});
      if (gap < 0.3 - 1e-9 && bad++ < 3) ADD_FAILURE() << scene.name() << ": mover at t=" << t;
    }
  }
  const Eigen::Vector3d start = scene.start_camera_position();
  EXPECT_GT(experiments::distance_to_geometry(input.boxes, start), 0) << scene.name();
}

struct Judged {
  int hidden = 0, too_close = 0, unflagged = 0, cuts = 0, discretionary = 0;
  double seconds = 0;
};

inline Judged judge(const camera::Scene& scene, const camera::ChaseCameraOptions& options,
             const experiments::CameraRun& run, bool report) {
  const double max_step = options.max_speed / scene.frame_rate();
  const experiments::MetricsInput input =
      experiments::metrics_input(scene, scene.profile(), max_step);
  Judged j;
  j.seconds = run.trace.back().t - run.trace.front().t;
  for (std::size_t i = 0; i < run.trace.size(); ++i) {
    const auto& row = run.trace[i];
    if (experiments::segment_blocked(input, row.camera, row.target, row.t) && j.hidden++ < 3 &&
        report) {
      ADD_FAILURE() << scene.name() << ": look-at hidden at t=" << row.t;
    }
    if (experiments::distance_to_geometry(input, row.camera, row.t) <
            scene.profile().clearance_radius - 1e-6 &&
        j.too_close++ < 3 && report) {
      ADD_FAILURE() << scene.name() << ": camera within clearance at t=" << row.t;
    }
    if (row.cut) ++j.cuts;
    if (row.cut && row.cut_reason != "visibility-lost") ++j.discretionary;
    if (i > 0 && !row.cut && (row.camera - run.trace[i - 1].camera).norm() > max_step + 1e-9 &&
        j.unflagged++ < 3 && report) {
      ADD_FAILURE() << scene.name() << ": unflagged jump at t=" << row.t;
    }
  }
  return j;
}

}  // namespace sightline
