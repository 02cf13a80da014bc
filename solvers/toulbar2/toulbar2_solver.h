// Toulbar2Solver (`toulbar2`): the reference weighted-CSP solver, run as a program on the
// problem, so every discrete problem the project can write as .wcsp can be solved (and the
// project's own solvers checked) by toulbar2 from the same command line.
//
// A solve writes the problem as .wcsp (csp/files/wcsp_writer.h; fractional weighted costs
// multiplied by the fewest power of ten, at most 10^6, that makes each an integer, and the
// costs toulbar2 reports divided back; a cost with more than 6 decimal places makes the
// problem unsuitable, saying so) into a fresh temporary
// directory, runs the toulbar2 binary on it with posix_spawn (no shell), its output going to
// a file there, and reads back the last solution it wrote (-w: value indices, one per
// variable), which is mapped to domain values and scored by Problem::score like any
// solver's result. Its report is parsed for the outcome: "Optimum:" is proven optimality
// (only when toulbar2 finished by itself), "No solution" a proof of infeasibility; the nodes
// it reports are the iterations. The result's message says what toulbar2 reported, and
// whether its cost agrees with the problem's own score (it must: a disagreement is a bug in
// the writer or the reader of its solution, and is said, not hidden).
//
// Limits: a time limit is kept by the wall clock (toulbar2 gets -timer with the limit
// rounded up, and is interrupted with SIGINT at the limit, which makes it stop and write its
// best, as it does on its own timer); an iteration limit becomes toulbar2's backtrack limit
// (-bt); evaluations are not toulbar2's notion and are not limited (one is counted: the
// score of its solution). Without a limit toulbar2 runs until it proves optimality. A stop
// request (SolveLimits::stop) interrupts it as the time limit does.
//
// Why a target of its own (sightline::toulbar2, registered from apps): it needs the .wcsp
// writer of csp_files, and `solvers` does not depend on csp_files (docs/ARCHITECTURE.md).
// The solver is registered only when the binary is found (Debian's toulbar2 package), so
// `sightline solvers` lists it exactly when it can run.
#pragma once

#include <optional>
#include <string>

#include "sightline/solvers/options.h"
#include "sightline/solvers/registry.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class Toulbar2Solver : public Solver {
 public:
  struct Options {
    std::string binary = "toulbar2";  // a path, or a name looked up in PATH
    bool keep_files = false;          // keep the temporary directory (its path in the message)

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  Toulbar2Solver(std::string name, Options options);
  std::string name() const override { return name_; }
  // Discrete problems whose weighted costs have at most 6 decimal places (.wcsp, scaled).
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
};

// The toulbar2 program's path: `name` itself when it holds a '/', else the first executable
// of that name along PATH; nothing when there is none.
std::optional<std::string> find_toulbar2(const std::string& name = "toulbar2");

// Registers `toulbar2` when find_toulbar2() finds the binary; returns whether it did.
// Calling it again is harmless.
bool register_toulbar2_solver(SolverRegistry& registry);

}  // namespace sightline::solvers
