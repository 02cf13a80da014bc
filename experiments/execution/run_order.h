// RunOrder: the order in which a dispatcher hands out a suite's unfinished runs, longest
// expected first.
//
// Runs are handed to workers on demand. Started in suite order, a long run drawn last keeps
// one worker busy while the others sit idle at the end; started longest first, the short
// runs fill the gaps (the classic LPT rule). Only the order depends on these guesses, never
// a result, so rough numbers do: the expected time of a run is
//   camera run: frames x (per-frame overhead + the solver's guessed time per frame), times
//               4 on a level scene (triangle queries instead of boxes); a pipeline "a>b"
//               costs the sum of its stages;
//   toy run:    its problem size (N-queens: N^2 pairs; a problem file or graph: its size in
//               bytes, times the colours for a graph) x a per-solver factor, capped at the
//               suite's time limit when it has one.
// The numbers are guesses in seconds (docs/CLUSTER.md lists them); ties keep suite order.
#pragma once

#include <cstddef>
#include <vector>

#include "sightline/experiments/suite/suite.h"

namespace sightline::experiments {

// The guessed wall time of `run`, in seconds (> 0). For ordering only; never reported.
double expected_run_seconds(const Suite& suite, const SuiteRun& run);

// `pending` (indices into `runs`) sorted by expected_run_seconds, longest first; runs with
// equal guesses keep their order in `pending`.
std::vector<std::size_t> longest_first(const Suite& suite, const std::vector<SuiteRun>& runs,
                                       std::vector<std::size_t> pending);

}  // namespace sightline::experiments
