#include "sightline/experiments/runs/shot_metrics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>

#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/experiments/runs/independent_triangles.h"

namespace sightline::experiments {
namespace {

struct Box {
  Eigen::Vector3d lo, hi;
};

// Does the segment a-b pass through the open interior of the box? By clipping the segment
// against each slab in turn (Liang-Barsky), strict inequalities throughout.
bool passes_through(const Box& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  double t0 = 0, t1 = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = b[axis] - a[axis];
    if (std::abs(d) < 1e-300) {
      if (a[axis] <= box.lo[axis] || a[axis] >= box.hi[axis]) return false;
      continue;
    }
    double enter = (box.lo[axis] - a[axis]) / d, leave = (box.hi[axis] - a[axis]) / d;
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 >= t1) return false;
  }
  return true;
}

Box feet_box(const Eigen::Vector3d& feet, const Eigen::Vector3d& size) {
  return {feet - Eigen::Vector3d(size.x() / 2, 0, size.z() / 2),
          feet + Eigen::Vector3d(size.x() / 2, size.y(), size.z() / 2)};
}

// Where a screen point of q falls for the camera at p looking at `at` with the lens, by
// the formulas of FORMATS.md; false when not in front or outside the image.
bool in_image(const Eigen::Vector3d& p, const Eigen::Vector3d& at, double fov, double roll,
              double aspect, const Eigen::Vector3d& q) {
  const Eigen::Vector3d f = (at - p).normalized();
  const Eigen::Vector3d r0 = f.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d u0 = r0.cross(f);
  const double rad = roll * M_PI / 180;
  const Eigen::Vector3d r = std::cos(rad) * r0 + std::sin(rad) * u0;
  const Eigen::Vector3d u = std::cos(rad) * u0 - std::sin(rad) * r0;
  const Eigen::Vector3d d = q - p;
  const double z = d.dot(f);
  if (!(z > 0.05)) return false;
  const double t = std::tan(fov * M_PI / 360);
  const double sx = (1 + d.dot(r) / (z * t * aspect)) / 2, sy = (1 + d.dot(u) / (z * t)) / 2;
  return sx >= 0 && sx <= 1 && sy >= 0 && sy <= 1;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

}  // namespace

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
  std::unique_ptr<IndependentTriangles> triangles;
  if (scene.level()) triangles = std::make_unique<IndependentTriangles>(scene.level()->mesh);
  camera::CompositionProblem problem(scene, shot, trace.empty() ? 0 : trace.front().t);
  std::vector<double> satisfaction;
  int feasible = 0;
  for (const TraceRow& row : trace) {
    // Everyone's box at the frame's time: the static boxes, the movers (actors included) and
    // the followed character, each named when it is a person.
    std::vector<std::pair<std::string, Box>> boxes;
    for (const camera::SolidBox& b : scene.solids()) boxes.push_back({"", {b.box.min, b.box.max}});
    const std::size_t first_actor = scene.movers().size() - scene.actors().size();
    for (std::size_t i = 0; i < scene.movers().size(); ++i) {
      const camera::Mover& mover = scene.movers()[i];
      const std::string who = i >= first_actor ? scene.actors()[i - first_actor].name : "";
      boxes.push_back({who, feet_box(mover.position_at(row.t), mover.size())});
    }
    if (scene.has_character()) {
      boxes.push_back({scene.character_name(),
                       feet_box(scene.character_at(row.t).position, scene.character().size)});
    }
    for (std::size_t n = 0; n < names.size(); ++n) {
      const auto own = std::find_if(boxes.begin(), boxes.end(),
                                    [&](const auto& b) { return b.first == names[n]; });
      if (own == boxes.end()) continue;
      const Box body = own->second;
      int seen = 0, framed = 0;
      for (double i : {0.1, 0.5, 0.9}) {
        for (double j : {0.1, 0.5, 0.9}) {
          for (double k : {0.1, 0.5, 0.9}) {
            const Eigen::Vector3d q = body.lo + Eigen::Vector3d(i, j, k).cwiseProduct(body.hi - body.lo);
            framed += in_image(row.camera, row.target, row.fov, row.roll, shot.aspect, q) ? 1 : 0;
            bool hidden = false;
            for (const auto& [who, box] : boxes) {
              if (who == names[n]) continue;
              if (passes_through(box, row.camera, q)) {
                hidden = true;
                break;
              }
            }
            if (!hidden && triangles && triangles->segment_blocked(row.camera, q)) hidden = true;
            seen += hidden ? 0 : 1;
          }
        }
      }
      // In the image as the shot asks (its framed ranges' least low end; without one, some
      // of the person), and seen as it asks.
      const bool in_frame = asked_framed[n] < 0 ? framed > 0
                                                : framed >= asked_framed[n] * camera::kPersonSamples - 1e-9;
      if (in_frame && seen >= asked[n] * camera::kPersonSamples - 1e-9) ++shown[n];
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
