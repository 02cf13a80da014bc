// BestKeeper: remembers the best assignment a local search has visited without copying the
// whole assignment at every improvement.
//
// On 1,000,000-queens the score improves hundreds of thousands of times; copying 10^6 values
// each time would cost more than the search. Instead the keeper logs the (variable, old
// value) of every accepted change made since the best was seen, so that
//   best = current assignment with the log undone (newest change first).
// An improvement just clears the log. When the log grows past `log_limit` entries (the
// search wandered far from its best) the best is materialised once into `stored` and
// logging stops until the next improvement, so the cost stays O(1) amortised per change.
// Tentative changes that the search reverts itself must not be logged.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::solvers::detail {

class BestKeeper {
 public:
  // Starts over with `current` as the best, scored `score`.
  void reset(const csp::Assignment& current, const csp::Score& score, std::size_t log_limit) {
    stored_ = current;
    score_ = score;
    log_.clear();
    logging_ = false;
    log_limit_ = log_limit;
  }

  const csp::Score& score() const { return score_; }

  // `current` (the assignment as it is now) becomes the best, scored `score`: it is
  // strictly better than the best, or as good and the one the search ends on.
  void improved(const csp::Score& score) {
    score_ = score;
    log_.clear();
    logging_ = true;
  }

  // Variable `var` changes (is about to, or has just been tentatively changed) from
  // `old_value`. Log every variable of one move, then call check_log once with the
  // assignment as it is now: entries are logged before any materialisation, so they are
  // undone whether or not `current` already holds the new values.
  void log_change(csp::VariableId var, double old_value) {
    if (logging_) log_.emplace_back(var, old_value);
  }
  void check_log(const csp::Assignment& current) {
    if (logging_ && log_.size() > log_limit_) materialise(current);
  }

  // Makes best() valid; `current` is the assignment as it is now.
  void materialise(const csp::Assignment& current) {
    if (!logging_) return;
    stored_ = current;
    for (auto it = log_.rbegin(); it != log_.rend(); ++it) stored_[it->first] = it->second;
    log_.clear();
    logging_ = false;
  }

  // The best assignment; call materialise() first.
  const csp::Assignment& best() const { return stored_; }
  // The same, moved out at the end of a search (a copy of a million values saved); the
  // keeper holds nothing until the next reset().
  csp::Assignment take_best() {
    csp::Assignment best = std::move(stored_);
    stored_.clear();
    return best;
  }

 private:
  csp::Assignment stored_;
  csp::Score score_;
  std::vector<std::pair<csp::VariableId, double>> log_;
  bool logging_ = false;
  std::size_t log_limit_ = 0;
};

}  // namespace sightline::solvers::detail
