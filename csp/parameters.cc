#include "sightline/csp/parameters.h"

#include <stdexcept>

namespace sightline::csp {

std::size_t Parameters::add(std::string name, double initial_value) {
  if (find(name)) throw std::invalid_argument("parameter '" + name + "' is defined twice");
  names_.push_back(std::move(name));
  values_.push_back(initial_value);
  return values_.size() - 1;
}

std::optional<std::size_t> Parameters::find(std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return i;
  }
  return std::nullopt;
}

std::size_t Parameters::index(std::string_view name) const {
  if (auto i = find(name)) return *i;
  std::string known;
  for (const auto& n : names_) known += (known.empty() ? "" : ", ") + n;
  throw std::out_of_range("unknown parameter '" + std::string(name) + "' (known: " +
                          (known.empty() ? "none" : known) + ")");
}

}  // namespace sightline::csp
