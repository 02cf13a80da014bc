// SpaceSensor: how much room the camera has around the character on a level, sensed with
// probe rays, for levels that carry no areas (thesis section 5.2's first limitation: the
// camera knew rooms only because someone drew their boxes).
//
// Each frame, from the look-at point L (the character's feet + look_at_height):
//   ceiling: a ray straight up, sensing.ceiling_probe long; the ceiling's height above the
//            feet, or L's height + the probe length when nothing is hit;
//   behind:  three horizontal rays toward where the profile wants the camera (the facing
//            turned by the desired orientation, then reversed) and 30 degrees to either side,
//            sensing.behind_probe long; the free room is the longest of the three (the
//            solver may swing the camera to the clearest side).
// Both are low-passed with time constant sensing.smoothing (first frame: taken as sensed), so
// a doorway or a pillar passing by does not jerk the profile. The adaptation is the area
// rule's, with the sensed room in place of an area's box:
//   desired height   = max(0, min(profile height, ceiling - enclosed.ceiling_margin))
//                      (only when enclosed.ceiling_margin is set)
//   desired distance = min(profile distance,
//                          max(sensing.min_distance,
//                              room behind - clearance radius - sensing.wall_margin))
// A sensor updates once per character time: calling it again for the same t changes
// nothing (the controller re-parameterises a frame twice when it searches a new shot).
// Four rays per frame; no allocation.
#pragma once

#include <Eigen/Core>

#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/scene_at_time.h"
#include "sightline/domains/camera/trajectory.h"

namespace sightline::camera {

class SpaceSensor {
 public:
  // Both must outlive the sensor. The probes see `scene` at its current time (movers
  // included); its owner sets that time to the character's before update().
  SpaceSensor(const SceneAtTime& scene, const CameraProfile& profile)
      : scene_(&scene), profile_(&profile) {}

  // Senses around `character` (at character.t) and low-passes what it sees.
  void update(const CharacterState& character);
  // Smoothed: the ceiling's height above the feet, and the free room behind (metres).
  double ceiling() const { return ceiling_; }
  double room_behind() const { return room_behind_; }
  // The desired height and distance this room allows (see the header comment).
  double desired_height() const;
  double desired_distance() const;

 private:
  const SceneAtTime* scene_;
  const CameraProfile* profile_;
  bool started_ = false;
  double last_t_ = 0;
  double ceiling_ = 0;
  double room_behind_ = 0;
};

}  // namespace sightline::camera
