#include "sightline/domains/camera/space_sensor.h"

#include <algorithm>
#include <cmath>

namespace sightline::camera {

void SpaceSensor::update(const CharacterState& character) {
  if (started_ && character.t == last_t_) return;
  const SpaceSensing& s = profile_->sensing;
  const Eigen::Vector3d look = scene_->scene().character().look_at(character.position);
  const double look_height = look.y() - character.position.y();

  double ceiling = look_height + s.ceiling_probe;
  const Eigen::Vector3d top = look + Eigen::Vector3d(0, s.ceiling_probe, 0);
  if (const auto hit = scene_->first_hit(look, top)) ceiling = look_height + hit->t * s.ceiling_probe;

  double room = 0;
  const double back = character.yaw + profile_->orientation.desired + 180;
  for (double turn : {0.0, -30.0, 30.0}) {
    const Eigen::Vector3d end = look + s.behind_probe * facing_from_yaw(back + turn);
    const auto hit = scene_->first_hit(look, end);
    room = std::max(room, hit ? hit->t * s.behind_probe : s.behind_probe);
  }

  if (!started_) {
    ceiling_ = ceiling;
    room_behind_ = room;
  } else {
    const double dt = character.t - last_t_;
    const double keep = s.smoothing > 0 && dt > 0 ? std::exp(-dt / s.smoothing) : 0.0;
    ceiling_ = keep * ceiling_ + (1 - keep) * ceiling;
    room_behind_ = keep * room_behind_ + (1 - keep) * room;
  }
  started_ = true;
  last_t_ = character.t;
}

double SpaceSensor::desired_height() const {
  const double h = profile_->height.desired;
  if (!profile_->enclosed.ceiling_margin) return h;
  return std::max(0.0, std::min(h, ceiling_ - *profile_->enclosed.ceiling_margin));
}

double SpaceSensor::desired_distance() const {
  const SpaceSensing& s = profile_->sensing;
  const double fits = room_behind_ - profile_->clearance_radius - s.wall_margin;
  return std::min(profile_->distance.desired, std::max(s.min_distance, fits));
}

}  // namespace sightline::camera
