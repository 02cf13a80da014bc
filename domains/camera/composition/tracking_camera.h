// TrackingCamera: films a scene's shot: block every frame (a tracking shot, FORMATS.md
// "Shots"): the camera holds the composition while the people move, moving smoothly, and
// cuts only when the shot cannot be kept.
//
// The shot it works to is the scene's, plus a `visible` property asking half the samples of
// each person the shot wants in the image and names in no visible property: a person framed
// but hidden behind someone else is not in the shot.
//
// The poses are solved for that shot asking more of it: each wanted person's soft
// `visible` range raised to `visible_aim` of the samples (all, by default), so the pose aimed
// for keeps a margin against occluders and the camera's lag; whether a pose keeps or loses
// someone (for the global solves and the cuts) is judged by the shot worked to.
//
// Each frame: the shot's problem is set to where the people will be `lead_seconds` on
// (their positions and velocities now: a forecast, as a game would make); the pose the
// camera aims for is refined from the last one (shot-search without its global phase, a
// small budget). A **background sweep** scores a few candidate poses a frame (16 with two
// people, 8 with four: `sweep_people_per_frame` over the people wanted; round the people at
// the aim's distance and 0.7 and 1.4 times it, 16 bearings, 3 elevations, then Halton
// points of the region, each looking at the people) with
// **foresight**: the shot's framed and visible properties also scored 0.5 s and 1 s on, the
// camera carried along with the people (CompositionProblem's Foresight), so a pose the
// pillar or bus about to pass spoils ranks low; a sweep of 192 takes 12-24 frames, and a
// candidate asks its sight lines only when it can still beat the sweep's best so far. When the
// aimed-for pose breaks a rule, a global solve (the configured solver, with foresight)
// replaces it. When it loses someone (a framed or visible property below its range) or its
// satisfaction falls `resolve_drop` below the last global or sweep pose's, the last sweep's
// best replaces it if it does better with foresight; else a global solve does, when that
// global pose kept everyone (or on the fall), at most one at hand at the start and then
// `resolves_per_second`. So the global search costs the same every frame, and few frames
// pay for a whole global solve. The camera follows the aimed-for pose through two
// first-order stages (the aimed-for pose low-passed, then a spring toward that; time
// constant `smoothing` each), bounded by max_speed; the look direction, fov and roll alike
// (on a long move, more than kNearAim behind the aim, the look turned toward the point the
// aimed-for view centres at the people's depth, then the aim, fov and roll refined from
// where the camera is, framing everyone wanted first); a step that would end inside the
// shot's clearance is halved, else not taken. When the camera's own pose breaks the shot
// while the aimed-for pose keeps it and is out of one frame's smooth reach, it cuts there
// (or to the last sweep's best, when that does better with foresight and keeps everyone
// now), never twice within `min_shot_seconds`. Once warm, a frame allocates nothing.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/solvers/solver.h"

namespace sightline::camera {

struct TrackingOptions {
  std::string solver = "shot-search";   // the global solve (any composition solver)
  // Budgets in evaluations of the shot, not seconds, so a run is the same on any machine
  // under any load (about 2 us each with four people among boxes).
  // The per-frame local refinement's evaluations: this over the number of people the shot
  // wants (60 with two, 30 with four), at least 30.
  std::int64_t frame_people_evaluations = 120;
  std::uint64_t resolve_evaluations = 250;  // a global solve (a broken rule)
  // On a long move, the camera's view refined from where it is (its aim, fov and roll;
  // these evaluations a frame; 0: the low-passed aimed-for pose's view turned toward the
  // people only). See move_toward in the .cc.
  std::int64_t turn_evaluations = 40;
  // Sweep candidates scored each frame: this over the number of people the shot wants (32:
  // 16 candidates with two people, 8 with four), at least 4.
  std::int64_t sweep_people_per_frame = 32;
  double resolves_per_second = 0.1;         // global solves for a lost person, at most
  double resolve_drop = 0.1;             // satisfaction lost before a global solve
  double max_speed = 8.0;                // m/s: longer moves are cuts
  double smoothing = 0.15;               // s: each of the two stages' time constant
  double min_shot_seconds = 1.0;         // never two cuts closer than this
  double lead_seconds = 0.3;             // the aimed-for pose is solved this far ahead
  // The poses are solved asking at least this share of each wanted person's samples
  // visible (each soft `visible` range's low end raised to it, within the range; see
  // asking_more_visible in the .cc); what a pose keeps or loses is judged by the shot.
  double visible_aim = 1.0;
  // A global solve also keeps the shot's people framed and visible this far beyond the
  // lead, the camera carried along with them (CompositionProblem's foresight).
  Foresight foresight{{0.5, 1.0}, 1.0};
  std::uint64_t seed = 1;
};

class TrackingCamera : public CameraController {
 public:
  // `scene` (with its shot) must outlive the camera. Throws std::invalid_argument for a
  // scene without a shot or a solver that cannot compose it.
  TrackingCamera(const Scene& scene, TrackingOptions options);
  std::string name() const override { return "tracking " + options_.solver; }
  const CameraFrame& update(const CharacterState& character, double dt) override;
  void reset(const Eigen::Vector3d& position) override;
  double max_step(double dt) const override { return options_.max_speed * dt; }

  const CameraPose& pose() const { return pose_; }
  // How the camera's pose does on the shot this frame (FORMATS.md's definitions).
  const ShotEvaluation& evaluation() const { return evaluation_; }

 private:
  // Metres between the camera and the low-passed aimed-for pose beyond which the camera's
  // look turns toward what that pose centres on, fully kTurnAcross metres farther (see
  // move_toward). Within it (the camera's usual lag), the aim's own direction.
  static constexpr double kNearAim = 2.0;
  static constexpr double kTurnAcross = 4.0;
  void solve_globally(std::uint64_t evaluations);
  void move_toward(double dt);
  void jump_to_aim();
  // Someone the shot wants framed and visible is not (a framed or visible property below 1).
  bool loses_someone(const ShotEvaluation& e) const;
  Eigen::Vector3d wanted_centre() const;
  // The background sweep: candidate i round the people's centre; score the next `count`;
  // adopt the last full sweep's best when it beats the aim with foresight.
  void sweep_pose(std::size_t i, const Eigen::Vector3d& centre, CameraPose& out) const;
  void sweep_slice(std::size_t count);
  bool take_sweep_best();

  const Scene* scene_;
  TrackingOptions options_;
  CompositionProblem verdict_;   // the scene's own shot: FORMATS.md's verdict
  Shot shot_;                    // the shot worked to (see working_shot in the .cc)
  Shot aimed_shot_;              // shot_ with margins: the shot the poses are solved for
  Shot turn_shot_;               // aimed_shot_ framing first: the view turned where the camera is
  CompositionProblem problem_;   // shot_ now: what a pose keeps or loses
  CompositionProblem refine_;    // aimed_shot_ now: the per-frame refinement
  CompositionProblem ahead_;     // aimed_shot_ with foresight: the sweep and the global solves
  CompositionProblem turn_;      // turn_shot_ now
  std::unique_ptr<solvers::Solver> local_, global_, turner_;
  solvers::SolveContext local_context_, global_context_, turn_context_;
  solvers::SolverResult result_, turned_;
  csp::Assignment aim_;          // the pose aimed for, as the problem's assignment
  double aim_satisfaction_ = 0;  // of the last global solve
  CameraPose pose_;              // where the camera is
  CameraPose filtered_;          // the aimed-for pose low-passed (look_at: a unit direction)
  ShotEvaluation evaluation_;        // verdict_'s, of pose_
  ShotEvaluation aimed_, here_;      // problem_'s, of the aimed-for pose and of pose_
  CameraFrame frame_;
  double t_ = 0, last_cut_t_ = -1e9;
  double resolves_ = 1;          // global solves due for a lost person (rationed)
  bool global_loses_ = false;    // the last global solve's pose loses someone too
  std::size_t sweep_cursor_ = 0, sweep_count_ = 16;
  bool has_best_ = false, ready_ = false;  // this sweep has a best; the last one's is ready
  csp::Score best_score_;
  std::vector<csp::Score> sweep_terms_;  // ahead_'s terms of a candidate (Problem::score_below)
  // Bests as offsets from the people's centre, so they move along with the people.
  Eigen::Vector3d best_offset_ = Eigen::Vector3d::Zero(), ready_offset_ = Eigen::Vector3d::Zero();
  bool started_ = false;
};

}  // namespace sightline::camera
