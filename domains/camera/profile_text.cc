#include "sightline/domains/camera/profile_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace sightline::camera {
namespace {

// Shortest text that reads back to the same double (std::to_chars' promise).
std::string number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string flag(bool value) { return value ? "1" : "0"; }

std::string optional_number(const std::optional<double>& value) {
  return value ? number(*value) : std::string("none");
}

// A scalar as written in a file that is a number in full ("2", "2.0", "2e0") is written
// as that number; anything else as a length-prefixed string, so no text can pass for
// another's structure.
std::string scalar(const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (!text.empty() && result.ec == std::errc() && result.ptr == end && std::isfinite(value)) {
    return "n" + number(value);
  }
  return "s" + std::to_string(text.size()) + ":" + text;
}

void write_spec(const csp::Spec& spec, std::ostringstream& out) {
  switch (spec.type()) {
    case csp::Spec::Type::kNull:
      out << "~";
      return;
    case csp::Spec::Type::kNumber:
      out << "n" << number(spec.as_number());
      return;
    case csp::Spec::Type::kString:
      out << scalar(spec.as_string());
      return;
    case csp::Spec::Type::kList:
      out << "[";
      for (const csp::Spec& item : spec.items()) {
        write_spec(item, out);
        out << ",";
      }
      out << "]";
      return;
    case csp::Spec::Type::kMap: {
      // Key order in a YAML mapping means nothing, so it must not change the text.
      std::vector<const std::pair<std::string, csp::Spec>*> fields;
      for (const auto& field : spec.fields()) fields.push_back(&field);
      std::sort(fields.begin(), fields.end(),
                [](const auto* a, const auto* b) { return a->first < b->first; });
      out << "{";
      for (const auto* field : fields) {
        out << field->first.size() << ":" << field->first << "=";
        write_spec(field->second, out);
        out << ",";
      }
      out << "}";
      return;
    }
  }
}

std::string desired(const DesiredValue& value) {
  return number(value.desired) + "," + number(value.weight);
}

std::string adaptation(const AreaAdaptation& a) {
  return optional_number(a.ceiling_margin) + "," + optional_number(a.distance_fraction);
}

}  // namespace

std::string profile_text(const CameraProfile& p) {
  std::ostringstream out;
  out << "height=" << desired(p.height) << "\n"
      << "distance=" << desired(p.distance) << "\n"
      << "orientation=" << desired(p.orientation) << "\n"
      << "frame_coherence=" << number(p.frame_coherence_weight) << "\n"
      << "occlusion=" << flag(p.look_at_hard) << "," << number(p.look_at_weight) << ","
      << number(p.visible_fraction_weight) << "\n"
      << "clearance=" << number(p.clearance_radius) << "," << flag(p.clearance_hard) << ","
      << number(p.clearance_weight) << "\n"
      << "search=" << number(p.search_half_size) << "\n"
      << "enclosed=" << adaptation(p.enclosed) << "\n"
      << "semi-enclosed=" << adaptation(p.semi_enclosed) << "\n";
  const SpaceSensing& s = p.sensing;
  out << "sensing=" << flag(s.enabled) << "," << number(s.ceiling_probe) << ","
      << number(s.behind_probe) << "," << number(s.wall_margin) << ","
      << number(s.min_distance) << "," << number(s.smoothing) << "\n";
  const Anticipation& a = p.anticipation;
  out << "anticipation=" << to_string(a.lookahead) << "," << number(a.horizon) << ","
      << a.samples << "," << number(a.weight) << "," << number(a.decay) << ","
      << number(a.plan_seconds) << "," << number(a.max_jerk) << "\n";
  const CutPolicy& c = p.cuts;
  out << "cuts=" << flag(c.leave_enclosed) << "," << flag(c.backing_up) << "," << flag(c.stuck)
      << "," << flag(c.smooth_escape) << "," << flag(c.cut_ahead);
  // Only when set, so profiles without a limit keep their text (and suites their runs).
  if (c.stuck_per_minute > 0) out << "," << c.stuck_per_minute;
  out << "\n";
  out << "extras=[";
  for (const csp::Spec& extra : p.extras) {
    write_spec(extra, out);
    out << ",";
  }
  out << "]\n";
  return out.str();
}

}  // namespace sightline::camera
