// CompositionProblem: a shot at one instant as a weighted CSP over the camera's pose.
//
// Variables (real intervals): cam_x, cam_y, cam_z (the shot's region), yaw and pitch of the
// view direction in degrees (yaw 0 along +z, 90 along +x; pitch in [-89, 89], > 0 up), fov
// and roll in degrees (the shot's value, or its range when the camera may zoom or roll).
// The look-at point is position + direction.
// Constraints:
//   one per property (ShotPropertyConstraint): violation 1 - satisfaction, soft with the
//   property's weight, or hard (the pose must score 1);
//   clearance (hard): how far the camera is inside `clearance` of solid geometry or a
//   person's box.
// So a pose's cost is the sum of weight x (1 - satisfaction), FORMATS.md's cost, and every
// solver of the registry composes shots. set_time() moves the people and movers.
//
// Foresight (a tracking camera's, off by default): each `framed` and `visible` property that
// wants its people in the image is also scored at forecast times t + h (the people and
// movers carried on at their velocities), the camera carried along with the wanted people's
// mean displacement (ShotForesightConstraint, soft, weight x `weight` per horizon). A pose
// whose sight lines a pillar or a bus is about to cross costs more than one that keeps its
// people in view as they move on. evaluate() never counts these terms: it is FORMATS.md's
// verdict on the shot at the current time.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/camera_controller.h"
#include "sightline/domains/camera/composition/camera_pose.h"
#include "sightline/domains/camera/composition/property_kinds.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/composition/shot_world.h"

namespace sightline::camera {

// How a pose does on a shot, by FORMATS.md's definitions.
struct ShotEvaluation {
  bool valid_pose = false;   // a view exists (not vertical, fov in (0, 180), ...)
  bool feasible = false;     // inside the region, clear, lens in range, every hard property 1
  double satisfaction = 0;   // weighted mean of the soft properties' scores (1 with none)
  double cost = 0;           // sum of weight x (1 - score) over the soft properties
  double clearance = 0;      // distance to the nearest solid or person (capped at 10 m)
  std::vector<double> measures;  // per property, as measured (inf / NaN as FORMATS.md says)
  std::vector<double> scores;    // per property, in [0, 1]
  std::string why_infeasible;    // empty when feasible: the first rule broken
};

struct Foresight {
  std::vector<double> horizons;  // seconds ahead; empty: none
  double weight = 0.5;           // of each forecast term, relative to its property's weight
};

class CompositionProblem {
 public:
  static constexpr csp::VariableId kX = 0, kY = 1, kZ = 2, kYaw = 3, kPitch = 4, kFov = 5,
                                   kRoll = 6;

  // `scene` and `shot` must outlive the problem. Throws csp::InputError (at the property)
  // when a property names someone the scene does not have.
  CompositionProblem(const Scene& scene, const Shot& shot, double t, Foresight foresight = {});
  CompositionProblem(const Scene&&, const Shot&, double, Foresight = {}) = delete;

  csp::Problem& problem() { return *problem_; }
  const csp::Problem& problem() const { return *problem_; }
  const Shot& shot() const { return *shot_; }
  const ShotWorld& world() const { return *world_; }
  // The people and movers at time t, or forecast `lead` seconds on at their velocity
  // (ShotWorld::set_time); the foresight's worlds `lead` + h on. No allocation.
  void set_time(double t, double lead = 0);
  // The foresight's horizons, their worlds and the camera's shift to each (the wanted
  // people's mean displacement from world()).
  const Foresight& foresight() const { return foresight_; }
  const ShotWorld& future(std::size_t horizon) const { return *futures_[horizon]; }
  const Eigen::Vector3d& future_shift(std::size_t horizon) const { return shifts_[horizon]; }
  // Each property's targets, as indices into world().people().
  const std::vector<std::vector<int>>& targets() const { return targets_; }
  // The people the shot wants in the image, in first-mention order: every target but those
  // it only keeps out (a framed or visible property with range [0, 0], an exclusion); the
  // first target when that leaves nobody.
  const std::vector<int>& wanted() const { return wanted_; }

  CameraPose pose(std::span<const double> values) const;
  // The assignment of a pose (yaw and pitch of its view direction; clamped to the domains).
  csp::Assignment assignment(const CameraPose& pose) const;
  // The same values without allocating.
  std::array<double, 7> pose_values(const CameraPose& pose) const;
  // FORMATS.md's verdict on a pose, computed from the definitions (not from the CSP).
  ShotEvaluation evaluate(const CameraPose& pose) const;
  // The same into `e`, reusing its storage (no allocation once it has held this shot's
  // evaluation, unless the pose is infeasible and the message is written).
  void evaluate_into(const CameraPose& pose, ShotEvaluation& e) const;

 private:
  const Shot* shot_;
  std::unique_ptr<ShotWorld> world_;
  Foresight foresight_;
  std::vector<std::unique_ptr<ShotWorld>> futures_;
  std::vector<Eigen::Vector3d> shifts_;
  std::unique_ptr<csp::Problem> problem_;
  std::vector<std::vector<int>> targets_;
  std::vector<int> wanted_;
};

// The composition problem a csp::Problem was built by (found through its property
// constraints), or null: how the composition solvers recognise a shot.
const CompositionProblem* composition_of(const csp::Problem& problem);

// A composing camera's frame (camera_controller.h) at `pose`: position, look-at point, lens,
// the problem's score of the pose, and `feasible` as the controller's own visibility flag.
void fill_frame(const CompositionProblem& problem, const CameraPose& pose, bool feasible,
                const Eigen::Vector3d& aimed_for, CameraFrame& frame);

// The middle of a wanted range of angles, as angle_horizontal reads it (hi < lo: the arc
// from lo up through 180 to hi + 360).
double arc_middle(const ValueRange& range);

// Degrees into [-180, 180).
double signed_degrees(double degrees);

// One property as a constraint over the seven pose variables. Camera-aware solvers find the
// shot through it (dynamic_cast): its property, kind, targets and world.
class ShotPropertyConstraint : public csp::Constraint {
 public:
  ShotPropertyConstraint(const CompositionProblem& owner, std::size_t index,
                         const ShotPropertyKind& kind);
  std::string_view kind() const override { return kind_name_; }
  double query_cost() const override { return kind_->name == "visible" ? 27 : 0; }
  double violation(std::span<const double> values) const override;
  // The property's score at a pose (0 for an invalid one).
  double score(const View& view) const;
  // Whether score() reads the view's position only (ShotPropertyKind::position_only).
  bool position_only() const { return kind_->position_only; }
  const ShotProperty& property() const { return *property_; }
  const CompositionProblem& owner() const { return *owner_; }

 private:
  const CompositionProblem* owner_;
  const ShotProperty* property_;
  const ShotPropertyKind* kind_;
  const int* targets_;
  std::string kind_name_;
  int visible_at_once_ = 0;  // a `visible` property's samples seen that make it score 1 (0: not one)
};

// A framed or visible property scored at a foresight horizon (see above): 1 - satisfaction
// at the pose shifted by the horizon's shift, in the horizon's world.
class ShotForesightConstraint : public csp::Constraint {
 public:
  ShotForesightConstraint(const CompositionProblem& owner, std::size_t index,
                          const ShotPropertyKind& kind, std::size_t horizon);
  std::string_view kind() const override { return "shot.foresight"; }
  double query_cost() const override { return kind_->name == "visible" ? 27 : 0; }
  double violation(std::span<const double> values) const override;

 private:
  const CompositionProblem* owner_;
  const ShotProperty* property_;
  const ShotPropertyKind* kind_;
  const int* targets_;
  std::size_t horizon_;
  int visible_at_once_;  // as ShotPropertyConstraint's
};

// Hard: max(0, clearance - distance to the nearest solid or person's box).
class ShotClearanceConstraint : public csp::Constraint {
 public:
  explicit ShotClearanceConstraint(const CompositionProblem& owner);
  std::string_view kind() const override { return "shot.clearance"; }
  double query_cost() const override { return 1; }
  double violation(std::span<const double> values) const override;

 private:
  const CompositionProblem* owner_;
};

}  // namespace sightline::camera
