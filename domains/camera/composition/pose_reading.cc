#include "sightline/domains/camera/composition/pose_reading.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "sightline/csp/input_error.h"

namespace sightline::camera {
namespace {

using Json = nlohmann::json;

class PoseReader {
 public:
  PoseReader(std::string_view text, std::string origin) : text_(text), origin_(std::move(origin)) {}

  CameraPose read() {
    const Json doc = parse();
    if (!doc.is_object()) {
      fail(1, "expected a JSON object {\"position\": [x, y, z], \"look_at\": [x, y, z], "
              "\"roll\": r, \"fov\": f, \"aspect\": a}");
    }
    CameraPose pose;
    pose.position = vector3(doc, "position");
    pose.look_at = vector3(doc, "look_at");
    pose.roll = number(doc, "roll", "a roll in degrees");
    pose.fov = number(doc, "fov", "a vertical field of view in degrees, in (0, 180)");
    if (!(pose.fov > 0 && pose.fov < 180)) {
      fail(find_key("fov"), "fov: expected degrees in (0, 180), got " + std::to_string(pose.fov));
    }
    pose.aspect = number(doc, "aspect", "an aspect (image width / height) > 0");
    if (!(pose.aspect > 0)) {
      fail(find_key("aspect"), "aspect: expected a width / height ratio > 0, got " +
                                   std::to_string(pose.aspect));
    }
    if (!View::of(pose)) {
      fail(find_key("look_at"), "not a view: the look-at point must be away from the position "
                                "and not straight above or below it");
    }
    return pose;
  }

 private:
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw csp::InputError(location(offset), message);
  }
  // 1-based offset -> file:line:column (0: the file alone).
  csp::SourceLocation location(std::size_t offset) const {
    if (offset == 0) return {origin_, 0, 0};
    offset = std::min(offset, text_.size());
    int line = 1;
    std::size_t line_start = 0;
    for (std::size_t i = 0; i + 1 < offset; ++i) {
      if (text_[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    }
    return {origin_, line, static_cast<int>(offset - line_start)};
  }
  // Where `"key":` first appears (1-based), or 0.
  std::size_t find_key(const std::string& key, std::size_t from = 0) const {
    const std::string quoted = Json(key).dump();
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

  Json parse() {
    // A key given twice would silently keep the last: the callback sees every key.
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
      std::string what = e.what();
      if (const std::size_t colon = what.rfind(": "); colon != std::string::npos) {
        what = what.substr(colon + 2);
      }
      fail(std::max<std::size_t>(e.byte, 1), "not valid JSON (" + what + ")");
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

  const Json& field(const Json& doc, const std::string& key, const std::string& what) const {
    const auto it = doc.find(key);
    if (it == doc.end()) fail(1, "missing \"" + key + "\" (" + what + ")");
    return *it;
  }
  double number(const Json& doc, const std::string& key, const std::string& what) const {
    const Json& j = field(doc, key, what);
    if (!j.is_number()) fail(find_key(key), key + ": expected " + what + ", got " + j.dump());
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(find_key(key), key + ": expected a finite number");
    return v;
  }
  Eigen::Vector3d vector3(const Json& doc, const std::string& key) const {
    const std::string what = "a point [x, y, z] in metres";
    const Json& j = field(doc, key, what);
    if (!j.is_array() || j.size() != 3) {
      fail(find_key(key), key + ": expected " + what + ", got " + j.dump());
    }
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) {
      const Json& c = j[static_cast<std::size_t>(i)];
      if (!c.is_number() || !std::isfinite(c.get<double>())) {
        fail(find_key(key), key + ": expected " + what + " of finite numbers, got " + j.dump());
      }
      v[i] = c.get<double>();
    }
    return v;
  }

  std::string_view text_;
  std::string origin_;
};

}  // namespace

CameraPose parse_pose_json(std::string_view text, const std::string& origin) {
  try {
    return PoseReader(text, origin).read();
  } catch (const nlohmann::json::exception& e) {
    // Every type is checked before a value is read; a case missed is still bad input.
    throw csp::InputError({origin, 0, 0}, std::string("unexpected content: ") + e.what());
  }
}

CameraPose read_pose_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw csp::InputError({path, 0, 0}, "cannot read the pose file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_pose_json(text.str(), path);
}

}  // namespace sightline::camera
