// Interrupting a suite (Ctrl-C, SIGTERM): the runner stops starting runs, lets the runs in
// flight end, and abandons an isolated run whose child the signal killed too (a terminal's
// Ctrl-C reaches the whole process group): it leaves no result and no log, so a resumed
// suite runs it again. Results, statistics and the summary of what is done are written, and
// the outcome says the suite was interrupted (the `run` command then prints how to resume
// and exits 130; the Python module raises KeyboardInterrupt saying so).
//
// run_suite installs the handlers for its duration (InterruptionHandlers) and restores the
// ones it found, so a host (the Python module) keeps its own outside a suite.
#pragma once

#include <string>

#include "sightline/experiments/suite/suite_results.h"

namespace sightline::experiments {

// True once SIGINT or SIGTERM arrived while handlers were installed (or a test asked).
bool interruption_requested();
// What the handlers do; for tests.
void request_interruption();

// What an interrupted suite's outcome says to its user, before how to resume (which the
// caller knows: a command line, a Python call): "interrupted: 3 of 8 runs are done and saved
// (1 in flight abandoned, to run again)".
std::string interruption_text(const SuiteOutcome& outcome);

class InterruptionHandlers {
 public:
  InterruptionHandlers();   // clears the request and installs the handlers
  ~InterruptionHandlers();  // restores the previous handlers
  InterruptionHandlers(const InterruptionHandlers&) = delete;
  InterruptionHandlers& operator=(const InterruptionHandlers&) = delete;

 private:
  struct Saved;
  Saved* saved_;
};

}  // namespace sightline::experiments
