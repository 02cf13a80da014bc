// Creating a constraint from an entry: the part every front end (problem files, the C++
// builder, camera profiles) shares, so each kind's factory only reads its own fields.
//
// An entry is a Spec map such as {kind: linear, scope: [x, y], op: "<=", rhs: 3, weight: 2}.
// The common fields are: kind, scope (or its synonym vars), weight (finite, >= 0, default 1),
// hard (default false) and label (default empty). Resolving scope names to variable ids is
// the front end's business (files know array names, the builder has plain names), so it
// passes the resolved scope in.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/problem.h"

namespace sightline::csp {

// The fields every constraint entry may carry besides its kind's own ones.
const std::vector<std::string>& common_constraint_fields();

// Weight and hard flag of an entry, validated (weight must be finite and >= 0).
double read_weight(const Spec& entry);
bool read_hard(const Spec& entry);

// Looks the kind up in `kinds` (InputError at `where` listing the known kinds when absent),
// rejects fields that are neither common nor the kind's own (InputError at the field, listing
// the allowed ones), runs the factory and sets the label. A std::invalid_argument from the
// factory becomes an InputError at `where`.
std::unique_ptr<Constraint> create_constraint(const ConstraintKinds& kinds, const Problem& problem,
                                              const std::string& kind,
                                              std::vector<VariableId> scope, double weight,
                                              bool hard, const Spec& entry,
                                              const SourceLocation& where);

}  // namespace sightline::csp
