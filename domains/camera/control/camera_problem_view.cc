#include "sightline/domains/camera/control/camera_problem_view.h"

#include <stdexcept>

namespace sightline::camera {

std::optional<CameraProblemView> CameraProblemView::find(const csp::Problem& problem,
                                                         std::string* why) {
  CameraProblemView view;
  bool has_look_at = false, has_orientation = false, has_height = false;
  // By type, not by name: the pieces the octree searches steer by. Every other constraint
  // is scored as it is, the cheap ones (no queries of the world) first.
  for (csp::ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const csp::Constraint& c = problem.constraint(id);
    if (const auto* look = dynamic_cast<const LookAtVisibleConstraint*>(&c); look && !has_look_at) {
      view.scene_ = &look->scene();
      view.look_at_id_ = id;
      has_look_at = true;
      view.expensive_.insert(view.expensive_.begin(), id);  // one ray: first of the expensive
      continue;
    }
    if (c.query_cost() > 0) {
      view.expensive_.push_back(id);
      continue;
    }
    if (const auto* orientation = dynamic_cast<const OrientationConstraint*>(&c);
        orientation && !has_orientation) {
      view.orientation_ = orientation;
      view.orientation_id_ = id;
      has_orientation = true;
    } else if (const auto* height = dynamic_cast<const HeightConstraint*>(&c);
               height && !has_height) {
      view.height_ = height;
      view.height_id_ = id;
      has_height = true;
    }
    view.cheap_.push_back(id);
  }
  const csp::Parameters& p = problem.parameters();
  const auto look = p.find("look_x"), ch = p.find("char_x"), yaw = p.find("char_yaw");
  if (!has_look_at || !has_orientation || !has_height || !look || !ch || !yaw ||
      problem.num_variables() != 3) {
    if (why) *why = "needs a camera problem (cam_x, cam_y, cam_z with the camera constraints)";
    return std::nullopt;
  }
  view.look_x_ = *look;
  view.char_x_ = *ch;
  view.char_yaw_ = *yaw;
  return view;
}

Eigen::Vector3d CameraProblemView::look_at(const csp::Problem& problem) const {
  const csp::Parameters& p = problem.parameters();
  return {p.get(look_x_), p.get(look_x_ + 1), p.get(look_x_ + 2)};
}

Eigen::Vector3d CameraProblemView::character(const csp::Problem& problem) const {
  const csp::Parameters& p = problem.parameters();
  return {p.get(char_x_), p.get(char_x_ + 1), p.get(char_x_ + 2)};
}

double CameraProblemView::character_yaw(const csp::Problem& problem) const {
  return problem.parameters().get(char_yaw_);
}

const CameraProblemView& CameraProblemViewCache::get(const csp::Problem& problem,
                                                     const std::string& solver) {
  if (problem_ != &problem || !view_) {
    std::string why;
    view_ = CameraProblemView::find(problem, &why);
    if (!view_) throw std::invalid_argument(solver + ": " + why);
    problem_ = &problem;
  }
  return *view_;
}

}  // namespace sightline::camera
