// The YAML files of a folder of the source tree (SIGHTLINE_SOURCE_DIR/folder), sorted, for
// tests that run over every shipped scene of a kind.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

inline std::vector<std::string> shipped_yaml_files(const std::string& folder) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SIGHTLINE_SOURCE_DIR) + "/" + folder)) {
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}
