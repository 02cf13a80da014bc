// The phases of `sightline nqueens N --solver sls` timed one by one, in CPU seconds: model
// building, the start assignment, the solve, the checks the command makes (domains, the
// per-constraint breakdown it prints, the independent attacking-pairs count) and freeing the
// model. Issue 16 asks for the whole process within 2x of a special-purpose solver's; this
// says which phase the rest of the time is in. CPU time, not wall: the VM is shared.
//
// Usage: build/bench/nqueens_phases [N=1000000] [ROUNDS=3]   (results: docs/BENCHMARKS.md)
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>

#include "sightline/domains/nqueens/nqueens.h"
#include "sightline/solvers/registry.h"

namespace {

double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace sightline;
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 1000000;
  const int rounds = argc > 2 ? std::stoi(argv[2]) : 3;
  std::printf("n %zu, CPU seconds per phase\n", n);
  for (int round = 0; round < rounds; ++round) {
    const double t0 = cpu_seconds();
    auto problem = nqueens::build_nqueens(n);
    const double t1 = cpu_seconds();
    const auto start = problem->default_assignment();
    const double t2 = cpu_seconds();
    auto sls = solvers::SolverRegistry::global().create("sls");
    solvers::SolveContext context;
    context.want_breakdown = false;  // timed on its own below
    const auto result = sls->solve(*problem, start, context);
    const double t3 = cpu_seconds();
    problem->check_assignment(result.best);
    const auto breakdown = problem->breakdown(result.best);
    const double t4 = cpu_seconds();
    const std::size_t pairs = nqueens::attacking_pairs(result.best);
    const double t5 = cpu_seconds();
    problem.reset();
    const double t6 = cpu_seconds();
    std::printf("build %.3f  start %.3f  solve %.3f  check+breakdown %.3f  attacking pairs %.3f"
                "  free model %.3f  (%zu attacking pairs, %zu constraints)\n",
                t1 - t0, t2 - t1, t3 - t2, t4 - t3, t5 - t4, t6 - t5, pairs, breakdown.size());
  }
  return 0;
}
