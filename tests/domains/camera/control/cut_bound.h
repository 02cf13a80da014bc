// Issue 24's bound on a run's cuts, checked from their times (the trace's cut flags, never
// the metrics): never two within 1 s, at most 2 in any 60 s. Shared by the tests that hold
// a camera to it (agile_families_test.cc, anticipation_test.cc, level_walks_test.cc).
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace sightline {

// The times of a trace's cut frames, in order (any rows with `cut` and `t`).
template <class Rows>
std::vector<double> cut_times(const Rows& trace) {
  std::vector<double> cuts;
  for (const auto& row : trace) {
    if (row.cut) cuts.push_back(row.t);
  }
  return cuts;
}

// Where the cuts at `cuts` (seconds, in order) break the bound, one line each; none when
// they keep it.
inline std::vector<std::string> cut_bound_breaches(const std::vector<double>& cuts) {
  std::vector<std::string> out;
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    if (cuts[i] - cuts[i - 1] < 1.0 - 1e-9) {
      std::ostringstream line;
      line << "cuts at " << cuts[i - 1] << " and " << cuts[i] << " s";
      out.push_back(line.str());
    }
  }
  for (std::size_t i = 2; i < cuts.size(); ++i) {
    if (cuts[i] - cuts[i - 2] < 60.0) {
      std::ostringstream line;
      line << "3 cuts within a minute, at " << cuts[i - 2] << ", " << cuts[i - 1] << " and "
           << cuts[i] << " s";
      out.push_back(line.str());
    }
  }
  return out;
}

// `what` names the run in a failure: one failure for each breach.
inline void expect_within_cut_bound(const std::string& what, const std::vector<double>& cuts) {
  for (const std::string& breach : cut_bound_breaches(cuts)) ADD_FAILURE() << what << ": " << breach;
}

}  // namespace sightline
