// Reading YAML into a Spec, keeping every node's file, line and column.
//
// Every YAML file of the project (problem files, scenes, profiles, suites) goes through here,
// so they all report errors the same way: "scene.yaml:12:5: expected a number, got 'abc'".
#pragma once

#include <string>

#include "sightline/csp/spec.h"

namespace sightline::csp {

// Parses a YAML file. Throws InputError for an unreadable file or malformed YAML, naming
// the file and (for syntax errors) the line; also for a document that its aliases (`*name`)
// make infinite or huge: nested more than 1000 deep, or more than a million values beyond
// one per character of the text, once each alias is replaced by what its anchor names.
Spec read_yaml_file(const std::string& path);
// Parses YAML text; `origin` names it in error messages.
Spec parse_yaml(const std::string& text, const std::string& origin);

}  // namespace sightline::csp
