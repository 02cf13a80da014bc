// profile_text: one canonical text of a resolved CameraProfile, for telling profiles apart.
//
// Why: an experiment suite's run ids hash each run's whole definition so that editing an
// entry re-runs exactly its runs (experiments/suite/suite_runs.cc). A profile named by its source
// alone ("inline", "file PATH", "preset NAME") would let an edited inline mapping, an edited
// profile file or an edited base it inherits from reuse stale results. The text is taken of
// the profile after every `base:` is applied, so it changes exactly when what the camera is
// asked to do changes: reordered YAML keys, comments or a byte-identical rewrite leave it as
// it is, a changed number anywhere in the chain does not.
//
// Every field that affects a run is written, in a fixed order, numbers round-trippable
// (shortest form that reads back to the same double). `name` and `description` are left
// out: they label a profile and change nothing a run does. `extras` are written as their
// Spec trees with map keys sorted, and scalars that read as numbers written as numbers, so
// `weight: 2` and `weight: 2.0` are one profile.
#pragma once

#include <string>

#include "sightline/domains/camera/profile.h"

namespace sightline::camera {

// The canonical text (one line per field group) of `profile`.
std::string profile_text(const CameraProfile& profile);

}  // namespace sightline::camera
