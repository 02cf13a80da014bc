// Pictures of camera runs for the suite report: the thesis' two auxiliary cameras (a top view
// and a side view of the scene with the character's and the camera's paths), what the main
// camera sees at a frame, and plots over time.
//
// Top and side views and plots are SVG text (vector drawings of boxes, paths and arrows stay
// sharp at any zoom and are small); the main camera's view is a ray-cast PNG: one ray per
// pixel through the scene at that frame's time (SceneAtTime::first_hit: the static BVH and
// the movers where they are then), boxes shaded by face (Lambert), the character's body
// highlighted, a checkered ground. Everything is returned as text or bytes so the report
// can embed it inline and stay one self-contained file.
#pragma once

#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/html_text.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

// What the views mark along a run: frames where the look-at point is hidden (judged by the
// independent check), one flag per trace row.
struct RunDrawing {
  const std::vector<TraceRow>* trace = nullptr;
  std::vector<char> occluded;
  std::string colour = "#d9480f";  // the camera path's colour
};

// Looking down the y axis: x to the right, z down the picture. Boxes shaded by height,
// areas dashed, the character's path with facing arrows, the camera's path with arrows
// toward its target, cuts circled, occluded frames dotted red, movers as report_movers.h
// draws them. `width` in pixels.
std::string top_view_svg(const camera::Scene& scene, const RunDrawing& run, int width);
// Looking along z (or x, whichever the character's path spans less): y up.
std::string side_view_svg(const camera::Scene& scene, const RunDrawing& run, int width);

// The main camera's picture at one frame: eye at row.camera, looking at row.target, y up,
// 60 degree vertical field of view, the scene as it is at row.t (movers included, in blue).
// A red frame marks a hidden look-at point. PNG bytes.
std::vector<unsigned char> camera_view_png(const camera::Scene& scene, const TraceRow& row,
                                           bool occluded, int width, int height);

struct PlotSeries {
  std::string label;
  std::string colour;
  std::vector<double> t;  // seconds
  std::vector<double> v;  // NaN leaves a gap (e.g. at a cut)
};
// A line plot of several series against time, with axes, ticks and a legend.
std::string line_plot_svg(const std::string& title, const std::vector<PlotSeries>& series,
                          int width, int height);

// RFC 4648 base64, for data: URIs.
std::string base64(const std::vector<unsigned char>& bytes);
}  // namespace sightline::experiments
