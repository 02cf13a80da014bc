// Issue 24's two comparisons of the default camera with baselines filmed on the same walk:
// at least half the character's body visible in at least as many frames as the spring arm
// shows it, and a jerk p99 no higher than the thesis' reactive camera's. Both figures are
// the suite's metrics (experiments/runs/metrics.h: the body's visible share by sight lines
// of its own to the body's samples, the jerk by differences of the trace skipping cuts),
// never the controller's own flags.
//
// The runs known to fall short are named by each test, with the figures they had when
// listed: each of them is held to still falling short, so that the day one stops, its
// exception goes; every other run is held to the comparison. docs/EXPERIMENTS.md ("The
// default camera against the thesis camera and the spring arm") says why they fall short.
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace sightline {

struct KnownShortfalls {
  std::set<std::string> body;  // runs showing half the body less often than the spring arm
  std::set<std::string> jerk;  // runs with a higher jerk p99 than the thesis camera
};

// `body` and `arm_body`: percent of frames with at least half the body visible (the
// default camera's, the spring arm's); `jerk` and `thesis_jerk`: jerk p99, m/s^3.
inline void expect_no_worse_than_baselines(const std::string& run, double body, double arm_body,
                                           double jerk, double thesis_jerk,
                                           const KnownShortfalls& known) {
  if (known.body.count(run) > 0) {
    EXPECT_LT(body, arm_body) << run << ": shows half the body as often as the spring arm "
                              << "now: drop it from the known shortfalls";
  } else {
    EXPECT_GE(body, arm_body) << run << ": frames with half the body visible (%), against the "
                              << "spring arm's on the same walk";
  }
  if (known.jerk.count(run) > 0) {
    EXPECT_GT(jerk, thesis_jerk) << run << ": no jerkier than the thesis camera now: drop it "
                                 << "from the known shortfalls";
  } else {
    EXPECT_LE(jerk, thesis_jerk) << run << ": jerk p99 (m/s^3), against the thesis camera's "
                                 << "on the same walk";
  }
}

}  // namespace sightline
