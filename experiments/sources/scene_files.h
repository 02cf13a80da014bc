// The scene files of a folder, in a fixed order: the shipped thesis scenes
// (experiments/scenes) are run one after another by tests and benchmarks, and every run
// must meet them in the same order.
#pragma once

#include <string>
#include <vector>

namespace sightline::experiments {

// The paths of the *.yaml files directly in `folder`, sorted; empty if there are none.
std::vector<std::string> scene_files(const std::string& folder);

}  // namespace sightline::experiments
