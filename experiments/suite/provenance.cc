#include "sightline/experiments/suite/provenance.h"

#include <unistd.h>

#include <climits>
#include <fstream>
#include <sstream>

#include "build_commit.h"  // generated at build time by build_commit.cmake

namespace sightline::experiments {
namespace {

std::string host_name() {
  char buffer[HOST_NAME_MAX + 1] = {};
  if (::gethostname(buffer, sizeof buffer - 1) != 0) return "unknown";
  return buffer;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::size_t first = line.find_first_not_of(" \t", colon + 1);
    if (first != std::string::npos) return line.substr(first);
  }
  return "unknown";
}

// /proc/self/cmdline: the arguments, each ended by a NUL.
std::vector<std::string> own_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> words;
  std::string word;
  while (std::getline(in, word, '\0')) words.push_back(word);
  return words;
}

}  // namespace

std::string shell_command_line(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) {
    if (!out.empty()) out += ' ';
    const bool plain = !w.empty() && w.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-+=./:,@%") == std::string::npos;
    if (plain) {
      out += w;
      continue;
    }
    out += '\'';
    for (char c : w) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

const Provenance& this_process_provenance() {
  static const Provenance provenance = [] {
    Provenance p;
    p.host = host_name();
    p.cpu_model = cpu_model();
    p.build_commit = SIGHTLINE_BUILD_COMMIT;
    p.command_line = shell_command_line(own_arguments());
    return p;
  }();
  return provenance;
}

}  // namespace sightline::experiments
