// Parameters: named numbers a problem's constraints read but solvers never change.
//
// Problems whose data change every step (the chase camera: where the character stands, where
// the camera was last frame, the desired orientation) are re-parameterised, not rebuilt: the
// owner writes new values here and every constraint holding a ParameterRef sees them. Solvers
// may also sweep a parameter by name (for example a desired angle) without knowing what it
// means. Indices are stable; the table only grows.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sightline::csp {

class Parameters {
 public:
  // Adds a parameter; throws std::invalid_argument if the name is taken.
  std::size_t add(std::string name, double initial_value);
  std::optional<std::size_t> find(std::string_view name) const;
  // Index of a parameter that must exist; throws std::out_of_range naming it otherwise.
  std::size_t index(std::string_view name) const;

  double get(std::size_t index) const { return values_[index]; }
  void set(std::size_t index, double value) { values_[index] = value; }
  double get(std::string_view name) const { return values_[index(name)]; }
  void set(std::string_view name, double value) { values_[index(name)] = value; }

  std::size_t size() const { return values_.size(); }
  const std::string& name(std::size_t index) const { return names_[index]; }
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<std::string> names_;
  std::vector<double> values_;
};

// A constraint's handle on one parameter: cheap to copy, reads the current value.
class ParameterRef {
 public:
  ParameterRef() = default;
  ParameterRef(const Parameters* table, std::size_t index) : table_(table), index_(index) {}
  double value() const { return table_->get(index_); }
  bool valid() const { return table_ != nullptr; }

 private:
  const Parameters* table_ = nullptr;
  std::size_t index_ = 0;
};

}  // namespace sightline::csp
