// The trace of an edited film (FORMATS.md "Trace file" and "Script and named shots"): one
// row per frame with the public columns, the lens (fov, roll) and the `shot` column; `cut`
// at every frame where a shot starts (never the first); `cost` the shot's cost in the
// editing model at that slot; char_* the scene's reference person (the followed character,
// or the first actor).
#pragma once

#include <vector>

#include "sightline/domains/camera/editing/editor.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

std::vector<TraceRow> edit_trace(const camera::Scene& scene, const camera::Edit& edit);

// A scene an editor films rather than a camera: nobody chased, no shot: block, and a
// script: or named shots:. Suites and `follow` run such a scene through the editor.
bool is_edit_scene(const camera::Scene& scene);

}  // namespace sightline::experiments
