// Weighted costs as exact decimals, for toulbar2's formats: .wcsp holds integer costs, and
// toulbar2 reads a .cfn's costs at the precision of its upper bound's digits after the
// decimal point ("mustbe": "<10.00" is two digits; toulbar2's "CFN format"), rounding finer
// ones silently. So the writers find the fewest decimal places that hold every cost exactly,
// at most kMaxCostDecimals (toulbar2 computes with 64-bit integers at that scale), and write
// or scale each cost with that many; a cost that needs more is refused by name rather than
// rounded.
#pragma once

#include <optional>
#include <string>

namespace sightline::csp {

inline constexpr int kMaxCostDecimals = 6;

// The fewest decimal places d in 0..max_decimals with `cost` x 10^d an integer, within a
// relative 1e-9 (weighted costs such as 3 x 0.1 are not exact in binary); none when no such d.
std::optional<int> cost_decimals(double cost, int max_decimals = kMaxCostDecimals);

// 10^decimals, exactly (decimals in 0..15).
double decimal_scale(int decimals);

// `cost` in fixed notation with `decimals` places ("12.50", "3"), never in scientific
// notation, which toulbar2 does not read.
std::string fixed_decimal(double cost, int decimals);

}  // namespace sightline::csp
