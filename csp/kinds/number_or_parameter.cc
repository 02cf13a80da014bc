#include "sightline/csp/kinds/number_or_parameter.h"

namespace sightline::csp {

NumberOrParameter NumberOrParameter::read(const Spec& field, const Parameters& parameters,
                                          const std::string& what) {
  if (field.type() == Spec::Type::kString) {
    if (auto index = parameters.find(field.as_string())) {
      return NumberOrParameter(ParameterRef(&parameters, *index));
    }
  }
  try {
    return NumberOrParameter(field.as_number(what));
  } catch (const InputError&) {
    std::string known;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      known += (known.empty() ? "" : ", ") + parameters.name(i);
    }
    field.fail("expected " + what + " or a parameter name (known parameters: " +
               (known.empty() ? "none" : known) + "), got " + field.preview());
  }
}

NumberOrParameter NumberOrParameter::read_or(const Spec& entry, const std::string& key,
                                             const Parameters& parameters, double fallback) {
  const Spec* field = entry.find(key);
  if (field == nullptr) return NumberOrParameter(fallback);
  return read(*field, parameters, "a number for '" + key + "'");
}

}  // namespace sightline::csp
