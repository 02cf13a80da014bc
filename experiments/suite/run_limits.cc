#include "sightline/experiments/suite/run_limits.h"

#include <cmath>
#include <cstdio>

namespace sightline::experiments {

std::string limit_seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", seconds);
  return buffer;
}

std::string RunLimits::text() const {
  std::string out;
  auto add = [&](const std::string& part) { out += (out.empty() ? "" : ",") + part; };
  if (wall_seconds > 0) add("wall=" + limit_seconds_text(wall_seconds));
  if (cpu_seconds > 0) add("cpu=" + limit_seconds_text(cpu_seconds));
  if (memory_mb > 0) add("memory_mb=" + std::to_string(memory_mb));
  return out;
}

std::string RunLimits::validate() const {
  if (!(wall_seconds >= 0) || !std::isfinite(wall_seconds)) {
    return "wall_seconds must be a number of seconds > 0";
  }
  if (!(cpu_seconds >= 0) || !std::isfinite(cpu_seconds)) {
    return "cpu_seconds must be a number of seconds > 0";
  }
  if (memory_mb > 0 && memory_mb < kMinimumMemoryMb) {
    return "memory_mb must be at least " + std::to_string(kMinimumMemoryMb) +
           " (the program needs that much address space to start)";
  }
  return "";
}

}  // namespace sightline::experiments
