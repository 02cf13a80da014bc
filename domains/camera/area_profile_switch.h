// AreaProfileSwitch: adapts the profile's desired height and distance to the area the
// character is in, and reports when it enters or leaves one (thesis section 3.2, table 9:
// "if character is inside an enclosed area, change the desired height and distance values;
// if character comes out from an enclosed area, restore [them] and use a camera cut").
//
// The area is the innermost one (smallest volume) whose closed box contains the character's
// feet. Inside an area of kind k with adaptation a = profile.adaptation(k):
//
//   desired height   = max(0, min(profile height, ceiling - a.ceiling_margin - feet_y))
//                      where ceiling = the area's max y           (if a.ceiling_margin is set)
//   desired distance = min(profile distance, a.distance_fraction x min(width_x, width_z))
//                                                                 (if a.distance_fraction is set)
//
// Outside every area, and for anything not adapted, the profile's own values apply: leaving
// an area restores them. The desired orientation and all weights are never changed here.
// update() is O(log areas) and does not allocate.
//
// A scene with a level and no areas senses its room instead (space_sensor.h), unless the
// profile turns sensing off: the same adaptation, with probe rays in place of area boxes.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/scene_at_time.h"
#include "sightline/domains/camera/space_sensor.h"

namespace sightline::camera {

struct EffectiveProfile {
  double desired_height = 0;
  double desired_distance = 0;
  double desired_orientation = 0;
  std::optional<std::size_t> area;  // index into scene.areas(), when inside one
};

struct AreaTransition {
  std::optional<std::size_t> left;     // the area just left, if any
  std::optional<std::size_t> entered;  // the area just entered, if any
  bool changed() const { return left.has_value() || entered.has_value(); }
};

class AreaProfileSwitch {
 public:
  // Both must outlive the switch. The sensor (levels without areas) probes `scene` at its
  // current time, so a closed sliding door or a parked bus narrows the room it senses. Starts outside every area (the first update reports the
  // area the character starts in as entered).
  AreaProfileSwitch(const SceneAtTime& scene, const CameraProfile& profile);

  // Recomputes the effective values for the character and reports which area was left and
  // which entered since the previous call (moving straight from one area into another
  // reports both).
  AreaTransition update(const CharacterState& character);
  // The same for a character standing at `feet` (t = 0, facing +z).
  AreaTransition update(const Eigen::Vector3d& feet) {
    CharacterState standing;
    standing.position = feet;
    return update(standing);
  }
  // True when the room is sensed (a level without areas) rather than read from areas.
  bool senses_space() const { return senses_; }
  const EffectiveProfile& current() const { return current_; }

  // The effective values at `feet` without changing state.
  EffectiveProfile effective_at(const Eigen::Vector3d& feet) const;

 private:
  const Scene* scene_;
  const CameraProfile* profile_;
  bool senses_ = false;
  SpaceSensor sensor_;
  EffectiveProfile current_;
};

}  // namespace sightline::camera
