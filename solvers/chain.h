// ChainSolver (`chain`): exact dynamic programming over a sequence of variables (Viterbi), as
// an editor cuts a film slot by slot (Galvane et al. 2015) or a rota fills its days.
//
// It works on problems whose variables, in id order, form a chain: every domain discrete;
// every constraint unary, binary over two consecutive variables (i, i + 1), or a run-length
// constraint (csp::Constraint::run_lengths(), the `stretch` kind) over all the variables in
// id order. The state at variable i is its value and how long the run of equal values
// ending there is (capped at the largest minimum length, or one past the largest maximum:
// each step beyond a maximum costs its share), so the optimum is exact: hard
// violation first, then cost, as csp::Score orders them. Work: n x D^2 x L transitions for
// n variables of at most D values and runs capped at L; the solver refuses problems above
// `max_transitions` and problems that are not chains (unsuitable_reason says which
// constraint breaks the chain). The start assignment is not used.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class ChainSolver : public Solver {
 public:
  struct Options {
    std::int64_t max_transitions = 2'000'000'000;  // n x D^2 x L above which it refuses

    static const OptionSchema<Options>& schema();
    std::string validate() const;
  };

  ChainSolver(std::string name, Options options) : name_(std::move(name)), options_(options) {}
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
};

}  // namespace sightline::solvers
