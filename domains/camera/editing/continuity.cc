#include "sightline/domains/camera/editing/continuity.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sightline::camera {

std::optional<std::size_t> line_under_way(const std::vector<ScriptEntry>& script, double t) {
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < script.size(); ++i) {
    const ScriptEntry& e = script[i];
    if (e.speaker.empty() || t < e.t0 || t >= e.t1) continue;
    if (!found || e.t0 >= script[*found].t0) found = i;
  }
  return found;
}

std::optional<std::size_t> line_of_action_entry(const std::vector<ScriptEntry>& script, double t) {
  if (auto now = line_under_way(script, t)) return now;
  std::optional<std::size_t> last;
  for (std::size_t i = 0; i < script.size(); ++i) {
    const ScriptEntry& e = script[i];
    if (e.speaker.empty() || e.t1 > t) continue;
    if (!last || e.t1 >= script[*last].t1) last = i;
  }
  return last;
}

double side_of_line(const Eigen::Vector3d& point, const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b) {
  const Eigen::Vector2d d(b.x() - a.x(), b.z() - a.z());
  const double length = d.norm();
  if (length < 1e-9) return 0;
  const Eigen::Vector2d q(point.x() - a.x(), point.z() - a.z());
  // ((b - a) x (point - a)).y = dz qx - dx qz.
  return (d.y() * q.x() - d.x() * q.y()) / length;
}

bool crosses_line(const Eigen::Vector3d& before, const Eigen::Vector3d& after,
                  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const ContinuityRules& rules) {
  const double s0 = side_of_line(before, a, b), s1 = side_of_line(after, a, b);
  return (s0 > rules.line_margin && s1 < -rules.line_margin) ||
         (s0 < -rules.line_margin && s1 > rules.line_margin);
}

double view_turn_degrees(const CameraPose& before, const CameraPose& after) {
  const Eigen::Vector3d f0 = (before.look_at - before.position).normalized();
  const Eigen::Vector3d f1 = (after.look_at - after.position).normalized();
  return std::acos(std::clamp(f0.dot(f1), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

bool is_jump_cut(const CameraPose& before, double size_before, const CameraPose& after,
                 double size_after, const ContinuityRules& rules) {
  if (view_turn_degrees(before, after) >= rules.jump_angle_degrees) return false;
  if (!(size_before > 0) || !(size_after > 0)) return false;
  const double ratio = std::max(size_before, size_after) / std::min(size_before, size_after);
  return ratio < rules.size_step;
}

}  // namespace sightline::camera
