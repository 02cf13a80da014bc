// Every solver a user meets, in the one registry (solvers::SolverRegistry::global()): the
// generic ones (built in), the camera's and the composition's, and toulbar2 when its program
// is installed. The program and the Python module both call this, so a solver's name means
// the same in either, and in the suites either runs.
#pragma once

namespace sightline::apps {

// Registers them; calling it again is harmless.
void register_all_solvers();

}  // namespace sightline::apps
