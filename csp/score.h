// Score: how good an assignment is, as the pair (hard violation, soft cost).
//
// Feasibility comes first: an assignment that breaks less of the hard constraints is better
// whatever its soft cost; among equally feasible ones the lower weighted soft cost wins.
// Keeping the pair (instead of one big-M sum) lets every solver compare fairly and report
// "feasible" and "cost" separately.
#pragma once

namespace sightline::csp {

struct Score {
  double hard = 0;  // sum of weight x violation over hard constraints (0 = feasible)
  double soft = 0;  // sum of weight x violation over soft constraints (the "cost")

  bool feasible() const { return hard <= 0; }
  // Strictly better, with a relative tolerance so round-off never counts as progress.
  bool better_than(const Score& other) const {
    constexpr double kTol = 1e-12;
    if (hard < other.hard - kTol * (1 + other.hard)) return true;
    if (hard > other.hard + kTol * (1 + other.hard)) return false;
    return soft < other.soft - kTol * (1 + (other.soft < 0 ? -other.soft : other.soft));
  }
  // Strictly before `other` in the exact lexicographic order (fewer hard, or as many and less
  // soft; no tolerance): the order candidates are sorted in and bounded scores compare in.
  bool before(const Score& other) const {
    return hard < other.hard || (hard == other.hard && soft < other.soft);
  }
  Score operator+(const Score& o) const { return {hard + o.hard, soft + o.soft}; }
  Score operator-(const Score& o) const { return {hard - o.hard, soft - o.soft}; }
  Score& operator+=(const Score& o) {
    hard += o.hard;
    soft += o.soft;
    return *this;
  }
};

}  // namespace sightline::csp
