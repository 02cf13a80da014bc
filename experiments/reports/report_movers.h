// Movers in the report's top and side views: what moved where, and where it was when it
// mattered.
//
// A mover's swept path is drawn faintly (the area its box covers between keyframes, as the
// view projects it), and its box solidly at a few marked times: the first frame of each
// occlusion episode and each cut of the run, or, when the run has neither, three evenly
// spaced times. At a marked time only the movers near the character are drawn, so a street
// of buses does not bury the picture. Kept apart from report_views.cc so the views stay one
// concept each; the views call this with their own projection.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/reports/report_views.h"

namespace sightline::experiments {

// World point to picture pixels (x right, y down), as a view projects it.
using ToPixel = std::function<Eigen::Vector2d(const Eigen::Vector3d&)>;

// The times (seconds) at which a view marks the movers' boxes for this run: the first frame
// of each occlusion episode and each cut frame, at most `limit` of them spread over the run;
// three evenly spaced times when there are none. Empty without a trace.
std::vector<double> mover_mark_times(const RunDrawing& run, std::size_t limit = 8);

// SVG elements (no <svg> wrapper) drawing the scene's movers: swept paths faintly, boxes at
// mover_mark_times() for those within `near` metres (ground distance) of the character then,
// each labelled with its time. Empty when the scene has no movers.
std::string movers_svg(const camera::Scene& scene, const RunDrawing& run, const ToPixel& to_pixel,
                       double near = 6);

}  // namespace sightline::experiments
