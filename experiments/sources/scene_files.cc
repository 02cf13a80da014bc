#include "sightline/experiments/sources/scene_files.h"

#include <algorithm>
#include <filesystem>

namespace sightline::experiments {

std::vector<std::string> scene_files(const std::string& folder) {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".yaml") paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace sightline::experiments
