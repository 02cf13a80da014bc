// File paths as suite files write them: relative to the suite file's folder, and globs.
#pragma once

#include <string>
#include <vector>

#include "sightline/csp/spec.h"

namespace sightline::experiments {

// `path` against `base_dir` (unless absolute or base_dir is empty), normalised.
std::string resolve(const std::string& base_dir, const std::string& path);

// Paths matching `pattern` (relative to base_dir), sorted. A pattern matching nothing is an
// InputError at `where`.
std::vector<std::string> expand_glob(const csp::Spec& where, const std::string& base_dir,
                                     const std::string& pattern);

}  // namespace sightline::experiments
