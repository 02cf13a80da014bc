// A solver's options from a Python dict, as the solver registry takes them: values as
// text, booleans as true / false. solve() and compose() both pass them on.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "sightline/solvers/options.h"

namespace sightline::python {

inline solvers::OptionValues option_values(const pybind11::dict& options) {
  solvers::OptionValues values;
  for (const auto& [k, v] : options) {
    values[pybind11::str(k)] = pybind11::isinstance<pybind11::bool_>(v)
                                   ? (v.cast<bool>() ? "true" : "false")
                                   : std::string(pybind11::str(v));
  }
  return values;
}

}  // namespace sightline::python
