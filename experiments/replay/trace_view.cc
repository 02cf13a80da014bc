#include "sightline/experiments/replay/trace_view.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"

namespace sightline::experiments {
namespace {

std::string number(double x, int decimals = 4) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, x);
  return text;
}

std::string position_text(const Eigen::Vector3d& p) {
  return "(" + number(p.x(), 3) + ", " + number(p.y(), 3) + ", " + number(p.z(), 3) + ")";
}

// Letters, digits and ._- only (replay.h), so an id goes into a URL fragment as it is.
std::string fragment_safe(const std::string& text) {
  const std::string safe = replay_safe_id(text);
  return safe.empty() ? std::string("run") : safe;
}

}  // namespace

void check_trace_matches_scene(const camera::Scene& scene, const std::vector<TraceRow>& trace,
                               const std::string& path, const TraceMatchTolerance& tolerance) {
  const std::size_t scene_frames = scene.frame_count();
  const double start = scene.trajectory().start_time();
  const double end = scene.trajectory().end_time();
  const std::string span = "[" + number(start) + ", " + number(end) + "] s";
  if (trace.empty()) {
    throw csp::InputError({path, 0, 0}, "the trace has no frames; scene '" + scene.name() +
                                            "' has " + std::to_string(scene_frames) +
                                            " (t in " + span + ")");
  }
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const TraceRow& r = trace[i];
    const csp::SourceLocation where{path, r.line, 0};
    const std::string frame = "frame " + std::to_string(r.frame) + " (row " +
                              std::to_string(i + 1) + ")";
    if (r.t < start - tolerance.time || r.t > end + tolerance.time) {
      const double off = r.t < start ? start - r.t : r.t - end;
      throw csp::InputError(where, frame + " is at t = " + number(r.t) + " s, " + number(off) +
                                       " s outside scene '" + scene.name() + "''s span " +
                                       span);
    }
    if (i > 0 && r.t <= trace[i - 1].t) {
      throw csp::InputError(where, frame + " is at t = " + number(r.t) +
                                       " s, not after the frame before it (t = " +
                                       number(trace[i - 1].t) + " s)");
    }
    const Eigen::Vector3d expected = scene.character_at(r.t).position;
    const double off = (r.character - expected).norm();
    if (!(off <= tolerance.position)) {
      throw csp::InputError(
          where, frame + " at t = " + number(r.t) + " s has the character at " +
                     position_text(r.character) + ", " + number(off, 3) +
                     " m from where scene '" + scene.name() + "' puts it " +
                     position_text(expected) + " (tolerance " +
                     number(tolerance.position, 3) + " m): is this a trace of that scene?");
    }
  }
  if (trace.size() != scene_frames) {
    const std::string counts = "the trace has " + std::to_string(trace.size()) +
                               " frames, scene '" + scene.name() + "' has " +
                               std::to_string(scene_frames) + " (t in " + span + " at " +
                               number(scene.frame_rate(), 3) + " frames per second)";
    // Point at the first frame where the two disagree: a different frame rate shows at
    // frame 1, a cut-short run at its end.
    for (std::size_t i = 0; i < trace.size() && i < scene_frames; ++i) {
      const double off = trace[i].t - scene.frame_time(i);
      if (std::abs(off) > tolerance.time) {
        throw csp::InputError({path, trace[i].line, 0},
                              counts + "; frame " + std::to_string(trace[i].frame) + " (row " +
                                  std::to_string(i + 1) + ") is at t = " + number(trace[i].t) +
                                  " s, the scene's frame " + std::to_string(i) + " at t = " +
                                  number(scene.frame_time(i)) + " s (" +
                                  number(off, 4) + " s apart)");
      }
    }
    if (trace.size() < scene_frames) {
      throw csp::InputError({path, trace.back().line, 0},
                            counts + ": the trace stops at t = " + number(trace.back().t) +
                                " s, " + std::to_string(scene_frames - trace.size()) +
                                " frames (" + number(end - trace.back().t) +
                                " s) before the scene ends");
    }
    throw csp::InputError({path, trace[scene_frames].line, 0},
                          counts + ": " + std::to_string(trace.size() - scene_frames) +
                              " frames more, from row " + std::to_string(scene_frames + 1));
  }
}

std::vector<char> hidden_frames(const MetricsInput& world, const std::vector<TraceRow>& trace) {
  std::vector<char> hidden;
  hidden.reserve(trace.size());
  for (const TraceRow& r : trace) hidden.push_back(segment_blocked(world, r.camera, r.target, r.t) ? 1 : 0);
  return hidden;
}

std::vector<std::string> run_ids_from_paths(const std::vector<std::string>& paths) {
  std::vector<std::string> ids;
  std::set<std::string> taken;
  for (const std::string& p : paths) {
    std::string name = std::filesystem::path(p).filename().string();
    for (const char* suffix : {".csv", ".trace"}) {
      const std::string s = suffix;
      if (name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0) {
        name.resize(name.size() - s.size());
      }
    }
    const std::string base = fragment_safe(name);
    std::string id = base;
    // A repeated name gets -2, -3, ...; skipping suffixes that are themselves taken.
    for (int k = 2; taken.count(id); ++k) id = base + "-" + std::to_string(k);
    taken.insert(id);
    ids.push_back(id);
  }
  return ids;
}

int unflagged_jumps(const std::vector<TraceRow>& trace, double max_speed) {
  // Traces round positions to a tenth of a millimetre and times to a tenth of a millisecond:
  // allow for both, on both ends of a step.
  constexpr double kPositionRounding = 2e-4, kTimeRounding = 1e-4;
  int jumps = 0;
  for (std::size_t i = 1; i < trace.size(); ++i) {
    const double dt = trace[i].t - trace[i - 1].t;
    const double step = (trace[i].camera - trace[i - 1].camera).norm();
    if (!trace[i].cut && step > max_speed * (dt + kTimeRounding) + kPositionRounding) ++jumps;
  }
  return jumps;
}

TraceView make_trace_view(const TraceViewOptions& options) {
  if (options.trace_paths.empty()) {
    throw std::invalid_argument("no trace given: name one or more with --trace FILE.csv");
  }
  const camera::Scene scene = camera::read_scene_file(options.scene_path);
  // The clearance radius and the smooth step do not matter for visibility.
  const MetricsInput world = metrics_input(scene, scene.profile(), 0);
  const std::vector<std::string> ids = run_ids_from_paths(options.trace_paths);

  ReplayScene replay;
  replay.id = fragment_safe(scene.name());
  replay.scene = &scene;
  TraceView view;
  for (std::size_t i = 0; i < options.trace_paths.size(); ++i) {
    const std::string& path = options.trace_paths[i];
    ReplayRun run;
    run.id = ids[i];
    run.label = std::filesystem::path(path).filename().string();
    run.trace = read_trace_csv(path);
    check_trace_matches_scene(scene, run.trace, path);
    run.hidden = hidden_frames(world, run.trace);
    TraceViewRunSummary summary;
    summary.id = run.id;
    summary.path = path;
    summary.frames = static_cast<int>(run.trace.size());
    for (const char h : run.hidden) summary.hidden_frames += h;
    for (const TraceRow& r : run.trace) summary.cuts += r.cut ? 1 : 0;
    summary.unflagged_jumps = unflagged_jumps(run.trace, options.max_speed);
    view.runs.push_back(summary);
    replay.runs.push_back(std::move(run));
  }
  view.html = replay_page("sightline view: " + scene.name(), {replay}, options.replay);
  return view;
}

}  // namespace sightline::experiments
