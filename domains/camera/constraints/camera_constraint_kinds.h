// CameraConstraintKinds: the registry of camera constraints, as the csp kinds are
// registered: a new one is one file (a csp::Constraint and its make function) and one add()
// call, from anywhere (a test registers its own).
//
// Every camera constraint is a kind here, the profile's own terms too: camera.height,
// camera.distance, camera.orientation, camera.frame_coherence, camera.look_at_visible,
// camera.visible_fraction, camera.clearance and camera.future_visible have a from_profile
// function, and CameraProblem builds each frame's problem from them, in the order they were
// registered (each returns null when the profile leaves it out). Solvers never look for a
// kind by name: they ask a constraint what it costs (query_cost) and what it offers.
//
// A profile's `extras:` entry naming a registered camera kind gets the camera's context
// (the geometry at the frame's time, the frame's parameters, the motion prediction and the
// three camera variables) instead of a scope:
//
//   extras:
//     - {kind: camera.keep_point_in_view, point: [0, 1, 5], weight: 2}
//
// `weight` and `hard` mean what they mean for every constraint (csp::read_weight,
// read_hard); the kind's own fields are checked (unknown ones refused with the line).
// Entries naming a csp kind (linear, expression, ...) keep their `scope:` form.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/csp/spec.h"
#include "sightline/domains/camera/constraints/frame_parameters.h"
#include "sightline/domains/camera/motion_prediction.h"
#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::camera {

// What a camera constraint may read. References stay valid as long as the camera problem.
struct CameraConstraintContext {
  const SceneAtTime& scene;             // the geometry at the frame's time, movers placed
  const FrameParameters& frame;         // the character, desired values, last camera
  const MotionPrediction& prediction;   // the predicted look-at points (may be empty)
  csp::VariableId cam_x, cam_y, cam_z;  // the camera's position variables
};

struct CameraConstraintKind {
  std::string name;         // what `kind:` says; by convention "camera.<something>"
  std::string description;  // one line
  std::vector<std::string> fields;  // its own fields besides kind, weight and hard
  // Builds the constraint from an `extras:` entry (csp::InputError via entry.fail for bad
  // fields).
  std::function<std::unique_ptr<csp::Constraint>(const CameraConstraintContext&,
                                                 const csp::Spec& entry)>
      make;
  // For the profile's own terms: the constraint as the profile asks for it, or null when
  // the profile leaves it out (weight 0, no anticipation). Empty for kinds that come only
  // through `extras:`. A kind registered with one is in every camera problem.
  std::function<std::unique_ptr<csp::Constraint>(const CameraConstraintContext&,
                                                 const CameraProfile& profile)>
      from_profile;
  std::string label;  // the constraint's label in reports ("height"); the name when empty
};

class CameraConstraintKinds {
 public:
  // The process-wide registry, with the built-in kinds.
  static CameraConstraintKinds& global();
  // Throws std::invalid_argument for an empty or taken name.
  void add(CameraConstraintKind kind);
  const CameraConstraintKind* find(const std::string& name) const;
  std::vector<std::string> names() const;
  // The kinds with a from_profile function, in the order they were registered.
  const std::vector<const CameraConstraintKind*>& profile_terms() const { return profile_terms_; }

 private:
  std::map<std::string, CameraConstraintKind> kinds_;  // nodes: the pointers below stay valid
  std::vector<const CameraConstraintKind*> profile_terms_;
};

}  // namespace sightline::camera
