// JSON text for the commands' --format json: a string quoted and escaped, a number (null
// when not finite), so every command spells JSON the same way.
#pragma once

#include <string>

namespace sightline::apps {

std::string json_string(const std::string& text);
std::string json_number(double value);

}  // namespace sightline::apps
