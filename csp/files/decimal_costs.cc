#include "sightline/csp/files/decimal_costs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sightline::csp {

double decimal_scale(int decimals) {
  double scale = 1;
  for (int i = 0; i < decimals; ++i) scale *= 10;
  return scale;
}

std::optional<int> cost_decimals(double cost, int max_decimals) {
  if (!std::isfinite(cost)) return std::nullopt;
  for (int d = 0; d <= max_decimals; ++d) {
    const double scaled = cost * decimal_scale(d);
    if (std::abs(scaled - std::round(scaled)) <= 1e-9 * std::max(1.0, std::abs(scaled))) return d;
  }
  return std::nullopt;
}

std::string fixed_decimal(double cost, int decimals) {
  // Rounded at the scale first, so 0.30000000000000004 is "0.3", never "0.30000000000000004".
  const double scale = decimal_scale(decimals);
  const double rounded = std::round(cost * scale) / scale;
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, rounded == 0 ? 0.0 : rounded);
  return text;
}

}  // namespace sightline::csp
