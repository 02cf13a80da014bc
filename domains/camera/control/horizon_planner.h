// HorizonPlanner: the anticipating camera's motion, planned over the prediction horizon and
// re-planned every frame (receding horizon, after Burg, Lino and Christie 2020, who move the
// camera early along paths that keep the character's future positions visible).
//
// Why: a one-frame greedy move (the spring's step, or the best short escape around it) only
// sees the next frame. It backs the camera into spots where every one-frame move is worse
// than staying (a corner, under an overhang), so the camera freezes until a stuck cut, and
// it switches direction from one frame to the next, which is jerk.
//
// Each frame, from the camera's state (position p0, velocity v0, acceleration a0), plan()
// builds a fixed set of candidate trajectories, each a minimum-jerk quintic
// x(t) that starts at (p0, v0, a0) (so acceleration is continuous) and ends at a goal
// position with the goal's velocity and no acceleration, in T seconds:
//   goals: the followed target (the spring's target, moving at its estimated velocity);
//          offsets around it in the view's frame: up 1 m and 2 m, pulled in toward the
//          look-at point by 35% and 65% (the latter also 0.5 m up), 1.5 m to either side,
//          up 1 m and 1.5 m to either side; the previous frame's chosen offset (so a choice
//          is kept while it stays good); and a smooth stop (come to rest ahead). A goal
//          moves with the target: the quintic ends where the target will be at T.
//          And, only when the camera is left behind (farther from the ideal shot than the
//          solver searches, the straight way there blocked, the shot open and seen from her
//          look-at point, and no nearer than the frame
//          before; it then keeps following until the way is clear), the trail: the
//          newest point of the character's own recent path (her look-at points, one every
//          kTrailSpacing metres, the last kTrailPoints) that the camera sees directly. She
//          walked there, so it is open space joined to where she is now: through the
//          doorway or the gap between columns she took, where every straight goal runs
//          into the wall beside it (a camera left behind a row of columns or a doorway's
//          wall otherwise waits there until a stuck cut).
//          And, while she runs (faster than kRunningSpeed), the chase on her trail: the
//          point of her trail the desired distance behind her measured along it (at the
//          shot's height where there is room), moving on along it at her speed. On a
//          straight run it is the ideal shot, moving as fast as she does (the solver's
//          target, searched near the camera and low-passed, lags a runner); round a corner
//          it is where a camera that went her way would be, which sees round the corner
//          she just took (a runner at 6-8 m/s turns a corner faster than the target swings
//          round behind her: without it the camera lost her at most corners of the running
//          family and cut there, 3-10 times in 12-18 s). Offered at walking pace too, it
//          led the camera off into corners of rooms it then had to cut its way out of.
//          And, while it has room and sees her look-at point, the ideal shot itself (the
//          profile's height, distance and orientation from her), moving at the velocity it
//          has had (low-passed over kIdealSmoothing, at most max_speed); while she walks and
//          turns (kTurningPace, kTurningRate), where it will be if she keeps her pace and
//          turn rate, turned with her (carried on along the tangent, the shot of a character
//          circling a pillar ran off outside her circle, and the camera lagged a quarter lap
//          behind until a stuck cut). The solver's
//          target is searched within the search cube around the camera and low-passed, so
//          a goal built on it moves at most a few metres a second toward a shot that
//          moves faster: round a character who circles a pillar, turns on the spot or
//          reverses, the camera fell behind until a pillar or a wall hid her. Without it,
//          on 144 walks on 36 Quake III maps never tuned on, the camera cut 67 times
//          (with it 55), and 44 times on 66 agile walks (with it 19).
//   T = max(plan_seconds, the time a minimum-jerk move of that length needs to stay under
//          max_speed and max_acceleration): a physical bound, not a scene constant.
// Each is priced:
//   framing   the profile's soft costs (height, distance, orientation, extras) at the goal;
//   sight     anticipation.weight x the weighted fraction of the predicted look-at points
//             (MotionPrediction's samples) hidden from x(ahead_k) in the geometry at that
//             time (the same points, weights and SceneAtTime that camera.future_visible
//             reads), with the samples where x(ahead_k) is inside clearance or the path
//             from the previous sample crosses geometry counted hidden twice, and priced
//             kBlockedPrice x w_k besides (running into geometry is no guess);
//   room      kBlockedPrice for each of the positions 2, 4 and 8 frames ahead that is
//             inside clearance or reached through geometry (momentum: within a few
//             frames every candidate goes nearly the same way, so walls must be seen early);
//   jerk      kJerkPrice per m/s^3 of |x'''| over the first frame (what the jerk metric sees);
//   switch    kSwitchPrice per metre between this goal's offset and the previous choice's.
// A candidate is usable only if its first frame is a smooth move (<= max_speed x dt) to a
// spot clear of geometry that sees the look-at point, along a segment that crosses nothing.
// A first frame that grazes a wall (at most 2 cm inside clearance) is pushed out along the
// wall's normal and loses its velocity into the wall: sliding along a wall costs a few
// millimetres of jerk, where any other way out once momentum has brought the camera there
// is a velocity jump.
// The cheapest usable candidate's first frame is returned, with its change of acceleration
// clipped to max_jerk x dt when max_jerk > 0, nothing is at stake (the plan keeps every
// predicted point in sight and meets no geometry) and the clipped frame is usable too (a
// jerk bound for comfort: a new cheapest candidate, the stop after the target say, is eased
// into instead of switching the acceleration in one frame, which made the top 1% of jerk in
// a room); the rest is thrown away and the
// plan is made again next frame. Candidates are priced cheapest-first on the terms without
// queries, so most frames ask the geometry for one or two trajectories only.
// No allocation per frame; the candidate set is fixed (kCandidates). Not thread-safe (it
// remembers the previous choice); one planner per camera.
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/camera_problem.h"

namespace sightline::camera {

class HorizonPlanner {
 public:
  static constexpr int kCandidates = 14;
  // The character's trail: one look-at point every kTrailSpacing metres, the newest
  // kTrailPoints (12 m: a room or two back).
  static constexpr int kTrailPoints = 24;
  static constexpr double kTrailSpacing = 0.5;
  // m/s: above this she runs, and the chase on her trail is a candidate.
  static constexpr double kRunningSpeed = 4.0;
  // Seconds: time constant of the low-pass on the ideal shot's velocity.
  static constexpr double kIdealSmoothing = 0.1;
  // Walking faster than kTurningPace (m/s) and turning faster than kTurningRate (degrees
  // per second), her ideal shot is carried on along her turn (see plan()).
  static constexpr double kTurningPace = 1.0;
  static constexpr double kTurningRate = 5.0;
  // Cost per m/s^3 of jerk over the first frame: 300 m/s^3 (about the reactive camera's
  // p99) costs what 0.3 m off the desired distance costs.
  static constexpr double kJerkPrice = 1e-3;
  // Cost per metre of change of the chosen offset from one frame to the next.
  static constexpr double kSwitchPrice = 0.05;
  // Cost of each of the next few frames (2, 4 and 8 frames ahead) where the trajectory
  // enters clearance or crosses geometry: more than losing every predicted point (which
  // costs anticipation.weight, 3 in the preset), as the camera cannot turn in a frame.
  static constexpr double kBlockedPrice = 10.0;

  struct State {
    Eigen::Vector3d position, velocity, acceleration;
  };

  // `problem` must outlive the planner. `framing_ids`: the soft constraints priced at a
  // goal (no sight lines, no frame coherence).
  HorizonPlanner(const CameraProblem& problem, std::vector<csp::ConstraintId> framing_ids,
                 double max_speed, double max_acceleration, double plan_seconds,
                 double max_jerk = 0);

  // The state after one frame (dt seconds) along the cheapest usable candidate, or nothing
  // when no candidate's first frame is usable. `target` moves at `target_velocity`.
  std::optional<State> plan(const State& now, const Eigen::Vector3d& target,
                            const Eigen::Vector3d& target_velocity, const Eigen::Vector3d& look,
                            double dt);
  // Forgets the previous choice (after a cut).
  void reset() {
    previous_offset_.setZero();
    following_trail_ = false;
    last_off_ideal_ = std::numeric_limits<double>::infinity();
  }
  // Index of the candidate chosen by the last successful plan() (0 = the target itself).
  int last_choice() const { return last_choice_; }
  // After a plan() that found no usable first frame: whether some candidate, its first
  // frame aside, is clear of geometry and sees the first predicted look-at point at that
  // sample's time (in the geometry forecast for then): sight lost for a frame, not for good.
  bool regains_sight() const { return regains_sight_; }

 private:
  // Records her look-at point on the trail and, when the camera is left behind (see the
  // header comment), returns the trail's waypoint and sets `trail_velocity` (on along her
  // path); nullopt otherwise.
  std::optional<Eigen::Vector3d> follow_trail(const State& now, const Eigen::Vector3d& look,
                                              const Eigen::Vector3d& target_velocity,
                                              Eigen::Vector3d& trail_velocity);
  // Records her look-at point on the trail (one every kTrailSpacing metres).
  void record_trail(const Eigen::Vector3d& look);
  // The shot on her trail the desired distance behind her, measured along the trail (at
  // the shot's height where there is room, else at her look-at height), and
  // `chase_velocity`, on along her path at her speed; nullopt while the trail is shorter.
  std::optional<Eigen::Vector3d> chase_on_trail(const Eigen::Vector3d& look,
                                                const Eigen::Vector3d& ideal,
                                                Eigen::Vector3d& chase_velocity) const;
  // A point of her trail raised by `rise` (to the shot's height), when there is room there
  // and nothing between it and her path (no ceiling in the way); nullopt otherwise.
  std::optional<Eigen::Vector3d> at_shot_height(const Eigen::Vector3d& p, double rise) const;
  const Eigen::Vector3d& trail_point(int k) const {  // k = 1: the newest
    return trail_[static_cast<std::size_t>((trail_next_ + kTrailPoints - k) % kTrailPoints)];
  }

  const CameraProblem* problem_;
  std::vector<csp::ConstraintId> framing_ids_;
  double max_speed_, max_acceleration_, plan_seconds_, max_jerk_;
  Eigen::Vector3d previous_offset_ = Eigen::Vector3d::Zero();
  int last_choice_ = 0;
  // The trail, a ring: trail_[(trail_next_ - 1) mod kTrailPoints] is the newest of
  // trail_size_ points.
  std::array<Eigen::Vector3d, kTrailPoints> trail_{};
  int trail_next_ = 0, trail_size_ = 0;
  bool following_trail_ = false;  // left behind and following her trail (see above)
  double last_off_ideal_ = std::numeric_limits<double>::infinity();
  bool regains_sight_ = true;
  // The ideal shot's last position and its velocity (low-passed), for the ideal candidate.
  Eigen::Vector3d last_ideal_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d ideal_velocity_ = Eigen::Vector3d::Zero();
  bool has_ideal_ = false;
};

}  // namespace sightline::camera
