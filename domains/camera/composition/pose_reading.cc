#include "sightline/domains/camera/composition/pose_reading.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "sightline/csp/files/json_source.h"
#include "sightline/csp/input_error.h"

namespace sightline::camera {
namespace {

using Json = nlohmann::ordered_json;

class PoseReader {
 public:
  PoseReader(std::string_view text, std::string origin) : source_(text, std::move(origin)) {}

  CameraPose read() {
    const Json doc = source_.parse();
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
    source_.fail(offset, message);
  }
  std::size_t find_key(const std::string& key) const { return source_.find_key(key); }

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

  csp::JsonSource source_;
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
