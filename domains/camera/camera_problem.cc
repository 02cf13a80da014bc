#include "sightline/domains/camera/camera_problem.h"

#include <cmath>
#include <stdexcept>

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/constraint_entry.h"
#include "sightline/domains/camera/constraints/camera_constraint_kinds.h"

namespace sightline::camera {

CameraProblem::CameraProblem(const Scene& scene, const CameraProfile& profile)
    : scene_(&scene),
      profile_(&profile),
      nearby_(std::make_unique<NearbyBoxes>(scene)),
      at_time_(std::make_unique<SceneAtTime>(scene)),
      prediction_(std::make_unique<MotionPrediction>(scene, profile.anticipation)),
      problem_(std::make_unique<csp::Problem>("camera: " + scene.name())),
      areas_(*at_time_, profile) {
  if (const std::string error = profile.validate(); !error.empty()) {
    throw std::invalid_argument("camera profile '" + profile.name + "': " + error);
  }
  at_time_->set_nearby(nearby_.get());
  prediction_->set_nearby(nearby_.get());
  csp::Problem& p = *problem_;
  // The scene's camera start, or this profile's ideal spot at the first keyframe.
  const CharacterState first = scene.character_at(scene.trajectory().start_time());
  const Eigen::Vector3d start =
      scene.camera_start() ? *scene.camera_start()
                           : ideal_camera_position(first, profile.height.desired,
                                                   profile.distance.desired,
                                                   profile.orientation.desired);
  const double h = profile.search_half_size;
  p.add_variable("cam_x", csp::Domain::real_interval(start.x() - h, start.x() + h));
  p.add_variable("cam_y", csp::Domain::real_interval(start.y() - h, start.y() + h));
  p.add_variable("cam_z", csp::Domain::real_interval(start.z() - h, start.z() + h));
  frame_ = FrameParameters::add_to(p.parameters());

  // The profile's terms, each a registered camera kind (camera_constraint_kinds.h).
  const CameraConstraintContext context{*at_time_, frame_, *prediction_, kCamX, kCamY, kCamZ};
  for (const CameraConstraintKind* kind : CameraConstraintKinds::global().profile_terms()) {
    std::unique_ptr<csp::Constraint> c = kind->from_profile(context, profile);
    if (!c) continue;
    c->set_label(kind->label.empty() ? kind->name : kind->label);
    record(kind->name, p.add_constraint(std::move(c)));
  }
  add_extras();
  // A meaningful first frame: the scene's start, one frame interval.
  set_frame(first, start, 1.0 / scene.frame_rate());
}

// Where the problem keeps the id of one of the profile's terms (ids()); others are extras.
void CameraProblem::record(std::string_view kind, csp::ConstraintId id) {
  if (kind == "camera.height") ids_.height = id;
  else if (kind == "camera.distance") ids_.distance = id;
  else if (kind == "camera.orientation") ids_.orientation = id;
  else if (kind == "camera.frame_coherence") ids_.frame_coherence = id;
  else if (kind == "camera.look_at_visible") ids_.look_at = id;
  else if (kind == "camera.clearance") ids_.clearance = id;
  else if (kind == "camera.visible_fraction") ids_.visible_fraction = id;
  else if (kind == "camera.future_visible") ids_.future_visible = id;
  else ids_.extras.push_back(id);
}

// A registered camera constraint kind (constraints/camera_constraint_kinds.h): it gets the
// camera's context, not a scope.
void CameraProblem::add_camera_kind(const CameraConstraintKind& kind, const csp::Spec& entry) {
  std::vector<std::string> keys = kind.fields;
  keys.insert(keys.end(), {"kind", "weight", "hard"});
  entry.check_keys(keys);
  const CameraConstraintContext context{*at_time_, frame_, *prediction_, kCamX, kCamY, kCamZ};
  std::unique_ptr<csp::Constraint> constraint = kind.make(context, entry);
  constraint->set_label(kind.label.empty() ? kind.name : kind.label);
  try {
    ids_.extras.push_back(problem_->add_constraint(std::move(constraint)));
  } catch (const std::invalid_argument& e) {
    entry.fail(e.what());
  }
}

void CameraProblem::add_extras() {
  const csp::ConstraintKinds& kinds = csp::ConstraintKinds::global();
  for (const csp::Spec& entry : profile_->extras) {
    if (!entry.is_map()) entry.fail("expected a constraint: {kind: ..., scope: [cam_y], ...}");
    const std::string& kind = entry.at("kind").as_string("a constraint kind name");
    if (const CameraConstraintKind* camera_kind = CameraConstraintKinds::global().find(kind)) {
      add_camera_kind(*camera_kind, entry);
      continue;
    }
    const csp::Spec* scope = entry.find("scope");
    const csp::Spec* vars = entry.find("vars");
    if ((scope != nullptr) == (vars != nullptr)) {
      entry.fail("expected exactly one of 'scope' and its synonym 'vars' (a list of camera "
                 "variables: cam_x, cam_y, cam_z)");
    }
    std::vector<csp::VariableId> ids;
    for (const csp::Spec& item : (scope ? scope : vars)->items("a list of camera variables")) {
      const std::string& name = item.as_string("a camera variable name");
      const auto id = problem_->find_variable(name);
      if (!id) item.fail("unknown variable '" + name + "' (known: cam_x, cam_y, cam_z)");
      ids.push_back(*id);
    }
    if (ids.empty()) entry.fail("expected at least one variable in the scope");
    auto constraint = csp::create_constraint(kinds, *problem_, kind, ids, csp::read_weight(entry),
                                             csp::read_hard(entry), entry, entry.where());
    try {
      ids_.extras.push_back(problem_->add_constraint(std::move(constraint)));
    } catch (const std::invalid_argument& e) {
      entry.fail(e.what());
    }
  }
}

AreaTransition CameraProblem::set_frame(const CharacterState& character,
                                        const Eigen::Vector3d& last_camera, double dt) {
  if (!(dt > 0) || !std::isfinite(dt)) {
    throw std::invalid_argument("camera frame interval dt must be > 0");
  }
  character_ = character;
  at_time_->set_time(character.t);
  prediction_->update(character);
  const AreaTransition transition = areas_.update(character);
  const EffectiveProfile& e = areas_.current();
  FrameValues values;
  values.feet = character.position;
  values.yaw = character.yaw;
  values.velocity = character.velocity;
  values.look_at = scene_->character().look_at(character.position);
  values.last_camera = last_camera;
  values.dt = dt;
  values.t = character.t;
  values.desired_height = e.desired_height;
  values.desired_distance = e.desired_distance;
  values.desired_orientation = e.desired_orientation;
  values.clearance_radius = profile_->clearance_radius;
  frame_.write(problem_->parameters(), values);
  set_search_box(last_camera, profile_->search_half_size);
  return transition;
}

void CameraProblem::set_search_box(const Eigen::Vector3d& centre, double half_size) {
  if (!(half_size > 0) || !std::isfinite(half_size) || !centre.allFinite()) {
    throw std::invalid_argument("camera search box needs a finite centre and half size > 0");
  }
  for (csp::VariableId v = 0; v < 3; ++v) {
    problem_->set_domain(v, csp::Domain::real_interval(centre[v] - half_size,
                                                       centre[v] + half_size));
  }
  // Every sight line of the frame runs from the search box to the body, the look-at point
  // or a predicted look-at point: the boxes near all of them answer it (nearby_boxes.h).
  const Eigen::Vector3d half(half_size, half_size, half_size);
  Aabb needed{centre - half, centre + half};
  needed.merge(scene_->character().body_at(character_.position));
  needed.merge(scene_->character().look_at(character_.position));
  for (int k = 0; k < prediction_->size(); ++k) needed.merge(prediction_->sample(k).look_at);
  nearby_->cover(needed);
}

Eigen::Vector3d CameraProblem::ideal_position() const {
  const EffectiveProfile& e = areas_.current();
  return ideal_camera_position(character_, e.desired_height, e.desired_distance,
                               e.desired_orientation);
}

}  // namespace sightline::camera
