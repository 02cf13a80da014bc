// A solve asked to stop from another thread after a delay (SolveLimits::stop, as the Python
// module's Ctrl-C does), for the tests of every solver's answer to a stop request.
#pragma once

#include <atomic>
#include <chrono>
#include <thread>

#include "sightline/solvers/solver.h"

namespace sightline::solvers::testing {

inline SolverResult solve_asked_to_stop(Solver& solver, const csp::Problem& problem,
                                        std::chrono::milliseconds delay) {
  std::atomic<bool> stop{false};
  SolveContext context;
  context.limits.stop = &stop;
  std::thread asker([&stop, delay] {
    std::this_thread::sleep_for(delay);
    stop = true;
  });
  const SolverResult r = solver.solve(problem, problem.default_assignment(), context);
  asker.join();
  return r;
}

}  // namespace sightline::solvers::testing
