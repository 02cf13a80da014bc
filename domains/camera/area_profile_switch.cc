#include "sightline/domains/camera/area_profile_switch.h"

#include <algorithm>

namespace sightline::camera {

AreaProfileSwitch::AreaProfileSwitch(const SceneAtTime& scene, const CameraProfile& profile)
    : scene_(&scene.scene()),
      profile_(&profile),
      senses_((scene.scene().level() != nullptr || scene.scene().world() != nullptr) &&
              scene.scene().areas().empty() &&
              profile.sensing.enabled),
      sensor_(scene, profile) {
  current_.desired_height = profile.height.desired;
  current_.desired_distance = profile.distance.desired;
  current_.desired_orientation = profile.orientation.desired;
}

EffectiveProfile AreaProfileSwitch::effective_at(const Eigen::Vector3d& feet) const {
  EffectiveProfile e;
  e.desired_height = profile_->height.desired;
  e.desired_distance = profile_->distance.desired;
  e.desired_orientation = profile_->orientation.desired;
  e.area = scene_->innermost_area(feet);
  if (!e.area) return e;
  const Area& area = scene_->areas()[*e.area];
  const AreaAdaptation& a = profile_->adaptation(area.kind);
  if (a.ceiling_margin) {
    const double room = area.box.max.y() - *a.ceiling_margin - feet.y();
    e.desired_height = std::max(0.0, std::min(e.desired_height, room));
  }
  if (a.distance_fraction) {
    const Eigen::Vector3d size = area.box.size();
    e.desired_distance =
        std::min(e.desired_distance, *a.distance_fraction * std::min(size.x(), size.z()));
  }
  return e;
}

AreaTransition AreaProfileSwitch::update(const CharacterState& character) {
  if (senses_) {
    sensor_.update(character);
    current_.desired_height = sensor_.desired_height();
    current_.desired_distance = sensor_.desired_distance();
    current_.desired_orientation = profile_->orientation.desired;
    return {};
  }
  const EffectiveProfile next = effective_at(character.position);
  AreaTransition transition;
  if (next.area != current_.area) {
    transition.left = current_.area;
    transition.entered = next.area;
  }
  current_ = next;
  return transition;
}

}  // namespace sightline::camera
