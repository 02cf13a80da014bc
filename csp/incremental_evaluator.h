// IncrementalEvaluator: an assignment plus everything needed to score one-variable changes
// in O(constraints touching the variable), for local search and branch and bound.
//
// It keeps each constraint's current violation and, for constraints that offer one, their
// IncrementalState (value counts for all_different, ...). Constraints without one are
// re-evaluated with the variable changed, which is still O(arity) and always correct.
//
// A delta walks the Problem's own variable -> constraint index (one compressed array,
// shared, not copied: at a million variables a copy is tens of MB of fresh pages to fault
// in and fill at every start), and what it needs of each constraint (state, weight, hard,
// constant) is in one small per-constraint array, so it reads contiguous memory: on
// 1,000,000-queens the memory traffic, not the arithmetic, is the cost. The Problem must
// therefore get no new constraint or variable while an evaluator on it lives.
//
// Constant constraints: a caller whose moves provably never change some constraints (local
// search that only swaps values inside an all_different permutation) may name them; they
// are scored once, stay in score(), and are skipped by every delta and assign. Naming a
// constraint that a move does change makes the incremental score drift from the truth.
//
// Partial assignments (see IncrementalState): when every non-constant constraint on a
// variable supports them, the variable can be retracted (it stops counting) and placed back;
// constructive starts use this to judge a value against the variables already placed only.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "sightline/csp/problem.h"

namespace sightline::csp {

class IncrementalEvaluator {
 public:
  IncrementalEvaluator(const Problem& problem, Assignment start,
                       std::span<const ConstraintId> constant = {});

  const Problem& problem() const { return *problem_; }
  const Assignment& values() const { return values_; }
  Score score() const { return total_; }
  double violation(ConstraintId id) const { return violations_[id]; }

  // Score change if `var` took `new_value`. Does not change anything.
  Score delta(VariableId var, double new_value);
  // Sets `var` to `new_value` and updates every affected constraint.
  void assign(VariableId var, double new_value);
  // Weighted violation the variable takes part in, summed over its (non-constant)
  // constraints (0 = in no conflict). Hard constraints count with their weight like soft ones.
  double involvement(VariableId var);
  // Re-computes everything from scratch (guards against drift in long floating-point runs).
  // Every variable must be placed.
  void resynchronise();

  // Partial assignments. can_retract: every non-constant constraint on `var` has an
  // incremental state that supports them. retract: `var` stops counting (its entry in
  // values() stays but means nothing until it is placed). place_delta: the score change if
  // the retracted `var` came back at `value`, judged against the variables present only.
  // place: it comes back at `value`.
  bool can_retract(VariableId var) const;
  void retract(VariableId var);
  // Retracts distinct variables, all present, at once; a constraint whose whole scope is among them
  // is cleared in one go (IncrementalState::retract_all).
  void retract(std::span<const VariableId> vars);
  Score place_delta(VariableId var, double value);
  // True when placing the retracted `var` at `value` would raise no constraint's violation;
  // stops at the first that it would (cheaper than place_delta when most values fail).
  // Inline, and reading the occupied-key bits of states that offer them (occupied_keys)
  // without a virtual call: constructive placement calls it millions of times in a row.
  bool place_is_free(VariableId var, double value) {
    for (const Incidence& link : links(var)) {
      const IncrementalState::OccupiedKeys& keys = occupied_keys_[link.constraint];
      if (keys.occupied) {
        ++evaluations_;
        if (keys.is_occupied(link.position, value)) return false;
        continue;
      }
      const Tracked& t = tracked_[link.constraint];
      if (t.constant) continue;
      ++evaluations_;
      if (t.state->place_delta(values_, link.position, value) > 0) return false;
    }
    return true;
  }
  void place(VariableId var, double value);
  // place() for a value place_is_free accepted (IncrementalState::place_free).
  void place_free(VariableId var, double value);

  // Constraint evaluations performed so far (deltas count one per constraint touched).
  std::size_t evaluations() const { return evaluations_; }

 private:
  // What a delta needs of one constraint, in one small array indexed by ConstraintId.
  struct Tracked {
    IncrementalState* state;  // nullptr: re-evaluate the constraint
    const Constraint* constraint;
    double weight;
    bool hard;
    bool partial;   // the state supports partial assignments
    bool constant;  // named constant: skipped by every delta and assign
  };
  // Throws std::logic_error unless can_retract(var).
  void require_retractable(VariableId var) const;
  // Every constraint on `var`, constant ones included (the loops skip those).
  std::span<const Incidence> links(VariableId var) const {
    return {index_.entries + index_.starts[var], index_.entries + index_.starts[var + 1]};
  }
  void add(Score& score, ConstraintId id, double violation_change) const {
    const Tracked& t = tracked_[id];
    (t.hard ? score.hard : score.soft) += t.weight * violation_change;
  }

  const Problem* problem_;
  Assignment values_;
  std::vector<std::unique_ptr<IncrementalState>> states_;
  std::vector<double> violations_;
  std::vector<char> constant_;    // per constraint (also in tracked_, which the loops read)
  std::vector<Tracked> tracked_;  // per constraint
  // Per constraint, the occupied-key view of a partial state that offers one (only
  // place_is_free reads it: kept out of Tracked, which every delta reads).
  std::vector<IncrementalState::OccupiedKeys> occupied_keys_;
  // The Problem's variable -> constraint index (see links()).
  Problem::IncidenceIndex index_;
  std::vector<std::uint32_t> hits_;  // retract(vars)'s per-constraint scratch
  // Every non-constant constraint supports partial assignments, so every variable can be
  // retracted: can_retract answers at once instead of walking the variable's links (a
  // constructive start asks it of a million variables).
  bool all_partial_ = false;
  Score total_;
  std::size_t evaluations_ = 0;
};

}  // namespace sightline::csp
