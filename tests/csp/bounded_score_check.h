// What a bounded score (csp::Problem::score_below, shot-search's Framing::score_below) must
// give against the full score of the same point: when complete, the full score to the bit;
// when not, a score at least the bound and no more than the full score, so that comparing
// it with the bound decides as the full score would.
#pragma once

#include <gtest/gtest.h>

#include "sightline/csp/score.h"

namespace sightline::csp {

// Fewer hard, or as many and less soft: the order the bounded scores compare in.
inline bool lexicographically_below(const Score& a, const Score& b) {
  return a.hard < b.hard || (a.hard == b.hard && a.soft < b.soft);
}

inline void expect_bounded_score(const Score& got, bool complete, const Score& full, const Score& bound,
                                 int trial) {
  SCOPED_TRACE(trial);
  if (complete) {
    EXPECT_EQ(got.hard, full.hard);
    EXPECT_EQ(got.soft, full.soft);
  } else {
    EXPECT_FALSE(lexicographically_below(got, bound));
    EXPECT_FALSE(lexicographically_below(full, bound));
    EXPECT_LE(got.hard, full.hard);
    EXPECT_LE(got.soft, full.soft);
  }
  EXPECT_EQ(lexicographically_below(full, bound), complete && lexicographically_below(got, bound));
}

}  // namespace sightline::csp
