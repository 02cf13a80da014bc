// ChaseCamera: the per-frame controller of the chase camera (thesis table 9, section 3.2).
//
// Once per frame, update(character, dt):
//   1. re-parameterises the camera problem (character state, last camera position, the
//      desired values adapted to the area the character is in) without rebuilding it;
//   2. runs the configured solver (any registered solver or pipeline) from the current
//      camera position over a search cube around it;
//   3. moves the camera:
//      - smoothly toward the solver's target, with bounded speed and acceleration, never
//        through geometry and never to a position from which the look-at point is hidden;
//      - or by a cut (a flagged jump) when the character leaves an enclosed area, when it
//        backs up to a wall or other obstruction, when the camera has been stuck behind an
//        obstacle for a while (each of these three is a profile option, CutPolicy: on in
//        the thesis profiles, off in the anticipating one), and whenever no smooth move
//        keeps the character visible (always: the last resort).
//   With cuts.smooth_escape, when the spring's step toward the target is blocked the camera
//   tries moves around that step and around where it is (1/8 to all of max_speed x dt: up,
//   down, toward and away from the look-at point, to either side and their mixes, never
//   longer than max_speed x dt in all), and takes the cheapest under this frame's problem
//   (so future visibility chooses among them) plus a price on the change of velocity, that
//   keeps the look-at point visible and crosses nothing, if it is cheaper than staying (or
//   staying loses sight). Only then does it stay, and after
//   stuck_seconds cut (if cuts.stuck), or cut because the look-at point is lost. A game
//   camera slides along the wall, rises or pulls in before it pops. A forced cut of these
//   profiles goes to the better framed (shot_cost) of the solver's target near the camera
//   and a new shot searched around the ideal position, so that a camera left behind does
//   not cut a metre or two and lose sight again next frame; if neither is usable, to the
//   first usable spot on rings 1-3 m around the look-at point (close_in) rather than stay
//   hidden.
//   With anticipation.plan_seconds > 0 the spring and the one-frame escape give way to a
//   motion planned over the prediction horizon (horizon_planner.h): each frame the camera
//   follows the first frame of the cheapest smooth trajectory toward the low-passed target
//   or an offset around it; the escape, staying and the cuts above are used only when no
//   planned trajectory's first frame is usable. Its stuck cut (cuts.stuck) comes when the
//   camera has been left behind: farther from the ideal position than the search cube's
//   half-size and getting no nearer for stuck_seconds or the horizon, whichever is
//   longer (a wall between it and the shot, that no plan over the horizon gets round).
//   With cuts.cut_ahead (on in the anticipating presets), a frame where the planner has no
//   usable first frame and none of its trajectories sees the first predicted look-at point
//   either, while a mover will hide the look-at point from where the camera is at more
//   than half the predicted samples (a door shutting, a bus; not a passer-by, gone within
//   the horizon), cuts at once (forced: no smooth move keeps the character visible) to a
//   shot that sees most predicted points, rather than escaping frame by frame (each escape
//   a velocity jump) into the same forced cut a few frames later.
//   After a cut the new shot lasts at least `min_shot_seconds` unless visibility forces
//   another cut. Every move longer than max_speed x dt is a cut, and flagged.
// The same smoothing and cut logic applies whatever solver runs, so solvers are compared on
// their targets alone. When the solver's target is unusable (hidden or inside clearance) the
// controller asks the same solver once more, from the ideal position, before moving.
#pragma once

#include <Eigen/Core>
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/control/horizon_planner.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/solvers/registry.h"

namespace sightline::camera {

struct ChaseCameraOptions {
  std::string solver = "occlusion-octree";  // any registered solver or pipeline
  solvers::OptionValues solver_options;
  std::uint64_t seed = 1;
  // m/s: the smooth-motion bound; longer moves are cuts. Above what characters run at
  // (6-8 m/s), so a camera left behind a runner at a corner can catch up (at 8 m/s the
  // anticipating camera cut 3-10 times on each of three 12-18 s runs).
  double max_speed = 12.0;
  double max_acceleration = 15.0;  // m/s^2
  // m/s: the longest one-frame escape move tried first (see smooth_escape); escapes are
  // velocity jumps, and at max_speed they were the top of the jerk.
  double escape_speed = 8.0;
  double response_time = 0.3;      // s: the spring toward the target settles in ~2x this
  double target_smoothing = 0.15;  // s: time constant of the low-pass on the solver's target
  // First-order low-pass stages in cascade, each of time constant target_smoothing (1 to
  // kMaxSmoothingStages). 2 cuts the camera's jerk to about a third on the thesis scenes, at
  // the cost of more lag behind the solver's target
  // (docs/studies/2026-11-22-target-smoothing-stages.md).
  static constexpr int kMaxSmoothingStages = 4;
  int target_smoothing_stages = 1;
  double min_shot_seconds = 1.0;  // s: no discretionary cut sooner after a cut
  double stuck_seconds = 0.5;     // s: blocked from its target this long -> cut
  double backing_speed = 0.2;     // m/s moving against the facing counts as backing up
  // Ali's last step (table 9): move only to positions that keep the look-at point visible
  // and the camera clear of geometry, along unobstructed steps. Off reproduces Bourne &
  // Sattar's published controller, which goes wherever its solver says.
  bool visibility_guard = true;
  // Empty when usable, else which field is wrong and why.
  std::string validate() const;
};

class ChaseCamera : public CameraController {
 public:
  // `scene` and `profile` must outlive the camera. Throws solvers::OptionError for an
  // unknown solver or bad options, std::invalid_argument for bad controller options or a
  // solver that cannot work on camera problems.
  ChaseCamera(const Scene& scene, const CameraProfile& profile, ChaseCameraOptions options);
  // A temporary would dangle: refused at compile time.
  ChaseCamera(const Scene&&, const CameraProfile&, ChaseCameraOptions) = delete;
  ChaseCamera(const Scene&, const CameraProfile&&, ChaseCameraOptions) = delete;
  ~ChaseCamera() override;
  std::string name() const override { return options_.solver; }

  // One frame; dt > 0 seconds since the previous one.
  const CameraFrame& update(const CharacterState& character, double dt) override;
  // Puts the camera at `position` (at rest) for the next update.
  void reset(const Eigen::Vector3d& position) override;

  const CameraFrame& frame() const { return frame_; }
  const CameraProblem& camera_problem() const { return problem_; }
  const ChaseCameraOptions& options() const { return options_; }
  // The largest move a smooth frame of length dt may make.
  double max_step(double dt) const override { return options_.max_speed * dt; }

 private:
  // What every step of a frame reads: the character, the time step, the look-at point, and
  // whether the shot is old enough for a discretionary cut.
  struct FrameContext {
    const CharacterState& character;
    double dt;
    Eigen::Vector3d look;
    bool may_cut;
  };
  // The steps of update(), in order (see chase_camera.cc).
  std::optional<CutReason> discretionary_cut(const FrameContext& frame,
                                             const AreaTransition& transition);
  Eigen::Vector3d solve_target(const FrameContext& frame);
  void move_or_cut(const FrameContext& frame, Eigen::Vector3d& target);
  const Eigen::Vector3d& low_pass(const Eigen::Vector3d& target, double dt);
  bool follow_plan(const Eigen::Vector3d& followed, const Eigen::Vector3d& look, double dt);
  bool cut_ahead_shot(const FrameContext& frame, Eigen::Vector3d& target);
  bool take_step(const Eigen::Vector3d& step, const Eigen::Vector3d& velocity,
                 const Eigen::Vector3d& look, bool escapes);
  void check_left_behind(const FrameContext& frame, Eigen::Vector3d& target);
  void stay(const FrameContext& frame, const Eigen::Vector3d& target);
  void forced_cut(const FrameContext& frame, bool escapes, Eigen::Vector3d& target);
  void record_frame(const Eigen::Vector3d& look, const Eigen::Vector3d& target,
                    std::chrono::steady_clock::time_point started);

  // Geometry tests at the frame's time (movers included), through the problem's SceneAtTime.
  bool clear(const Eigen::Vector3d& p) const;
  bool sees(const Eigen::Vector3d& p, const Eigen::Vector3d& look) const;
  bool usable(const Eigen::Vector3d& p, const Eigen::Vector3d& look) const {
    return clear(p) && sees(p, look);
  }
  Eigen::Vector3d solve_from_here();
  Eigen::Vector3d solve_for_new_shot(const CharacterState& character, double dt,
                                     const Eigen::Vector3d& look);
  // The next position and velocity of a critically damped spring pulled toward `target`.
  Eigen::Vector3d smooth_step(const Eigen::Vector3d& target, double dt,
                              Eigen::Vector3d* velocity) const;
  void cut_to(const Eigen::Vector3d& p, CutReason reason);
  bool backed_up(const CharacterState& character, const Eigen::Vector3d& look) const;
  // For a forced cut the solver could not place: the first usable spot on rings 1-3 m
  // around the look-at point (escape profiles only), if any.
  // With `ahead`, the spot must not be shut out itself (shut_out(p, false)).
  std::optional<Eigen::Vector3d> close_in(const Eigen::Vector3d& look, bool ahead = false) const;
  // This frame's soft cost of a shot to cut to: framing and sight, without frame coherence.
  double shot_cost(const Eigen::Vector3d& p) const;
  // The cheapest usable short move (see the header comment), if any. `step` is where the
  // spring would have gone.
  std::optional<Eigen::Vector3d> smooth_escape(const Eigen::Vector3d& look,
                                               const Eigen::Vector3d& step, double dt) const;
  // How many of the predicted look-at points are hidden from `p`, each in the geometry
  // forecast for its time; *by_mover set when a mover's box is among what hides one.
  int hidden_ahead(const Eigen::Vector3d& p, bool* by_mover) const;
  // More than half of the predicted points hidden from `p` (and, with `by_mover_only`, a
  // mover among what hides them): for most of the horizon, whatever happens, no sight.
  bool shut_out(const Eigen::Vector3d& p, bool by_mover_only) const;

  const Scene* scene_;
  ChaseCameraOptions options_;
  CameraProblem problem_;
  std::unique_ptr<solvers::Solver> solver_;
  solvers::SolverResult result_;
  solvers::SolveContext context_;
  Eigen::Vector3d position_;
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
  // With anticipation.plan_seconds > 0: the camera's acceleration (the planner keeps it
  // continuous), the planner, and the followed target's velocity (low-passed).
  Eigen::Vector3d acceleration_ = Eigen::Vector3d::Zero();
  std::optional<HorizonPlanner> planner_;
  Eigen::Vector3d followed_velocity_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_followed_ = Eigen::Vector3d::Zero();
  // The low-pass stages' outputs; the last one in use is what the spring follows.
  std::array<Eigen::Vector3d, ChaseCameraOptions::kMaxSmoothingStages> filtered_target_{};
  void set_filtered_target(const Eigen::Vector3d& p) { filtered_target_.fill(p); }
  double since_cut_ = 1e9;  // seconds since the last cut
  // The times of the last cuts, of any reason (a ring), for the profile's
  // cuts.stuck_per_minute.
  std::array<double, 16> cut_times_{};
  std::size_t cuts_made_ = 0;  // how many were made (the ring holds the last 16)
  double now_ = 0;             // the frame's time (the character's t)
  bool stuck_cut_allowed(double t) const;
  void note_cut(double t);
  double stuck_for_ = 0;    // seconds the smooth move has been blocked
  // With the planner: the camera's distance from the ideal position last frame.
  double last_off_ideal_ = 1e9;
  bool was_backed_up_ = false;
  std::uint64_t frames_ = 0;
  CameraFrame frame_;
  // Constraint ids for pricing escape moves: without sight lines, and with them.
  std::vector<csp::ConstraintId> cheap_ids_, sighted_ids_;
};

}  // namespace sightline::camera
