#include "sightline/domains/camera/composition/shot_world.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sightline/domains/camera/geometry/triangle_index.h"
#include "sightline/world.h"

namespace sightline::camera {

std::array<Eigen::Vector3d, kPersonSamples> person_samples(const Aabb& body) {
  static constexpr double kAt[3] = {0.1, 0.5, 0.9};
  std::array<Eigen::Vector3d, kPersonSamples> out;
  const Eigen::Vector3d size = body.max - body.min;
  int n = 0;
  for (double i : kAt) {
    for (double j : kAt) {
      for (double k : kAt) {
        out[n++] = body.min + Eigen::Vector3d(i * size.x(), j * size.y(), k * size.z());
      }
    }
  }
  return out;
}

ShotWorld::ShotWorld(const Scene& scene, double t) : scene_(&scene) {
  if (scene.has_character()) {
    PersonAtTime p;
    p.name = scene.character_name();
    people_.push_back(p);
  }
  const std::size_t first_actor_mover = scene.movers().size() - scene.actors().size();
  for (std::size_t k = 0; k < scene.actors().size(); ++k) {
    PersonAtTime p;
    p.name = scene.actors()[k].name;
    p.mover = static_cast<int>(first_actor_mover + k);
    people_.push_back(p);
  }
  movers_.resize(scene.movers().size());
  set_time(t);
}

void ShotWorld::set_time(double t, double lead) {
  t_ = t;
  std::size_t i = 0;
  if (scene_->has_character()) {
    const CharacterState s = scene_->character_at(t);
    const Eigen::Vector3d at = s.position + lead * s.velocity;
    people_[0].body = scene_->character().body_at(at);
    people_[0].aim = scene_->character().look_at(at);
    people_[0].yaw = s.yaw;
    i = 1;
  }
  for (const Actor& actor : scene_->actors()) {
    const CharacterState s = actor.state_at(t);
    const Eigen::Vector3d at = s.position + lead * s.velocity;
    people_[i].body = actor.shape.body_at(at);
    people_[i].aim = actor.shape.look_at(at);
    people_[i].yaw = s.yaw;
    ++i;
  }
  for (std::size_t m = 0; m < movers_.size(); ++m) {
    const Mover& mover = scene_->movers()[m];
    movers_[m] = Aabb::around_feet(mover.position_at(t) + lead * mover.velocity_at(t), mover.size());
  }
}

std::optional<int> ShotWorld::find(const std::string& name) const {
  for (std::size_t i = 0; i < people_.size(); ++i) {
    if (people_[i].name == name) return static_cast<int>(i);
  }
  return std::nullopt;
}

template <class Visit>
void ShotWorld::for_each_box_near(const Aabb& span, int own, Visit&& visit) const {
  auto touches = [&](const Aabb& b) {
    return (b.min.array() <= span.max.array()).all() && (span.min.array() <= b.max.array()).all();
  };
  const int own_mover = own >= 0 ? people_[static_cast<std::size_t>(own)].mover : -1;
  for (std::size_t m = 0; m < movers_.size(); ++m) {
    if (static_cast<int>(m) != own_mover && touches(movers_[m])) visit(movers_[m]);
  }
  // The followed character is not a mover: its box blocks the others' samples.
  if (scene_->has_character() && own != 0 && touches(people_[0].body)) visit(people_[0].body);
  if (!scene_->world()) {
    scene_->solid_tree().for_each_touching(span, [&](auto index) { visit(scene_->solid_tree().box(index)); });
  }
}

bool ShotWorld::surfaces_clear(const Eigen::Vector3d& p, const Eigen::Vector3d& q) const {
  if (const sightline::World* world = scene_->world()) {
    return !world->first_hit({p.x(), p.y(), p.z()}, {q.x(), q.y(), q.z()}, t_).has_value();
  }
  return !scene_->triangle_index().segment_blocked(p, q);
}

bool ShotWorld::clear(const Eigen::Vector3d& p, const Eigen::Vector3d& q, int own) const {
  bool blocked = false;
  for_each_box_near(Aabb{p.cwiseMin(q), p.cwiseMax(q)}, own,
                    [&](const Aabb& box) { blocked = blocked || segment_enters_interior(box, p, q); });
  return !blocked && surfaces_clear(p, q);
}

int ShotWorld::count_clear(const Eigen::Vector3d& p, int own, int enough) const {
  const Aabb& body = people_[static_cast<std::size_t>(own)].body;
  // Every sight line lies in the box round p and the body: only boxes touching it can block,
  // gathered once (more than kMost of them: sample by sample).
  constexpr std::size_t kMost = 64;
  std::array<const Aabb*, kMost> near{};
  std::size_t count = 0;
  bool overflow = false;
  for_each_box_near(Aabb{p.cwiseMin(body.min), p.cwiseMax(body.max)}, own, [&](const Aabb& box) {
    if (count == kMost) {
      overflow = true;
    } else {
      near[count++] = &box;
    }
  });
  int clear_count = 0;
  for (const Eigen::Vector3d& q : person_samples(body)) {
    bool seen;
    if (overflow) {
      seen = clear(p, q, own);
    } else {
      seen = true;
      for (std::size_t i = 0; i < count && seen; ++i) seen = !segment_enters_interior(*near[i], p, q);
      seen = seen && surfaces_clear(p, q);
    }
    if (seen && ++clear_count == enough) break;
  }
  return clear_count;
}

double ShotWorld::clearance(const Eigen::Vector3d& p, double limit) const {
  double d = limit;
  if (const sightline::World* world = scene_->world()) {
    d = std::min(d, world->clearance({p.x(), p.y(), p.z()}, limit, t_));
  } else {
    d = std::min(d, scene_->clearance(p, limit));
  }
  for (const Aabb& box : movers_) d = std::min(d, box.signed_distance(p));
  if (scene_->has_character()) d = std::min(d, people_[0].body.signed_distance(p));
  return d;
}

}  // namespace sightline::camera
