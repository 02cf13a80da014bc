// JSON text: a string quoted and escaped, a number (null when not finite, else %.17g, so it
// reads back exactly), so every writer of JSON (the commands' --format json, the pose file)
// spells it the same way; and a number's shortest exact text, for messages and names. The
// report's replay data keeps its own, HTML-safe and shorter.
#pragma once

#include <string>

namespace sightline::csp {

std::string json_string(const std::string& text);
std::string json_number(double value);
// The shortest text that reads back to the same double ("5", "0.1", "1e+20"; std::to_chars),
// for messages and names, where %.17g's "0.10000000000000001" and to_string's "5.000000"
// read badly.
std::string short_number(double value);

}  // namespace sightline::csp
