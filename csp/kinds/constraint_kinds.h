// ConstraintKinds: the registry of constraint kinds that files and builders name.
//
// A kind is registered once in C++ (a name, a one-line description, and a factory that reads
// its parameters from a Spec) and can then be used by name from any problem file, camera
// profile or builder. Unknown names are answered with the list of known ones.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/csp/spec.h"

namespace sightline::csp {

class Problem;

// What a factory gets: the resolved scope, the common fields, and the kind's own parameters.
struct ConstraintRequest {
  const Problem& problem;          // for domains and parameters; the constraint is added to it
  std::vector<VariableId> scope;   // resolved variable ids, in the order written
  double weight = 1.0;
  bool hard = false;
  const Spec& params;              // the whole constraint entry (kind-specific fields inside)
  SourceLocation where;            // where the constraint was written
};

using ConstraintFactory = std::function<std::unique_ptr<Constraint>(const ConstraintRequest&)>;

struct ConstraintKindInfo {
  std::string name;
  std::string description;  // one line, for `sightline kinds` and error messages
  // Parameter fields this kind reads besides the common ones (scope/vars, weight, hard,
  // label, kind), so readers can reject misspelt fields.
  std::vector<std::string> fields;
  ConstraintFactory factory;
  // A working example, for `sightline kinds` and for the tests that take every registered
  // kind through the writers and solvers, so a kind is tested by being registered: how many
  // variables its scope takes (over small integer domains, such as 0..3) and its own fields
  // as a problem file writes them inside a flow mapping ("op: '<=', rhs: 2"; "" when it has
  // none to give).
  std::size_t example_arity = 2;
  std::string example;
};

class ConstraintKinds {
 public:
  // The process-wide registry, with the built-in kinds already registered.
  static ConstraintKinds& global();

  // Registers a kind; throws std::invalid_argument if the name is taken.
  void add(ConstraintKindInfo info);
  bool contains(const std::string& name) const { return kinds_.count(name) != 0; }
  // Throws InputError at request.where for an unknown kind, listing the known ones.
  const ConstraintKindInfo& get(const std::string& name, const SourceLocation& where) const;
  std::unique_ptr<Constraint> create(const std::string& name, const ConstraintRequest& request) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, ConstraintKindInfo> kinds_;
};

// Registers the built-in kinds (not_equal, all_different, linear, abs_deviation, table,
// expression, ...) into `kinds`. Called once by ConstraintKinds::global().
void register_builtin_kinds(ConstraintKinds& kinds);

}  // namespace sightline::csp
