#include "sightline/experiments/runs/file_globs.h"

#include <glob.h>

#include <algorithm>
#include <filesystem>

namespace sightline::experiments {

using csp::Spec;

std::string resolve(const std::string& base_dir, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || base_dir.empty()) return p.lexically_normal().string();
  return (std::filesystem::path(base_dir) / p).lexically_normal().string();
}

std::vector<std::string> expand_glob(const Spec& where, const std::string& base_dir,
                                     const std::string& pattern) {
  const std::string full = resolve(base_dir, pattern);
  glob_t found{};
  const int status = ::glob(full.c_str(), 0, nullptr, &found);
  std::vector<std::string> paths;
  if (status == 0) {
    for (std::size_t i = 0; i < found.gl_pathc; ++i) paths.emplace_back(found.gl_pathv[i]);
  }
  ::globfree(&found);
  if (paths.empty()) {
    const bool is_pattern = pattern.find_first_of("*?[") != std::string::npos;
    where.fail(is_pattern ? "the pattern '" + pattern + "' (" + full + ") matches no file"
                          : "file '" + full + "' does not exist");
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace sightline::experiments
