#include "sightline/experiments/runs/shot_metrics.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/experiments/runs/independent_people.h"

namespace sightline::experiments {
namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

}  // namespace

const std::vector<std::string>& shot_metric_names() {
  static const std::vector<std::string> names = {"shot_shown_min_pct", "shot_satisfaction_mean",
                                                 "shot_satisfaction_p10", "shot_feasible_pct"};
  return names;
}

std::vector<double> shot_metric_values(const ShotMetrics& m) {
  return {m.shown_percent_min, m.satisfaction_mean, m.satisfaction_p10, m.feasible_percent};
}

ShotMetrics shot_metrics(const camera::Scene& scene, const std::vector<TraceRow>& trace) {
  const camera::Shot& shot = *scene.shot();
  ShotMetrics m;
  // The people the shot wants in the image (not those it only keeps out), and the fraction
  // of each one's samples it asks to see: the least low end of their visible ranges, else a
  // half.
  std::vector<std::string> names;
  std::vector<double> asked, asked_framed;
  for (const camera::ShotProperty& p : shot.properties) {
    if ((p.kind == "framed" || p.kind == "visible") && p.range.hi <= 0) continue;
    for (const std::string& t : p.targets) {
      auto it = std::find(names.begin(), names.end(), t);
      if (it == names.end()) {
        names.push_back(t);
        asked.push_back(-1);
        asked_framed.push_back(-1);
        it = names.end() - 1;
      }
      if (p.kind == "visible" || p.kind == "framed") {
        double& a = (p.kind == "visible" ? asked : asked_framed)[static_cast<std::size_t>(it - names.begin())];
        a = a < 0 ? p.range.lo : std::min(a, p.range.lo);
      }
    }
  }
  for (double& a : asked) a = a < 0 ? 0.5 : a;
  std::vector<int> shown(names.size(), 0);
  IndependentPeople people(scene);
  camera::CompositionProblem problem(scene, shot, trace.empty() ? 0 : trace.front().t);
  std::vector<double> satisfaction;
  int feasible = 0;
  for (const TraceRow& row : trace) {
    people.set_time(row.t);
    const JudgedCamera camera{row.camera, row.target, row.fov, row.roll, shot.aspect};
    for (std::size_t n = 0; n < names.size(); ++n) {
      const PersonSeen look = people.look(camera, names[n]);
      if (!look.found) continue;
      // In the image as the shot asks (its framed ranges' least low end; without one, some
      // of the person), and seen as it asks.
      const bool in_frame = asked_framed[n] < 0 ? look.framed > 0
                                                : look.framed >= asked_framed[n] * camera::kPersonSamples - 1e-9;
      if (in_frame && look.seen >= asked[n] * camera::kPersonSamples - 1e-9) ++shown[n];
    }
    problem.set_time(row.t);
    camera::CameraPose pose;
    pose.position = row.camera;
    pose.look_at = row.target;
    pose.fov = row.fov;
    pose.roll = row.roll;
    pose.aspect = shot.aspect;
    const camera::ShotEvaluation e = problem.evaluate(pose);
    satisfaction.push_back(e.satisfaction);
    feasible += e.feasible ? 1 : 0;
  }
  const double frames = std::max<double>(1, static_cast<double>(trace.size()));
  m.shown_percent_min = 100;
  for (std::size_t n = 0; n < names.size(); ++n) {
    m.people.push_back({names[n], 100.0 * shown[n] / frames});
    m.shown_percent_min = std::min(m.shown_percent_min, m.people.back().shown_percent);
  }
  double sum = 0;
  for (double s : satisfaction) sum += s;
  m.satisfaction_mean = sum / frames;
  m.satisfaction_p10 = percentile(satisfaction, 0.1);
  m.feasible_percent = 100.0 * feasible / frames;
  return m;
}

}  // namespace sightline::experiments
