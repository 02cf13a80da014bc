#include "sightline/csp/domain.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sightline::csp {

Domain Domain::integer_range(std::int64_t lo, std::int64_t hi) {
  if (lo > hi) {
    throw std::invalid_argument("empty integer range [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "]: lower bound above upper bound");
  }
  Domain d;
  d.kind_ = DomainKind::kIntegerRange;
  d.lo_ = static_cast<double>(lo);
  d.hi_ = static_cast<double>(hi);
  return d;
}

Domain Domain::value_set(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("empty value set");
  for (double v : values) {
    if (!std::isfinite(v)) throw std::invalid_argument("value set holds a non-finite value");
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  Domain d;
  d.kind_ = DomainKind::kValueSet;
  d.lo_ = values.front();
  d.hi_ = values.back();
  d.values_ = std::move(values);
  return d;
}

Domain Domain::real_interval(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    throw std::invalid_argument("real interval bounds must be finite numbers");
  }
  if (lo > hi) throw std::invalid_argument("empty real interval: lower bound above upper bound");
  Domain d;
  d.kind_ = DomainKind::kRealInterval;
  d.lo_ = lo;
  d.hi_ = hi;
  return d;
}

std::optional<std::size_t> Domain::index_of(double value) const {
  switch (kind_) {
    case DomainKind::kIntegerRange:
      if (value < lo_ || value > hi_ || value != std::floor(value)) return std::nullopt;
      return static_cast<std::size_t>(value - lo_);
    case DomainKind::kValueSet: {
      auto it = std::lower_bound(values_.begin(), values_.end(), value);
      if (it == values_.end() || *it != value) return std::nullopt;
      return static_cast<std::size_t>(it - values_.begin());
    }
    case DomainKind::kRealInterval: return std::nullopt;
  }
  return std::nullopt;
}

double Domain::middle() const {
  if (is_continuous()) return 0.5 * (lo_ + hi_);
  return value_at(size() / 2);
}

bool Domain::contains(double value) const {
  if (is_continuous()) return value >= lo_ && value <= hi_;
  return index_of(value).has_value();
}

double Domain::clamp(double value) const {
  if (std::isnan(value)) return middle();
  switch (kind_) {
    case DomainKind::kRealInterval: return std::clamp(value, lo_, hi_);
    case DomainKind::kIntegerRange: return std::clamp(std::round(value), lo_, hi_);
    case DomainKind::kValueSet: {
      auto it = std::lower_bound(values_.begin(), values_.end(), value);
      if (it == values_.end()) return values_.back();
      if (it == values_.begin()) return *it;
      return (value - *(it - 1) <= *it - value) ? *(it - 1) : *it;
    }
  }
  return value;
}

std::string Domain::describe() const {
  std::ostringstream out;
  switch (kind_) {
    case DomainKind::kIntegerRange:
      out << "int[" << static_cast<std::int64_t>(lo_) << "," << static_cast<std::int64_t>(hi_) << "]";
      break;
    case DomainKind::kValueSet: {
      out << "{";
      for (std::size_t i = 0; i < values_.size() && i < 8; ++i) out << (i ? "," : "") << values_[i];
      if (values_.size() > 8) out << ",...(" << values_.size() << " values)";
      out << "}";
      break;
    }
    case DomainKind::kRealInterval: out << "real[" << lo_ << "," << hi_ << "]"; break;
  }
  return out.str();
}

}  // namespace sightline::csp
