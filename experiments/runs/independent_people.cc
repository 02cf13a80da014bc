#include "sightline/experiments/runs/independent_people.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline::experiments {

bool IndependentPeople::passes_through(const Box& box, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b) {
  // Liang-Barsky clipping against each slab, strict inequalities: touching does not count.
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

IndependentPeople::IndependentPeople(const camera::Scene& scene) : scene_(&scene) {
  if (scene.has_character()) {
    people_.push_back({scene.character_name(), scene.character().size,
                       scene.character().look_at_height, &scene.trajectory()});
  }
  for (const camera::Actor& a : scene.actors()) {
    people_.push_back({a.name, a.shape.size, a.shape.look_at_height, &a.trajectory});
  }
  if (scene.level()) triangles_ = std::make_unique<IndependentTriangles>(scene.level()->mesh);
  set_time(scene.trajectory().start_time());
}

void IndependentPeople::set_time(double t) {
  boxes_.clear();
  owner_.clear();
  for (const camera::SolidBox& b : scene_->solids()) {
    boxes_.push_back({b.box.min, b.box.max});
    owner_.push_back(-1);
  }
  const std::size_t movers = scene_->movers().size() - scene_->actors().size();
  for (std::size_t i = 0; i < movers; ++i) {
    const camera::Mover& m = scene_->movers()[i];
    const Eigen::Vector3d feet = m.position_at(t), s = m.size();
    boxes_.push_back({feet - Eigen::Vector3d(s.x() / 2, 0, s.z() / 2),
                      feet + Eigen::Vector3d(s.x() / 2, s.y(), s.z() / 2)});
    owner_.push_back(-1);
  }
  for (std::size_t p = 0; p < people_.size(); ++p) {
    Person& person = people_[p];
    const camera::CharacterState state = person.path->state_at(t);
    person.feet = state.position;
    person.yaw = state.yaw;
    const Eigen::Vector3d& s = person.size;
    person.box = static_cast<int>(boxes_.size());
    boxes_.push_back({person.feet - Eigen::Vector3d(s.x() / 2, 0, s.z() / 2),
                      person.feet + Eigen::Vector3d(s.x() / 2, s.y(), s.z() / 2)});
    owner_.push_back(static_cast<int>(p));
  }
}

Eigen::Vector3d IndependentPeople::aim(const std::string& name) const {
  for (const Person& p : people_) {
    if (p.name == name) return p.feet + Eigen::Vector3d(0, p.look_at_height, 0);
  }
  return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
}

PersonSeen IndependentPeople::look(const JudgedCamera& c, const std::string& name) const {
  PersonSeen out;
  const auto person = std::find_if(people_.begin(), people_.end(), [&](const Person& p) { return p.name == name; });
  if (person == people_.end()) return out;
  out.found = true;
  const int own = static_cast<int>(person - people_.begin());
  // FORMATS.md's view axes and projection.
  const Eigen::Vector3d f = (c.target - c.position).normalized();
  const Eigen::Vector3d r0 = f.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d u0 = r0.cross(f);
  const double rad = c.roll * M_PI / 180;
  const Eigen::Vector3d r = std::cos(rad) * r0 + std::sin(rad) * u0;
  const Eigen::Vector3d u = std::cos(rad) * u0 - std::sin(rad) * r0;
  const double tan_half = std::tan(c.fov * M_PI / 360);
  const Box& body = boxes_[static_cast<std::size_t>(person->box)];
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  bool all_in_front = true;
  for (double i : {0.1, 0.5, 0.9}) {
    for (double j : {0.1, 0.5, 0.9}) {
      for (double k : {0.1, 0.5, 0.9}) {
        const Eigen::Vector3d q = body.lo + Eigen::Vector3d(i, j, k).cwiseProduct(body.hi - body.lo);
        const Eigen::Vector3d d = q - c.position;
        const double z = d.dot(f);
        bool framed = false;
        if (z > 0.05) {
          const double sx = (1 + d.dot(r) / (z * tan_half * c.aspect)) / 2;
          const double sy = (1 + d.dot(u) / (z * tan_half)) / 2;
          framed = sx >= 0 && sx <= 1 && sy >= 0 && sy <= 1;
          top = std::max(top, sy);
          bottom = std::min(bottom, sy);
        } else {
          all_in_front = false;
        }
        bool hidden = false;
        for (std::size_t b = 0; b < boxes_.size() && !hidden; ++b) {
          if (owner_[b] == own) continue;
          hidden = passes_through(boxes_[b], c.position, q);
        }
        if (!hidden && triangles_ && triangles_->segment_blocked(c.position, q)) hidden = true;
        out.framed += framed ? 1 : 0;
        out.seen += hidden ? 0 : 1;
        out.framed_and_seen += framed && !hidden ? 1 : 0;
        if (i == 0.5 && j == 0.9 && k == 0.5) out.head = framed && !hidden;
      }
    }
  }
  out.height = all_in_front ? top - bottom : 0;
  const Eigen::Vector3d away = c.position - (person->feet + Eigen::Vector3d(0, person->look_at_height, 0));
  double bearing = std::atan2(away.x(), away.z()) * 180 / M_PI - person->yaw;
  bearing = std::fmod(bearing + 180, 360);
  if (bearing < 0) bearing += 360;
  out.bearing = bearing - 180;
  return out;
}

}  // namespace sightline::experiments
