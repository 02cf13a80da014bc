// CameraProfile: what a good chase-camera shot is, as desired values and weights.
//
// Bourne & Sattar's "camera profile" (thesis section 3.1, tables 5-7): desired height of the
// camera above the character's feet, desired horizontal distance, desired orientation (the
// angle between the character's facing and the horizontal camera -> character direction;
// 0 = right behind), and a weight for each, plus a weight on frame coherence (camera speed).
// On top of those: the occlusion and clearance constraints' settings, the size of the search
// box, how enclosed and semi-enclosed areas adapt the desired height and distance (thesis
// section 3.2, table 9), and `extras`: constraint entries of any registered kind over the
// camera variables, which is how a user adds a camera constraint without writing C++.
//
// Profiles come from YAML (profile_file.h); named presets ship in domains/camera/profiles/.
// The in-class defaults below are the `thesis-default` preset.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "sightline/csp/spec.h"
#include "sightline/domains/camera/trajectory.h"

namespace sightline::camera {

enum class AreaKind { kEnclosed, kSemiEnclosed };
// "enclosed", "semi-enclosed".
const char* to_string(AreaKind kind);
std::optional<AreaKind> area_kind_from_string(const std::string& text);

// One soft constraint with a desired value: cost = weight x |desired - actual|.
struct DesiredValue {
  double desired = 0;
  double weight = 1;
};

// How an area of some kind adapts the desired height and distance while the character is in
// it (restored when it leaves). An area only ever lowers them: a high hall leaves the profile
// as it is, a low narrow room pulls the camera in and down.
struct AreaAdaptation {
  // desired height = min(profile height, area ceiling - ceiling_margin - character feet y),
  // never below 0. Absent: the height is not adapted.
  std::optional<double> ceiling_margin;
  // desired distance = min(profile distance, distance_fraction x the area's smaller
  // horizontal width). Absent: the distance is not adapted.
  std::optional<double> distance_fraction;

  bool operator==(const AreaAdaptation&) const = default;
};

// How the camera senses the space around the character on a level, which carries no areas
// (space_sensor.h): probe rays for the ceiling above the character and the free room behind
// it, low-passed over time, adapt the desired height and distance as an enclosed area would.
// Scenes with areas keep the area rule and do not sense.
struct SpaceSensing {
  bool enabled = true;
  double ceiling_probe = 6.0;   // metres above the look-at point a ceiling is looked for
  double behind_probe = 12.0;   // metres probed behind the character (toward the ideal spot)
  double wall_margin = 0.3;     // metres kept between the camera's sphere and the wall behind
  double min_distance = 1.0;    // metres: the desired distance is never pulled in below this
  double smoothing = 0.5;       // s: time constant of the low-pass on what the probes see

  bool operator==(const SpaceSensing&) const = default;
};

// How far ahead the camera looks (motion_prediction.h, constraints/future_visibility.h).
//   none:   the reactive camera: only this frame's look-at point counts;
//   motion: the character's look-at point is forecast from what a game knows this frame
//           (position, velocity, turn rate) and the geometry ahead, movers from their
//           current velocity; no future keyframe is read;
//   path:   the trajectory's and the movers' keyframes are read ahead (scripted sequences,
//           characters on a planned path).
enum class Lookahead { kNone, kMotion, kPath };
const char* to_string(Lookahead lookahead);
std::optional<Lookahead> lookahead_from_string(const std::string& text);

// The anticipation block: the soft constraint camera.future_visible over `samples` predicted
// look-at points, at horizon x k / samples seconds ahead (k = 1..samples), each weighted
// exp(-ahead / decay) (sooner matters more); cost = weight x the weighted fraction hidden.
struct Anticipation {
  static constexpr int kMaxSamples = 8;
  Lookahead lookahead = Lookahead::kNone;
  double horizon = 1.0;  // seconds ahead, in (0, 5]
  int samples = 5;       // 1 .. kMaxSamples
  double weight = 3.0;   // cost when every predicted point is hidden
  double decay = 0.6;    // seconds: time constant of the weights, > 0
  // > 0: the camera's motion is planned over the horizon (control/horizon_planner.h): each
  // frame it follows the first frame of the cheapest of a fixed set of minimum-jerk
  // trajectories at least this many seconds long, priced on the predicted points' sight
  // along them, room, framing at their end and jerk. 0 (thesis-default): the spring toward
  // the target, with cuts.smooth_escape's one-frame escapes if set. In [0, 5].
  double plan_seconds = 0;
  // With plan_seconds > 0: the most the camera's acceleration may change per second, m/s^3
  // (0: unbounded). Each frame's planned move is executed with its change of acceleration
  // clipped to max_jerk x dt when nothing is at stake (the plan keeps every predicted point
  // in sight and meets no geometry) and that move is usable too, so a new cheapest plan (the
  // smooth stop instead of the target, a side offset) is eased into over a few frames
  // instead of switching the acceleration in one. In [0, 100000].
  double max_jerk = 0;

  bool operator==(const Anticipation&) const = default;
};

// Which discretionary cuts the chase camera may make (thesis table 9). A cut forced by the
// look-at point becoming hidden from everywhere the camera can move smoothly is always
// allowed: it is the last resort. The thesis profiles keep all three; the anticipating
// preset turns them off and relies on moving early instead.
struct CutPolicy {
  bool leave_enclosed = true;  // cut when the character leaves an enclosed area
  bool backing_up = true;      // cut when it backs up into an obstruction
  bool stuck = true;           // cut when the smooth move has been blocked for a while
  // Before the last-resort cut, try short smooth moves that keep the look-at point visible
  // (up, toward the character, to either side; chase_camera.h). Off in the thesis profiles,
  // whose controller cut there.
  bool smooth_escape = false;
  // With the planner (anticipation.plan_seconds > 0, a lookahead) and smooth_escape: when no
  // planned trajectory keeps the look-at point this frame, none gets it back by the first
  // predicted sample, and a mover will hide it from where the camera is for most of the
  // horizon (a door shutting, a bus), the forced cut comes at once, to a shot that sees most
  // predicted points, instead of after a series of escapes (velocity jumps) that each buy a
  // frame (chase_camera.h). Off in the thesis profiles.
  bool cut_ahead = false;
  // A stuck cut (above) is taken only while the last 60 s hold fewer cuts than this, cuts
  // of any reason counted (a forced cut too); 0: no limit (the thesis profiles). A camera
  // left behind that keeps cutting is a camera that failed to anticipate: past the limit it
  // follows smoothly, still seeing the character, and does not cut for being late. The
  // anticipating presets set 1: a stuck cut only in a minute without another cut, which
  // leaves room for one forced cut (issue 24: at most 2 cuts a minute beyond the thesis'
  // rules, whatever their reason; at 2, two stuck cuts and a forced one made 3 in 10 s while
  // orbiting a pillar). In [0, 16].
  int stuck_per_minute = 0;

  bool operator==(const CutPolicy&) const = default;
};

struct CameraProfile {
  std::string name = "thesis-default";
  std::string description;

  DesiredValue height{2.5, 1.0};        // metres above the feet; cost per metre
  DesiredValue distance{4.0, 1.0};      // horizontal metres; cost per metre
  DesiredValue orientation{0.0, 0.02};  // degrees in [0, 180]; cost per degree
  double frame_coherence_weight = 0.002;  // cost per metre per second of camera speed

  bool look_at_hard = true;              // the look-at point must be visible (hard) ...
  double look_at_weight = 1.0;           // ... with this weight (also when soft)
  double visible_fraction_weight = 2.0;  // soft: cost = weight x (1 - visible fraction)
  double clearance_radius = 0.2;         // metres: the camera is a sphere this big
  bool clearance_hard = true;
  double clearance_weight = 1.0;         // per metre of penetration

  // Half the edge of the cube the camera may move in per frame, centred on the last camera
  // position: the domains of cam_x, cam_y, cam_z.
  double search_half_size = 2.0;

  AreaAdaptation enclosed{0.5, 0.35};
  AreaAdaptation semi_enclosed{0.5, 0.5};
  // On levels: the ceiling adapts the height with `enclosed.ceiling_margin`, the room behind
  // the character the distance (see SpaceSensing).
  SpaceSensing sensing;
  Anticipation anticipation;
  CutPolicy cuts;

  // Constraint entries ({kind: ..., scope: [cam_y], ...}) built through the kind registry
  // over the variables cam_x, cam_y, cam_z and the frame parameters (see camera_problem.h).
  std::vector<csp::Spec> extras;

  const AreaAdaptation& adaptation(AreaKind kind) const {
    return kind == AreaKind::kEnclosed ? enclosed : semi_enclosed;
  }
  // Empty when every field is in range; otherwise which field is wrong and why.
  std::string validate() const;
};

// The camera position that satisfies height, distance and orientation exactly: on the circle
// of the desired distance around the character, at the desired angle from behind (measured
// through increasing yaw), at the desired height above the feet.
Eigen::Vector3d ideal_camera_position(const CharacterState& character, double height,
                                      double distance, double orientation_degrees);

// Where a camera starts when its ideal spot may be inside a wall or behind one: `ideal` if
// `usable(ideal)`, else the farthest of 63 points pulled in from it along the line toward
// `look` (as a spring arm does) that `usable` accepts, else `ideal` (the first frame then
// cuts away). Scene::start_camera_position and the public camera share it.
template <class Usable>
Eigen::Vector3d pulled_in_start(const Eigen::Vector3d& look, const Eigen::Vector3d& ideal,
                                Usable&& usable) {
  if (usable(ideal)) return ideal;
  constexpr int kSteps = 64;
  for (int i = kSteps - 1; i > 0; --i) {
    const Eigen::Vector3d p = look + (static_cast<double>(i) / kSteps) * (ideal - look);
    if (usable(p)) return p;
  }
  return ideal;
}

}  // namespace sightline::camera
