// The replay page's own JavaScript and CSS (experiments/replay/replay.js and replay.css),
// compiled into the program at build time (experiments/CMakeLists.txt reads the files into a
// generated .cc), so a report never fetches code and the program needs no data folder.
#pragma once

namespace sightline::experiments::replay_detail {

extern const char* const kReplayJs;
extern const char* const kReplayCss;

}  // namespace sightline::experiments::replay_detail
