// Domain: the set of values a variable may take.
//
// Three kinds, as weighted-CSP tools know them: an integer range [lo, hi], an explicit set
// of values (discrete, kept sorted and unique), and a real interval [lo, hi] (continuous).
// Every value is a double; integers are represented exactly. Discrete domains can be walked
// by index (0 .. size()-1), which is how files such as toulbar2's .wcsp name values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sightline::csp {

enum class DomainKind { kIntegerRange, kValueSet, kRealInterval };

class Domain {
 public:
  // Factories; they validate (finite bounds, lo <= hi, non-empty set) and throw
  // std::invalid_argument with a message saying what was wrong.
  static Domain integer_range(std::int64_t lo, std::int64_t hi);
  static Domain value_set(std::vector<double> values);
  static Domain real_interval(double lo, double hi);

  DomainKind kind() const { return kind_; }
  bool is_discrete() const { return kind_ != DomainKind::kRealInterval; }
  bool is_continuous() const { return kind_ == DomainKind::kRealInterval; }

  // Number of values of a discrete domain (0 for a continuous one). Inline, as value_at:
  // local search calls both in its inner loops.
  std::size_t size() const {
    switch (kind_) {
      case DomainKind::kIntegerRange: return static_cast<std::size_t>(hi_ - lo_) + 1;
      case DomainKind::kValueSet: return values_.size();
      case DomainKind::kRealInterval: return 0;
    }
    return 0;
  }
  // The index-th value of a discrete domain (index < size()).
  double value_at(std::size_t index) const {
    return kind_ == DomainKind::kValueSet ? values_[index] : lo_ + static_cast<double>(index);
  }
  // The index of a value in a discrete domain, if it belongs to it.
  std::optional<std::size_t> index_of(double value) const;

  double lower() const { return lo_; }
  double upper() const { return hi_; }
  // Midpoint for continuous domains; the middle value for discrete ones.
  double middle() const;
  bool contains(double value) const;
  // Nearest member of the domain (clamped for intervals and ranges).
  double clamp(double value) const;
  // "int[0,7]", "{1,2,5}", "real[-1,1]".
  std::string describe() const;

 private:
  Domain() = default;
  DomainKind kind_ = DomainKind::kIntegerRange;
  double lo_ = 0, hi_ = 0;
  std::vector<double> values_;  // only for kValueSet, sorted and unique
};

}  // namespace sightline::csp
