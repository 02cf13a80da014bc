#include "sightline/domains/camera/composition/pose_file.h"

#include "sightline/csp/json_text.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sightline::camera {
namespace {

std::string vector3(const Eigen::Vector3d& v) {
  return "[" + csp::json_number(v.x()) + ", " + csp::json_number(v.y()) + ", " + csp::json_number(v.z()) + "]";
}

}  // namespace

std::string pose_json(const CameraPose& pose, const CompositionProblem& problem,
                      const ShotEvaluation& e, const PoseFileExtras& extras) {
  std::ostringstream out;
  out << "{\n  \"position\": " << vector3(pose.position)
      << ",\n  \"look_at\": " << vector3(pose.look_at) << ",\n  \"roll\": " << csp::json_number(pose.roll)
      << ",\n  \"fov\": " << csp::json_number(pose.fov) << ",\n  \"aspect\": " << csp::json_number(pose.aspect)
      << ",\n  \"time\": " << csp::json_number(extras.time) << ",\n  \"feasible\": "
      << (e.feasible ? "true" : "false");
  if (!e.feasible) out << ",\n  \"why_infeasible\": " << csp::json_string(e.why_infeasible);
  out << ",\n  \"satisfaction\": " << csp::json_number(e.satisfaction) << ",\n  \"cost\": "
      << csp::json_number(e.cost) << ",\n  \"solver\": " << csp::json_string(extras.solver)
      << ",\n  \"solve_seconds\": " << csp::json_number(extras.solve_seconds) << ",\n  \"properties\": [";
  const std::vector<ShotProperty>& properties = problem.shot().properties;
  for (std::size_t i = 0; i < properties.size(); ++i) {
    const ShotProperty& p = properties[i];
    out << (i ? ",\n" : "\n") << "    {\"kind\": " << csp::json_string(p.kind) << ", \"targets\": [";
    for (std::size_t k = 0; k < p.targets.size(); ++k) out << (k ? ", " : "") << csp::json_string(p.targets[k]);
    out << "], \"line\": " << p.where.line << ", \"hard\": " << (p.hard ? "true" : "false")
        << ", \"measure\": " << csp::json_number(e.measures[i]) << ", \"score\": " << csp::json_number(e.scores[i])
        << "}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

}  // namespace sightline::camera
