// The suite report: OUT/report.html, one self-contained file that opens offline.
//
// It holds the summary tables (the same numbers as summary.md and results.csv) and, for each
// scene of a camera suite: a top view and a side view per run side by side (the thesis'
// auxiliary cameras: walls, areas, the character's path with facing arrows, the camera's
// path with arrows, cuts circled, occluded frames dotted), what the main camera sees at a
// few chosen frames (ray-cast PNGs), an interactive 3D replay of every run (replay.h; the
// still pictures stay for print), and plots over time of cost, visible fraction of the
// body and camera speed. CSS is inline, pictures are inline SVG or base64 data: URIs; the
// file references nothing outside itself.
#pragma once

#include <string>

#include "sightline/experiments/replay/replay.h"
#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/suite/suite_results.h"

namespace sightline::experiments {

struct ReportOptions {
  int view_width = 420;     // pixels, each top/side view
  int camera_width = 240;   // pixels, each main-camera picture
  int camera_height = 150;
  int plot_width = 640, plot_height = 200;
  // The interactive 3D replay (replay.h), one section per camera scene.
  bool replay = true;
  // Where its data goes: as the suite says (`report: replay_assets:`), or forced inline (one
  // self-contained file) or beside (out_dir/report-assets/*.js, loaded with <script src>).
  enum class ReplayAssets { kSuite, kInline, kBeside };
  ReplayAssets replay_assets = ReplayAssets::kSuite;
  std::string three_dir = "/usr/share/javascript/three";  // Debian's libjs-three
};

// The HTML text. Reads each camera run's trace from out_dir/runs/<id>.trace.csv; a missing
// or unreadable trace leaves that run's pictures out with a note.
std::string report_html(const Suite& suite, const SuiteOutcome& outcome,
                        const std::string& out_dir, const ReportOptions& options = {});
// Writes out_dir/report.html (write, then rename).
void write_report(const Suite& suite, const SuiteOutcome& outcome, const std::string& out_dir,
                  const ReportOptions& options = {});

}  // namespace sightline::experiments
