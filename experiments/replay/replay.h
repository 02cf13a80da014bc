// Replay: an interactive 3D replay of camera runs in a web page (three.js), for the suite
// report and `sightline view`.
//
// People judge a camera by watching it. The page shows, per scene, an orbit view of the
// world (boxes, level triangles, movers, the character moving along its path, the camera as
// a small frustum with its path and look-at point, cut and hidden-frame markers), the main
// camera's own view (what the player sees), a timeline (play, speed, frame steps, a scrubber
// marked at cuts and at frames whose look-at point the independent check finds hidden), a
// run selector and a side-by-side mode playing two runs of a scene in sync.
//
// Data is written once per scene (geometry) and once per run (per-frame arrays), as base64
// little-endian Float32 / Uint32 / Uint8 buffers rather than JSON numbers, so a suite's
// report stays small. three.js is Debian's libjs-three, read from /usr/share/javascript/three/
// when the page is written and inlined (or copied beside the page): the page opens offline
// and fetches nothing. The replay's own JS and CSS (experiments/replay/) are compiled in.
//
// The DOM contract (classes, data attributes, the URL fragment #run=ID&t=SECONDS&panel=...,
// and document.documentElement.dataset.replay = "ready" | "error") is documented at the top
// of experiments/replay/replay.js and in docs/EXPERIMENTS.md; scripts that check the page in
// a browser rely on it.
#pragma once

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

struct ReplayRun {             // one camera run
  std::string id;              // stable id (the suite run id; for `view`, from the trace file name)
  std::string label;           // "solver / profile / seed" for the selector
  std::vector<TraceRow> trace;
  std::vector<char> hidden;    // per frame: look-at point hidden by the independent check
};

struct ReplayScene {
  std::string id;                        // unique on the page (file-name safe is best)
  const camera::Scene* scene = nullptr;  // not owned
  std::vector<ReplayRun> runs;
};

struct ReplayOptions {
  // Empty: everything inline (one self-contained page). Otherwise three.js and each scene's
  // data are written as .js files into assets_dir and referenced as assets_href + "/" + file
  // (assets_href relative to the page, e.g. "report-assets"); they load with <script src>,
  // which works from file:// where fetch() does not.
  std::string assets_dir;
  std::string assets_href;
  // Where Debian's libjs-three lives (tests point it elsewhere to check the error).
  std::string three_dir = "/usr/share/javascript/three";
  // The levels (keys) already written on this page: scenes on the same level share its
  // triangles, written once. replay_page starts a fresh set; a caller writing sections
  // itself uses one ReplayOptions per page (copies share the set). Null: always write.
  std::shared_ptr<std::set<std::string>> levels_on_page = std::make_shared<std::set<std::string>>();
};

// CSS, three.js (with its OrbitControls) and the replay code: once per page, inside <head>
// or before the first section. Throws std::runtime_error naming the package libjs-three
// when three.js is missing. In assets mode writes three.js into assets_dir.
std::string replay_head(const ReplayOptions& options);
// One scene's replay section (data inline, or written to assets_dir/replay-<id>.js).
// Throws std::invalid_argument when a run has no rows or its hidden flags do not match them.
std::string replay_section(const ReplayScene& scene, const ReplayOptions& options);
// A whole page: head, a title, one section per scene.
std::string replay_page(const std::string& title, const std::vector<ReplayScene>& scenes,
                        const ReplayOptions& options);

// The file-name-safe form of an id: letters, digits, '-', '_' and '.' kept, others '_'.
std::string replay_safe_id(const std::string& id);

}  // namespace sightline::experiments
