#include "sightline/csp/kinds/constraint_entry.h"

#include <stdexcept>

namespace sightline::csp {

const std::vector<std::string>& common_constraint_fields() {
  static const std::vector<std::string> fields = {"kind",   "scope", "vars",
                                                  "weight", "hard",  "label"};
  return fields;
}

double read_weight(const Spec& entry) {
  const Spec* field = entry.find("weight");
  if (field == nullptr) return 1.0;
  const double w = field->as_number("a weight");
  if (w < 0) field->fail("expected a weight >= 0, got " + field->preview());
  return w;
}

bool read_hard(const Spec& entry) { return entry.bool_or("hard", false); }

std::unique_ptr<Constraint> create_constraint(const ConstraintKinds& kinds, const Problem& problem,
                                              const std::string& kind,
                                              std::vector<VariableId> scope, double weight,
                                              bool hard, const Spec& entry,
                                              const SourceLocation& where) {
  const ConstraintKindInfo& info = kinds.get(kind, where);
  std::vector<std::string> allowed = common_constraint_fields();
  allowed.insert(allowed.end(), info.fields.begin(), info.fields.end());
  if (!entry.is_null()) entry.check_keys(allowed);  // a non-map entry fails here too
  const std::string label = entry.is_map() ? entry.string_or("label", "") : "";

  ConstraintRequest request{problem, std::move(scope), weight, hard, entry, where};
  std::unique_ptr<Constraint> constraint;
  try {
    constraint = info.factory(request);
  } catch (const std::invalid_argument& e) {
    throw InputError(where, kind + ": " + e.what());
  }
  if (!constraint) throw InputError(where, "constraint kind '" + kind + "' built nothing");
  constraint->set_label(label);
  return constraint;
}

}  // namespace sightline::csp
