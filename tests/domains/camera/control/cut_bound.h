// Issue 24's bound on a run's cuts, checked from their times (the trace's cut flags, never
// the metrics): never two within 1 s, at most 2 in any 60 s. Shared by the tests that hold
// a camera to it (agile_families_test.cc, anticipation_test.cc, level_walks_test.cc).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sightline {

// `cuts`: the cut times in seconds, in order; `what` names the run in a failure.
inline void expect_within_cut_bound(const std::string& what, const std::vector<double>& cuts) {
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    EXPECT_GE(cuts[i] - cuts[i - 1], 1.0 - 1e-9)
        << what << ": cuts at " << cuts[i - 1] << " and " << cuts[i] << " s";
  }
  for (std::size_t i = 2; i < cuts.size(); ++i) {
    EXPECT_GE(cuts[i] - cuts[i - 2], 60.0) << what << ": 3 cuts within a minute, at "
                                           << cuts[i - 2] << ", " << cuts[i - 1] << " and "
                                           << cuts[i] << " s";
  }
}

// The same bound as a verdict, for a run known to break it.
inline bool within_cut_bound(const std::vector<double>& cuts) {
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    if (cuts[i] - cuts[i - 1] < 1.0 - 1e-9) return false;
  }
  for (std::size_t i = 2; i < cuts.size(); ++i) {
    if (cuts[i] - cuts[i - 2] < 60.0) return false;
  }
  return true;
}

}  // namespace sightline
