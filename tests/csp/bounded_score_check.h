// What a bounded score (csp::Problem::score_below, shot-search's Framing::score_below) must
// give against the full score of the same point: when complete, the full score to the bit;
// when not, a score at least the bound and no more than the full score, so that comparing
// it with the bound decides as the full score would.
#pragma once

#include <gtest/gtest.h>

#include "sightline/csp/score.h"

namespace sightline::csp {

inline void expect_bounded_score(const Score& got, bool complete, const Score& full, const Score& bound,
                                 int trial) {
  SCOPED_TRACE(trial);
  if (complete) {
    EXPECT_EQ(got.hard, full.hard);
    EXPECT_EQ(got.soft, full.soft);
  } else {
    EXPECT_FALSE(got.before(bound));
    EXPECT_FALSE(full.before(bound));
    EXPECT_LE(got.hard, full.hard);
    EXPECT_LE(got.soft, full.soft);
  }
  EXPECT_EQ(full.before(bound), complete && got.before(bound));
}

}  // namespace sightline::csp
