// CameraProblemView: what a camera-aware solver needs to find inside a csp::Problem.
//
// Solvers are created by name and see only a csp::Problem. The camera's octree solvers
// (Bourne's and Ali's) need more than a cost: the character's look-at point, the
// orientation term (to sweep its desired value), the sight-line test and the scene. This
// view finds those pieces by the constraints' types, the rest by what each says it costs
// (csp::Constraint::query_cost), and the frame's parameters by name, so the solvers work on any problem built by CameraProblem (with or without extras)
// and politely refuse any other.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/constraints/occlusion.h"
#include "sightline/domains/camera/constraints/smooth_constraints.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

class CameraProblemView {
 public:
  // Empty optional (with `why` set) when `problem` is not a camera problem.
  static std::optional<CameraProblemView> find(const csp::Problem& problem, std::string* why);

  // The geometry at the frame's time (movers included): what the look-at constraint reads.
  const SceneAtTime& scene() const { return *scene_; }
  const OrientationConstraint& orientation() const { return *orientation_; }
  csp::ConstraintId orientation_id() const { return orientation_id_; }
  const HeightConstraint& height() const { return *height_; }
  csp::ConstraintId height_id() const { return height_id_; }
  csp::ConstraintId look_at_id() const { return look_at_id_; }
  // Constraints a candidate is scored with: cheap() ask nothing of the world
  // (query_cost() 0); expensive() do (sight lines, clearance), the look-at test first, then
  // in the problem's order, so a search can stop early.
  const std::vector<csp::ConstraintId>& cheap() const { return cheap_; }
  const std::vector<csp::ConstraintId>& expensive() const { return expensive_; }

  // Frame parameters, read live.
  Eigen::Vector3d look_at(const csp::Problem& problem) const;
  Eigen::Vector3d character(const csp::Problem& problem) const;
  double character_yaw(const csp::Problem& problem) const;

 private:
  const SceneAtTime* scene_ = nullptr;
  const OrientationConstraint* orientation_ = nullptr;
  const HeightConstraint* height_ = nullptr;
  csp::ConstraintId orientation_id_ = 0, height_id_ = 0, look_at_id_ = 0;
  std::vector<csp::ConstraintId> cheap_, expensive_;
  std::size_t look_x_ = 0, char_x_ = 0, char_yaw_ = 0;
};

// Finds the view once per problem (a camera problem is re-parameterised every frame, never
// rebuilt), so a solver called every frame scans the constraints only on its first call.
class CameraProblemViewCache {
 public:
  // Throws std::invalid_argument ("<solver>: needs a camera problem ...") for other problems.
  const CameraProblemView& get(const csp::Problem& problem, const std::string& solver);

 private:
  const csp::Problem* problem_ = nullptr;
  std::optional<CameraProblemView> view_;
};

}  // namespace sightline::camera
