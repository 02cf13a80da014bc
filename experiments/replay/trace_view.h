// TraceView: the interactive replay page (replay.h) for traces from anywhere, the work of
// `sightline view SCENE.yaml --trace A.csv [--trace B.csv ...] --out view.html`.
//
// A suite's report replays the runs it made itself; this replays any trace in the FORMATS.md
// columns, written by this program or by another tool, against the scene it claims to
// follow. Because the trace may come from elsewhere, nothing in it is trusted beyond its
// columns: it must match the scene (same frames, the character where the scene's trajectory
// puts it at the trace's times, or the replay would show a camera filming an empty spot),
// and the frames with the look-at point hidden are judged here with the independent check
// (metrics.h), never taken from a controller's flag.
#pragma once

#include <string>
#include <vector>

#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/metrics.h"
#include "sightline/experiments/replay/replay.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

// How far a trace may stray from its scene and still be a run of it. Traces round positions
// to a tenth of a millimetre and times to a tenth of a millisecond (trace.h); another tool
// computing frame times as float sums drifts by much less than a centimetre.
struct TraceMatchTolerance {
  double position = 0.01;  // metres, between the trace's character and the scene's
  double time = 1e-3;      // seconds, outside the scene's first and last keyframe
};

// Throws csp::InputError naming `path`, the line of the first frame that is wrong and by how
// much, when `trace` is not a run of `scene`: times not increasing, a time outside the
// scene's span, the character's feet farther than the tolerance from the scene's trajectory
// at the trace's time, or a different number of frames than the scene simulates (the first
// frame whose time differs from the scene's frame time, or where one of the two ends).
void check_trace_matches_scene(const camera::Scene& scene, const std::vector<TraceRow>& trace,
                               const std::string& path, const TraceMatchTolerance& tolerance = {});

// 1 for each frame whose look-at point (the trace's target) is hidden from its camera by the
// scene's boxes or level triangles, by the independent check; 0 where it is visible.
std::vector<char> hidden_frames(const MetricsInput& world, const std::vector<TraceRow>& trace);

// Run ids for the page's URL fragment (#run=<id>) from trace file names: the name without
// folders and without ".csv" (and a ".trace" before it, as suites write), with characters
// other than letters, digits, '.', '_' and '-' replaced by '_' (replay_safe_id); a repeated
// id gets "-2", "-3", ... in the order given.
std::vector<std::string> run_ids_from_paths(const std::vector<std::string>& paths);

// Frames whose camera moved faster than max_speed (m/s) since the frame before without a
// cut flag (positions' rounding allowed for).
int unflagged_jumps(const std::vector<TraceRow>& trace, double max_speed);

struct TraceViewOptions {
  std::string scene_path;
  std::vector<std::string> trace_paths;  // at least one
  // A move faster than this (m/s, over the frame's time step) without a cut flag is an
  // unflagged jump; the default is the chase camera's smooth-motion bound.
  double max_speed = camera::ChaseCameraOptions{}.max_speed;
  ReplayOptions replay;
};

// What the page shows, one entry per trace, for the command to print.
struct TraceViewRunSummary {
  std::string id;
  std::string path;
  int frames = 0;
  int hidden_frames = 0;  // independent check
  int cuts = 0;
  int unflagged_jumps = 0;  // moves faster than TraceViewOptions::max_speed, not flagged cuts
};

struct TraceView {
  std::string html;  // the whole page
  std::vector<TraceViewRunSummary> runs;
};

// Reads the scene (levels included) and every trace, checks each trace against the scene,
// judges visibility per frame and builds the page. Throws csp::InputError for an unreadable
// scene or trace, a malformed trace or one that does not match the scene, and
// std::invalid_argument when no trace is given.
TraceView make_trace_view(const TraceViewOptions& options);

}  // namespace sightline::experiments
