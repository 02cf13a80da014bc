// JSON text: a string quoted and escaped, a number (null when not finite, else %.17g, so it
// reads back exactly), so every writer of JSON (the commands' --format json, the pose file)
// spells it the same way. The report's replay data keeps its own, HTML-safe and shorter.
#pragma once

#include <string>

namespace sightline::csp {

std::string json_string(const std::string& text);
std::string json_number(double value);

}  // namespace sightline::csp
