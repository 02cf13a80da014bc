// IncrementalEvaluator: an assignment plus everything needed to score one-variable changes
// in O(constraints touching the variable), for local search and branch and bound.
//
// It keeps each constraint's current violation and, for constraints that offer one, their
// IncrementalState (value counts for all_different, ...). Constraints without one are
// re-evaluated with the variable changed, which is still O(arity) and always correct.
#pragma once

#include <memory>
#include <vector>

#include "csp/problem.h"

namespace sightline::csp {

class IncrementalEvaluator {
 public:
  IncrementalEvaluator(const Problem& problem, Assignment start);

  const Problem& problem() const { return *problem_; }
  const Assignment& values() const { return values_; }
  Score score() const { return total_; }
  double violation(ConstraintId id) const { return violations_[id]; }

  // Score change if `var` took `new_value`. Does not change anything.
  Score delta(VariableId var, double new_value);
  // Sets `var` to `new_value` and updates every affected constraint.
  void assign(VariableId var, double new_value);
  // Weighted violation the variable takes part in, summed over its constraints (0 = in no
  // conflict). Hard constraints count with their weight like soft ones.
  double involvement(VariableId var);
  // Re-computes everything from scratch (guards against drift in long floating-point runs).
  void resynchronise();

  // Constraint evaluations performed so far (deltas count one per constraint touched).
  std::size_t evaluations() const { return evaluations_; }

 private:
  double constraint_weighted(ConstraintId id, double violation) const;

  const Problem* problem_;
  Assignment values_;
  std::vector<std::unique_ptr<IncrementalState>> states_;
  std::vector<double> violations_;
  Score total_;
  std::size_t evaluations_ = 0;
};

}  // namespace sightline::csp
