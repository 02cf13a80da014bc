#include "sightline/solvers/options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace sightline::solvers::detail {

std::int64_t parse_integer(const std::string& option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(begin, &end, 10);
  if (end == begin || *end != '\0' || errno == ERANGE) {
    // Accept integral values written in scientific notation (1e6).
    const double d = std::strtod(begin, &end);
    if (end != begin && *end == '\0' && std::isfinite(d) && d == std::floor(d) &&
        std::abs(d) < 9.0e18) {
      return static_cast<std::int64_t>(d);
    }
    throw OptionError("option '" + option + "' expects an integer, got '" + text + "'");
  }
  return v;
}

double parse_real(const std::string& option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(v)) {
    throw OptionError("option '" + option + "' expects a finite number, got '" + text + "'");
  }
  return v;
}

bool parse_bool(const std::string& option, const std::string& text) {
  if (text == "true" || text == "1" || text == "yes" || text == "on") return true;
  if (text == "false" || text == "0" || text == "no" || text == "off") return false;
  throw OptionError("option '" + option + "' expects true or false, got '" + text + "'");
}

std::string format_real(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace sightline::solvers::detail
