// Problem: a weighted CSP instance: variables with domains, constraints, parameters, and the
// variable -> constraint index that keeps every one-variable delta O(constraints touching it).
//
// The Problem owns its constraints. It evaluates whole assignments (Score, per-constraint
// breakdown, feasibility) and one-variable changes; solvers that move one variable at a time
// should use IncrementalEvaluator, which adds per-constraint incremental state on top.
// Values are indexed by VariableId; see Assignment.
//
// Storage is flat so that a model of millions of variables (1,000,000-queens) costs little to
// build and to free: a batch from add_variables keeps one prefix, not a name per variable,
// and shares one Domain; the variable -> constraint index is built on first use in one
// compressed array (CSR) rather than one small vector per variable. variable() and
// variables() still hand out Variable records, made on first call (see there).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/csp/domain.h"
#include "sightline/csp/parameters.h"
#include "sightline/csp/score.h"

namespace sightline::csp {

using Assignment = std::vector<double>;

struct Variable {
  std::string name;
  Domain domain;
};

// One entry of the variable -> constraint index: the constraint, and where the variable sits
// in its scope (so incremental states can be addressed in O(1)).
struct Incidence {
  ConstraintId constraint;
  std::uint32_t position;
};

struct ConstraintCost {
  ConstraintId id;
  double violation;  // raw violation (0 = satisfied)
  double cost;       // weight x violation
  bool hard;
};

class Problem {
 public:
  explicit Problem(std::string name = "problem") : name_(std::move(name)) {}
  Problem(const Problem&) = delete;
  Problem& operator=(const Problem&) = delete;

  const std::string& name() const { return name_; }
  void set_name(std::string name) { name_ = std::move(name); }

  // Adds a variable; throws std::invalid_argument on an empty or duplicate name.
  VariableId add_variable(std::string name, Domain domain);
  // Adds `count` variables named prefix0 .. prefix<count-1> (decimal, no leading zeros),
  // each with `domain`, and returns the first one's id (the others follow in order). The
  // same as as many add_variable calls, but without a name-index insert per variable: a
  // model of a million variables (1,000,000-queens) would spend more on the index than on
  // its solve. The index catches up when a name is looked up or a variable added one at a
  // time. Throws std::invalid_argument on an empty prefix, or when an existing name has
  // that form (it would be defined twice).
  VariableId add_variables(std::string_view prefix, std::size_t count, const Domain& domain);
  // Adds a constraint; throws std::invalid_argument if its scope names an unknown variable,
  // repeats a variable, or is empty. Returns its id (ids are dense, in order of addition).
  ConstraintId add_constraint(std::unique_ptr<Constraint> constraint);

  std::size_t num_variables() const { return domain_slot_.size(); }
  std::size_t num_constraints() const { return constraints_.size(); }
  // A variable's domain; O(1), no allocation. Prefer it to variable(id).domain.
  const Domain& domain(VariableId id) const { return domains_[domain_slot_[id]]; }
  // A variable's name (made from its batch's prefix for add_variables batches).
  std::string variable_name(VariableId id) const;
  // How messages, tables and breakdowns name a constraint: its label, else its kind over
  // its variables' names, "not_equal(WA, NT)".
  std::string constraint_name(ConstraintId id) const;
  // A constraint's variables' names, "WA, NT"; past 8 of them the first 6 and the count
  // ("q0, q1, q2, q3, q4, q5, ... 1000 variables"), so a message stays a line.
  std::string scope_names(ConstraintId id) const;
  // Name and domain as one record. The records are made for every variable on the first
  // call of either (a copy of each name and domain: on a million-variable model that is as
  // much as building it), so code that runs on large models uses domain() and
  // variable_name(). The references stay valid until a variable is added.
  const Variable& variable(VariableId id) const { return variables()[id]; }
  const std::vector<Variable>& variables() const;
  std::optional<VariableId> find_variable(std::string_view name) const;
  // Re-parameterisation: replaces a variable's domain (the camera's search box moves with the
  // character every frame). Constraints and the index are untouched. After the first call
  // for a variable of a batch, no allocation beyond the domain's own.
  void set_domain(VariableId id, Domain domain);
  const Constraint& constraint(ConstraintId id) const { return *constraints_[id]; }
  Constraint& mutable_constraint(ConstraintId id) { return *constraints_[id]; }
  // The constraints `id` takes part in, in order of addition. The index is built on the
  // first call after constraints were added (O(total scope size)); the span stays valid
  // until a constraint is added. Throws std::length_error when the scopes hold 2^32 or
  // more variable occurrences in all.
  std::span<const Incidence> incidences(VariableId id) const {
    if (!incidence_ready_.load(std::memory_order_acquire)) build_incidences();
    return {incidence_.data() + incidence_start_[id],
            incidence_start_[id + 1] - incidence_start_[id]};
  }
  // The whole index at once, for code that walks it in hot loops and should not test
  // whether it is built at every call (IncrementalEvaluator shares it instead of keeping
  // a copy): variable v's incidences are entries[starts[v] .. starts[v + 1]). Built here if
  // needed; valid, like incidences(), until a constraint or variable is added.
  struct IncidenceIndex {
    const Incidence* entries;
    const std::uint32_t* starts;  // num_variables() + 1 of them
  };
  IncidenceIndex incidence_index() const {
    if (!incidence_ready_.load(std::memory_order_acquire)) build_incidences();
    return {incidence_.data(), incidence_start_.data()};
  }

  Parameters& parameters() { return parameters_; }
  const Parameters& parameters() const { return parameters_; }

  bool all_discrete() const;
  bool all_continuous() const;

  // Weighted score of a whole assignment (values.size() == num_variables()).
  Score score(std::span<const double> values) const;
  double cost(std::span<const double> values) const { return score(values).soft; }
  bool is_feasible(std::span<const double> values) const { return score(values).feasible(); }
  // For a search that keeps an assignment only when it beats `bound`: score(values), with
  // `complete` set, whenever it may be below `bound` (fewer hard, or as many and less soft);
  // else possibly a score at least `bound` and no more than score(values), with `complete`
  // cleared. The
  // constraints that ask nothing of an outside world (query_cost() 0) are scored first, the
  // others only when those leave the assignment able to win; a complete score is summed in
  // id order, score(values) to the bit (terms >= 0 added in the same order with some left
  // out sum to no more: rounding is monotone). `terms` is the caller's scratch, one per
  // constraint.
  Score score_below(std::span<const double> values, const Score& bound, bool& complete,
                    std::span<Score> terms) const;
  // Every constraint's violation and weighted cost, in id order.
  std::vector<ConstraintCost> breakdown(std::span<const double> values) const;
  // Weighted score contribution of one constraint.
  Score constraint_score(ConstraintId id, std::span<const double> values) const;
  // Score change if `var` took `new_value`; O(constraints touching var). `values` is
  // modified during the call and restored before it returns.
  Score delta(std::span<double> values, VariableId var, double new_value) const;

  // A start assignment: each domain's middle value.
  Assignment default_assignment() const;
  // Throws std::invalid_argument naming the first variable whose value is missing, NaN or
  // outside its domain.
  void check_assignment(std::span<const double> values) const;

 private:
  // Consecutive variables named alike: a batch from add_variables (prefix + index), or
  // variables added one at a time (their names in named_, from named_base on).
  struct NameRun {
    VariableId first = 0;
    std::size_t count = 0;
    bool generated = false;
    std::string prefix;         // generated runs only
    std::size_t named_base = 0;  // other runs: where their names start in named_
  };
  const NameRun& run_of(VariableId id) const;
  // Throws if a batch (prefix, count) would make a name that exists already.
  void check_batch_names(std::string_view prefix, std::size_t count) const;
  void build_incidences() const;
  std::string name_;
  std::vector<NameRun> runs_;
  std::vector<std::string> named_;  // names of variables added one at a time, in order
  // name -> id of variables added one at a time; a batch's names are parsed instead.
  std::unordered_map<std::string, VariableId> variable_ids_;
  // Variable v's domain is domains_[domain_slot_[v]]. A batch shares one slot; set_domain
  // gives a variable a slot of its own (slot_owner_) the first time and then reuses it.
  std::vector<Domain> domains_;
  std::vector<std::uint32_t> domain_slot_;
  std::vector<VariableId> slot_owner_;  // kSharedSlot for a batch's slot
  static constexpr VariableId kSharedSlot = ~VariableId{0};
  // The Variable records of variables(), made on first use under view_mutex_ (queries are
  // thread-safe) for variables [0, view_size_); set_domain keeps them current.
  mutable std::vector<Variable> view_;
  mutable std::atomic<std::size_t> view_size_{0};
  mutable std::mutex view_mutex_;
  std::vector<std::unique_ptr<Constraint>> constraints_;
  // CSR index: variable v's incidences are incidence_[incidence_start_[v] ..
  // incidence_start_[v + 1]), rebuilt lazily after constraints or variables were added.
  // The starts are 32-bit (4 bytes a variable, not 8): 2^32 incidences would be 32 GB of
  // index, so a problem that large is refused when the index is built (std::length_error).
  mutable std::vector<Incidence> incidence_;
  mutable std::vector<std::uint32_t> incidence_start_{0};
  mutable std::atomic<bool> incidence_ready_{true};
  mutable std::mutex incidence_mutex_;
  Parameters parameters_;
};

}  // namespace sightline::csp
