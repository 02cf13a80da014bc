#include "sightline/domains/camera/composition/pose_file.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sightline::camera {
namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char u[8];
          std::snprintf(u, sizeof u, "\\u%04x", c);
          out += u;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string vector3(const Eigen::Vector3d& v) {
  return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]";
}

}  // namespace

std::string pose_json(const CameraPose& pose, const CompositionProblem& problem,
                      const ShotEvaluation& e, const PoseFileExtras& extras) {
  std::ostringstream out;
  out << "{\n  \"position\": " << vector3(pose.position)
      << ",\n  \"look_at\": " << vector3(pose.look_at) << ",\n  \"roll\": " << number(pose.roll)
      << ",\n  \"fov\": " << number(pose.fov) << ",\n  \"aspect\": " << number(pose.aspect)
      << ",\n  \"time\": " << number(extras.time) << ",\n  \"feasible\": "
      << (e.feasible ? "true" : "false");
  if (!e.feasible) out << ",\n  \"why_infeasible\": " << quoted(e.why_infeasible);
  out << ",\n  \"satisfaction\": " << number(e.satisfaction) << ",\n  \"cost\": "
      << number(e.cost) << ",\n  \"solver\": " << quoted(extras.solver)
      << ",\n  \"solve_seconds\": " << number(extras.solve_seconds) << ",\n  \"properties\": [";
  const std::vector<ShotProperty>& properties = problem.shot().properties;
  for (std::size_t i = 0; i < properties.size(); ++i) {
    const ShotProperty& p = properties[i];
    out << (i ? ",\n" : "\n") << "    {\"kind\": " << quoted(p.kind) << ", \"targets\": [";
    for (std::size_t k = 0; k < p.targets.size(); ++k) out << (k ? ", " : "") << quoted(p.targets[k]);
    out << "], \"line\": " << p.where.line << ", \"hard\": " << (p.hard ? "true" : "false")
        << ", \"measure\": " << number(e.measures[i]) << ", \"score\": " << number(e.scores[i])
        << "}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

}  // namespace sightline::camera
