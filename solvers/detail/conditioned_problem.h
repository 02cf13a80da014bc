// ConditionedProblem: a discrete problem with some variables fixed at their values, as a
// problem of the other (free) variables only: what large-neighbourhood search hands to an
// exact solver.
//
// Conditioning a weighted CSP on x_F = a_F keeps, of each constraint, the function of its
// free variables obtained by fixing the others; constraints with no free variable become a
// constant and are left out (the caller compares whole assignments with the full problem,
// so the constant does not matter). Each kept constraint is a thin view of the original
// (any kind): violation() writes the free values into a full assignment that holds the
// fixed ones and asks the original; min_violation() does the same with the fixed variables
// marked assigned, so an exact solver's bounds use the fixed part too. The views share that
// full assignment (scratch), which is why one ConditionedProblem is used by one solve at a
// time. The sub-problem's variable i is free_variables()[i] of the original, with the same
// name and domain.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::solvers::detail {

class ConditionedProblem {
 public:
  // `values`: a full assignment of `problem` (the fixed variables' values are read from it);
  // `free`: the variables left free, distinct.
  ConditionedProblem(const csp::Problem& problem, std::span<const double> values,
                     std::span<const csp::VariableId> free);
  ConditionedProblem(const ConditionedProblem&) = delete;
  ConditionedProblem& operator=(const ConditionedProblem&) = delete;

  const csp::Problem& problem() const { return *sub_; }
  std::span<const csp::VariableId> free_variables() const { return free_; }
  // The free variables' values in `full`, as an assignment of the sub-problem.
  csp::Assignment restrict(std::span<const double> full) const;
  // Writes a sub-problem assignment into the full one.
  void extend(std::span<const double> sub_values, std::span<double> full) const;

  // Shared by the views: a full assignment and assigned marks (fixed variables: 1).
  struct Scratch {
    std::vector<double> values;
    std::vector<std::uint8_t> assigned;
  };

 private:
  std::vector<csp::VariableId> free_;
  std::shared_ptr<Scratch> scratch_;
  std::unique_ptr<csp::Problem> sub_;
};

}  // namespace sightline::solvers::detail
