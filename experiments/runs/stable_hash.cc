#include "sightline/experiments/runs/stable_hash.h"

#include <cstdio>

namespace sightline::experiments {

std::string StableHash::hex() const {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value_));
  return buffer;
}

std::string StableHash::short_hex() const {
  char buffer[9];
  std::snprintf(buffer, sizeof buffer, "%08llx", static_cast<unsigned long long>(value_ >> 32));
  return buffer;
}

}  // namespace sightline::experiments
