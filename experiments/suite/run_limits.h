// RunLimits: a suite run's wall-time, CPU-time and memory limits, as a suite file gives them
// (`limits:`); execution/run_isolation.h holds a child process to them.
#pragma once

#include <cstdint>
#include <string>

namespace sightline::experiments {

// Per-run limits; 0 means none. The CPU limit is whole seconds for the kernel (rounded up).
struct RunLimits {
  double wall_seconds = 0;
  double cpu_seconds = 0;
  std::uint64_t memory_mb = 0;

  bool any() const { return wall_seconds > 0 || cpu_seconds > 0 || memory_mb > 0; }
  // "wall=60,cpu=60,memory_mb=2048" (only the limits set): part of a run's definition.
  std::string text() const;
  // A reason these limits make no sense ("" when they are fine).
  std::string validate() const;
};

// The program needs this much address space just to start (its libraries: Embree, assimp,
// Ceres, TBB...): a memory limit below it is refused when the suite is read.
constexpr std::uint64_t kMinimumMemoryMb = 256;

// Seconds as limits are written ("%g": 60, 2.5), in definitions and messages.
std::string limit_seconds_text(double seconds);

}  // namespace sightline::experiments
