// MotionPrediction: where the character's look-at point will be over the next second or so,
// and the geometry (movers included) at each of those moments: what the anticipating camera
// keeps in view (constraints/future_visibility.h).
//
// Each frame, update() fills K = anticipation.samples predictions at ahead_k = horizon x k / K
// seconds (k = 1..K), each with its own SceneAtTime and a weight exp(-ahead_k / decay):
//
//   lookahead: motion (the default of the anticipating preset) uses only what a game knows
//     at this frame. The character keeps its speed and its turn rate (the yaw rate between
//     the previous frame and this one, the trajectory state's yaw): the velocity is rotated
//     about +y at that rate while the look-at point is integrated in steps of at most
//     1/30 s. Each step is traced against the static geometry (Scene::first_hit): a
//     predicted point is never inside a wall. At a wall the rest of the step slides along
//     it (the component into the wall is removed, from the velocity too) and the point stops
//     kWallMargin short of the surface; a second wall in the same step stops it there.
//     Movers are forecast the same way: their current velocity carried on
//     (SceneAtTime::set_time_extrapolated), never their future keyframes. Movers are not
//     obstacles for the character's forecast: people step round each other, and a door in
//     the way is a guess we would rather not make.
//     Turning on the spot after walking (standing, turning faster than kSetOffTurnRate,
//     within kPaceMemory seconds of last moving) she is about to set off: the forecast
//     starts her at her last walking pace along her facing turned kSetOffLead seconds
//     further at her (unclamped) turn rate, at most 90 degrees (none after a snap: kSnapTurn
//     or more in one frame is a facing set, not a turn going on), and on straight from there
//     (a turn on the spot ends within a fraction of a second). A camera told only that she
//     stands saw her walk off round a doorway's edge 0.2-0.4 s later: on 144 walks of 36
//     Quake III maps never tuned on the forecast took the default camera's cuts from 80 to
//     67 (docs/CAMERA.md, "Anticipation").
//   lookahead: path reads the future: the trajectory at t + ahead_k and the movers'
//     keyframes at that time (scripted sequences, characters on a planned path).
//   lookahead: none predicts nothing (size() is 0).
//
// The turn rate is the one state a game has that the trajectory state does not carry, so
// the prediction remembers the previous frame's yaw and time. update() is idempotent for one
// character time (the controller re-parameterises a frame twice when it searches a new
// shot). Queries and update() do not allocate; the constructor sizes everything.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/domains/camera/scene_at_time.h"
#include "sightline/domains/camera/trajectory.h"

namespace sightline::camera {

class MotionPrediction {
 public:
  // Metres a predicted point stops short of a wall it runs into.
  static constexpr double kWallMargin = 0.1;
  // Longest integration step of the motion forecast, seconds.
  static constexpr double kMaxStep = 1.0 / 30.0;
  // Turn rates beyond this (degrees per second) are clamped: a yaw snapped in one frame is
  // not a turn that will go on for a second.
  static constexpr double kMaxTurnRate = 180.0;
  // Setting off (see above): below kStillSpeed horizontal m/s she stands; turning faster
  // than kSetOffTurnRate degrees per second within kPaceMemory seconds of last moving, she
  // sets off along her facing kSetOffLead seconds further into the turn.
  static constexpr double kStillSpeed = 0.2;
  static constexpr double kSetOffTurnRate = 60.0;
  static constexpr double kPaceMemory = 3.0;
  static constexpr double kSetOffLead = 0.1;
  // Degrees turned between two frames from which the facing counts as snapped.
  static constexpr double kSnapTurn = 45.0;

  struct Sample {
    double ahead = 0;  // seconds after the frame's time
    Eigen::Vector3d look_at = Eigen::Vector3d::Zero();
    double weight = 0;  // exp(-ahead / decay)
  };

  // `scene` and `settings` must outlive the prediction.
  MotionPrediction(const Scene& scene, const Anticipation& settings);

  // Predicts from the character's state at character.t.
  void update(const CharacterState& character);
  // Every sample's geometry answers its static boxes from `nearby` where it covers a sight
  // line (SceneAtTime::set_nearby; the answers are the same).
  void set_nearby(const NearbyBoxes* nearby) {
    for (auto& g : geometry_) g->set_nearby(nearby);
  }

  // Number of samples: 0 for lookahead none, else settings.samples.
  int size() const { return size_; }
  const Sample& sample(int k) const { return samples_[static_cast<std::size_t>(k)]; }
  // The geometry at sample k's time (movers forecast or read, per the lookahead mode).
  const SceneAtTime& geometry(int k) const { return *geometry_[static_cast<std::size_t>(k)]; }
  // Sum of the samples' weights (> 0 when size() > 0).
  double total_weight() const { return total_weight_; }
  // The turn rate used by the last update, degrees per second (lookahead motion).
  double turn_rate() const { return turn_rate_; }

 private:
  void predict_motion(const CharacterState& character);
  void predict_path(const CharacterState& character);

  const Scene* scene_;
  const Anticipation* settings_;
  int size_ = 0;
  std::array<Sample, Anticipation::kMaxSamples> samples_{};
  std::vector<std::unique_ptr<SceneAtTime>> geometry_;
  double total_weight_ = 0;
  bool started_ = false;
  double last_t_ = 0;
  double last_yaw_ = 0;
  double turn_rate_ = 0;
  double spin_rate_ = 0;     // the same, unclamped
  double last_turn_ = 0;     // degrees turned since the previous frame
  double moving_pace_ = 0;   // her horizontal speed when she last moved (m/s), and when
  double moved_at_ = -1e9;
};

}  // namespace sightline::camera
