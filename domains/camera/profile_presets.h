// The YAML text of the shipped profile presets (domains/camera/profiles/*.yaml), compiled into
// the library by CMake (see profile_presets.cc.in). Only profile_file.cc reads this.
#pragma once

#include <vector>

namespace sightline::camera::detail {

struct PresetText {
  const char* name;  // the file name without .yaml
  const char* yaml;
};

const std::vector<PresetText>& preset_texts();

}  // namespace sightline::camera::detail
