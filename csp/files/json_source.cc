#include "sightline/csp/files/json_source.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <vector>

namespace sightline::csp {

void JsonSource::fail(std::size_t offset, const std::string& message) const {
  throw InputError(location(offset), message);
}

SourceLocation JsonSource::location(std::size_t offset) const {
  if (offset == 0) return {origin_, 0, 0};
  offset = std::min(offset, text_.size());
  int line = 1;
  std::size_t line_start = 0;  // 0-based index of the line's first character
  for (std::size_t i = 0; i + 1 < offset; ++i) {
    if (text_[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return {origin_, line, static_cast<int>(offset - line_start)};
}

std::size_t JsonSource::find_key(const std::string& key, std::size_t from) const {
  const std::string quoted = nlohmann::json(key).dump();
  for (std::size_t at = text_.find(quoted, from); at != std::string_view::npos;
       at = text_.find(quoted, at + 1)) {
    std::size_t after = at + quoted.size();
    while (after < text_.size() && std::isspace(static_cast<unsigned char>(text_[after]))) {
      ++after;
    }
    if (after < text_.size() && text_[after] == ':') return at + 1;
  }
  return 0;
}

nlohmann::ordered_json JsonSource::parse(const std::string& hint) const {
  using Json = nlohmann::ordered_json;
  // Keys twice in one object would silently keep the last: the callback sees every key.
  std::vector<std::set<std::string>> keys;
  auto callback = [&](int, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::object_start) keys.emplace_back();
    if (event == Json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == Json::parse_event_t::key && !keys.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!keys.back().insert(key).second) {
        const std::size_t first = find_key(key);
        const std::size_t second = find_key(key, first);
        fail(second ? second : first, "key '" + key + "' is given twice in one object");
      }
    }
    return true;
  };
  try {
    return Json::parse(text_.begin(), text_.end(), callback);
  } catch (const Json::parse_error& e) {
    // e.byte is the 1-based index of the last character read.
    std::string what = e.what();
    if (const std::size_t colon = what.rfind(": "); colon != std::string::npos) {
      what = what.substr(colon + 2);
    }
    fail(std::max<std::size_t>(e.byte, 1), "not valid JSON (" + what + ")" + hint);
  } catch (const Json::out_of_range& e) {
    // A number no double holds (1e999): at the number, when it can be found.
    const std::string what = e.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    std::size_t at = 0;
    if (open != std::string::npos && close > open) {
      const std::size_t found = text_.find(what.substr(open + 1, close - open - 1));
      if (found != std::string_view::npos) at = found + 1;
    }
    fail(at, "a number too large for a double");
  }
}

}  // namespace sightline::csp
