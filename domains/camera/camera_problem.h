// CameraProblem: one frame of chase-camera control as a weighted CSP, built once per run and
// re-parameterised every frame.
//
// Variables: cam_x, cam_y, cam_z, the camera position in metres, each a real interval: the
// search cube of half-size profile.search_half_size around the last camera position (thesis
// section 3.1: "the domains of the variables define a cube ... where the camera can be
// positioned for the next frame"). Parameters: the FrameParameters (char_x .. clearance_radius).
// Constraints, from the profile, each a registered camera kind built by its from_profile
// (constraints/camera_constraint_kinds.h), in the registry's order:
//   soft  camera.height, camera.distance, camera.orientation, camera.frame_coherence
//   hard  camera.look_at_visible (soft when profile.look_at_hard is false)
//   soft  camera.visible_fraction (left out when its weight is 0)
//   hard  camera.clearance (soft when profile.clearance_hard is false)
//   soft  camera.future_visible (with anticipation.lookahead motion or path and a weight
//         > 0: the predicted look-at points over the horizon, constraints/future_visibility.h)
//   plus the profile's `extras`, built through csp::ConstraintKinds::global() over the
//   variables above, reading any frame parameter by name.
//
// set_frame() writes the frame into the parameters and the domains: it never adds or removes
// anything and never allocates, so a solver may keep per-problem state across frames.
//
// Geometry: the problem owns a SceneAtTime, set to the character's time by set_frame(), and
// every constraint that asks the geometry (look-at visible, body visible, clearance) asks
// it, so movers count at the frame's time. Nothing here asks Scene's static-only queries.
// The problem also owns the MotionPrediction the future-visibility constraint reads;
// set_frame() updates it (once per character time).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/area_profile_switch.h"
#include "sightline/domains/camera/constraints/frame_parameters.h"
#include "sightline/domains/camera/motion_prediction.h"
#include "sightline/domains/camera/nearby_boxes.h"
#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::camera {

struct CameraConstraintKind;  // constraints/camera_constraint_kinds.h

class CameraProblem {
 public:
  struct ConstraintIds {
    csp::ConstraintId height = 0, distance = 0, orientation = 0, frame_coherence = 0;
    csp::ConstraintId look_at = 0, clearance = 0;
    std::optional<csp::ConstraintId> visible_fraction;
    std::optional<csp::ConstraintId> future_visible;
    std::vector<csp::ConstraintId> extras;
  };

  // `scene` and `profile` must outlive the problem. Throws std::invalid_argument for a
  // profile that does not validate() and csp::InputError (at the entry's location) for an
  // extra that does not build.
  CameraProblem(const Scene& scene, const CameraProfile& profile);
  // A temporary would dangle (the problem keeps pointers): refused at compile time.
  CameraProblem(const Scene&&, const CameraProfile&) = delete;
  CameraProblem(const Scene&, const CameraProfile&&) = delete;
  // Same, with the scene's own profile.
  explicit CameraProblem(const Scene& scene) : CameraProblem(scene, scene.profile()) {}

  csp::Problem& problem() { return *problem_; }
  const csp::Problem& problem() const { return *problem_; }
  const Scene& scene() const { return *scene_; }
  // The scene's geometry at the last set_frame()'s time (movers placed there).
  const SceneAtTime& scene_at_time() const { return *at_time_; }
  // The look-at points predicted at the last set_frame() (empty with lookahead none).
  const MotionPrediction& prediction() const { return *prediction_; }
  const CameraProfile& profile() const { return *profile_; }
  const FrameParameters& frame() const { return frame_; }
  // The character's state at the last set_frame().
  const CharacterState& character() const { return character_; }
  const ConstraintIds& ids() const { return ids_; }
  static constexpr csp::VariableId kCamX = 0, kCamY = 1, kCamZ = 2;

  // Re-parameterises for one frame: the character's state and look-at point, last frame's
  // camera, the frame interval (seconds, > 0; std::invalid_argument otherwise), the desired
  // values adapted to the area the character is in, and the search cube centred on
  // `last_camera`. Returns which area was left / entered since the previous call (the
  // constructor makes that call for the scene's first frame, from the scene's start camera).
  AreaTransition set_frame(const CharacterState& character, const Eigen::Vector3d& last_camera,
                           double dt);
  // Moves the search cube (for example around a cut's target): each domain becomes
  // [centre_i - half_size, centre_i + half_size]. half_size > 0.
  void set_search_box(const Eigen::Vector3d& centre, double half_size);

  // Desired values in force this frame, and the area that set them.
  const EffectiveProfile& effective() const { return areas_.current(); }
  // The position that meets height, distance and orientation exactly this frame.
  Eigen::Vector3d ideal_position() const;
  // The assignment {x, y, z} of a position (a convenience for solvers' start points).
  static csp::Assignment assignment(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

 private:
  void record(std::string_view kind, csp::ConstraintId id);
  void add_extras();
  void add_camera_kind(const CameraConstraintKind& kind, const csp::Spec& entry);

  const Scene* scene_;
  const CameraProfile* profile_;
  // Owned through a pointer so the constraints' references survive a move of the problem.
  // The static boxes around the search box and the character (and its predicted look-at
  // points), shared by at_time_ and the prediction's geometries; set_search_box covers them.
  std::unique_ptr<NearbyBoxes> nearby_;
  std::unique_ptr<SceneAtTime> at_time_;
  std::unique_ptr<MotionPrediction> prediction_;
  std::unique_ptr<csp::Problem> problem_;
  FrameParameters frame_;
  ConstraintIds ids_;
  AreaProfileSwitch areas_;
  CharacterState character_;
};

}  // namespace sightline::camera
