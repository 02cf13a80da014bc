#include "sightline/experiments/runs/edit_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sightline/domains/camera/composition/shot.h"
#include "sightline/experiments/runs/independent_people.h"

namespace sightline::experiments {
namespace {

// The script entry whose pair draws the line of action at t (FORMATS.md): the line of
// dialogue under way (the latest begun), else the last one that ended; -1 before any.
int line_of_action(const std::vector<camera::ScriptEntry>& script, double t) {
  int now = -1, ended = -1;
  for (std::size_t i = 0; i < script.size(); ++i) {
    const camera::ScriptEntry& e = script[i];
    if (e.speaker.empty()) continue;
    if (e.t0 <= t && t < e.t1 && (now < 0 || e.t0 >= script[now].t0)) now = static_cast<int>(i);
    if (e.t1 <= t && (ended < 0 || e.t1 >= script[ended].t1)) ended = static_cast<int>(i);
  }
  return now >= 0 ? now : ended;
}

double side(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double dx = b.x() - a.x(), dz = b.z() - a.z();
  const double length = std::hypot(dx, dz);
  if (length < 1e-9) return 0;
  return (dx * (p.z() - a.z()) - dz * (p.x() - a.x())) / length;
}

double turn_degrees(const TraceRow& a, const TraceRow& b) {
  const Eigen::Vector3d f0 = (a.target - a.camera).normalized(), f1 = (b.target - b.camera).normalized();
  return std::acos(std::clamp(f0.dot(f1), -1.0, 1.0)) * 180 / M_PI;
}

bool shown(const PersonSeen& s) { return s.found && s.head && s.framed_and_seen >= 9; }

}  // namespace

const std::vector<std::string>& edit_metric_names() {
  static const std::vector<std::string> names = {
      "edit_line_crossings", "edit_jump_cuts",       "edit_short_shots",
      "edit_cuts_per_min",   "edit_mean_shot_s",     "edit_speaker_shown_pct",
      "edit_speaker_readable_pct", "edit_action_shown_pct"};
  return names;
}

std::vector<double> edit_metric_values(const EditMetrics& m) {
  return {static_cast<double>(m.line_crossings), static_cast<double>(m.jump_cuts),
          static_cast<double>(m.short_shots),     m.cuts_per_minute,
          m.mean_shot_seconds,                    m.speaker_shown_percent,
          m.speaker_readable_percent,             m.action_shown_percent};
}

EditMetrics edit_metrics(const camera::Scene& scene, const std::vector<TraceRow>& trace,
                         double min_shot_seconds, double aspect) {
  EditMetrics m;
  m.frames = static_cast<int>(trace.size());
  if (trace.empty()) return m;
  static const std::vector<camera::ScriptEntry> kNone;
  const auto& script = scene.script() ? *scene.script() : kNone;
  std::vector<std::string> people;
  if (scene.has_character()) people.push_back(scene.character_name());
  for (const camera::Actor& a : scene.actors()) people.push_back(a.name);
  IndependentPeople judge(scene);
  auto camera_of = [&](const TraceRow& r) {
    return JudgedCamera{r.camera, r.target, r.fov > 0 ? r.fov : 50, r.roll, aspect};
  };
  // The largest person shown from a row's camera (0: nobody).
  auto subject_size = [&](const TraceRow& r) {
    double size = 0;
    for (const std::string& who : people) {
      const PersonSeen s = judge.look(camera_of(r), who);
      if (shown(s)) size = std::max(size, s.height);
    }
    return size;
  };
  const double dt = trace.size() > 1 ? (trace.back().t - trace.front().t) / static_cast<double>(trace.size() - 1) : 0;
  m.seconds = trace.back().t - trace.front().t + dt;
  std::vector<double> shot_starts{trace.front().t};
  int speaking = 0, speaker_shown = 0, readable = 0, acting = 0, actor_shown = 0;
  for (std::size_t f = 0; f < trace.size(); ++f) {
    const TraceRow& row = trace[f];
    judge.set_time(row.t);
    if (f > 0 && row.cut) {
      ++m.cuts;
      shot_starts.push_back(row.t);
      const int entry = line_of_action(script, row.t);
      if (entry >= 0) {
        const Eigen::Vector3d a = judge.aim(script[entry].speaker), b = judge.aim(script[entry].to);
        const double s0 = side(trace[f - 1].camera, a, b), s1 = side(row.camera, a, b);
        if ((s0 > 0.05 && s1 < -0.05) || (s0 < -0.05 && s1 > 0.05)) ++m.line_crossings;
      }
      if (turn_degrees(trace[f - 1], row) < 30) {
        const double after = subject_size(row);
        judge.set_time(trace[f - 1].t);
        const double before = subject_size(trace[f - 1]);
        judge.set_time(row.t);
        if (before > 0 && after > 0 && std::max(before, after) / std::min(before, after) < 1.5) ++m.jump_cuts;
      }
    }
    for (const camera::ScriptEntry& e : script) {
      if (row.t < e.t0 || row.t >= e.t1) continue;
      const PersonSeen s = judge.look(camera_of(row), e.speaker.empty() ? e.action : e.speaker);
      if (e.speaker.empty()) {
        ++acting;
        actor_shown += shown(s) ? 1 : 0;
      } else {
        ++speaking;
        if (shown(s)) {
          ++speaker_shown;
          if (std::abs(s.bearing) <= 90 && s.height >= 0.2) ++readable;
        }
      }
    }
  }
  m.shots = static_cast<int>(shot_starts.size());
  m.shortest_shot_seconds = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < shot_starts.size(); ++i) {
    const double end = i + 1 < shot_starts.size() ? shot_starts[i + 1] : trace.back().t + dt;
    const double length = end - shot_starts[i];
    m.shortest_shot_seconds = std::min(m.shortest_shot_seconds, length);
    if (length < min_shot_seconds - 1e-6) ++m.short_shots;
  }
  m.cuts_per_minute = m.seconds > 0 ? m.cuts / (m.seconds / 60) : 0;
  m.mean_shot_seconds = m.seconds / m.shots;
  m.speaking_seconds = speaking * dt;
  m.action_seconds = acting * dt;
  if (speaking > 0) {
    m.speaker_shown_percent = 100.0 * speaker_shown / speaking;
    m.speaker_readable_percent = 100.0 * readable / speaking;
  }
  if (acting > 0) m.action_shown_percent = 100.0 * actor_shown / acting;
  return m;
}

}  // namespace sightline::experiments
