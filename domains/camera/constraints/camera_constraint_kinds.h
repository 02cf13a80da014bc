// CameraConstraintKinds: the registry of camera constraints a profile may add by name, as
// the csp kinds are registered: a new one is one file (a csp::Constraint and its make
// function) and one add() call, from anywhere (a test registers its own).
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
  // Builds the constraint from the entry (csp::InputError via entry.fail for bad fields).
  std::function<std::unique_ptr<csp::Constraint>(const CameraConstraintContext&,
                                                 const csp::Spec& entry)>
      make;
};

class CameraConstraintKinds {
 public:
  // The process-wide registry, with the built-in kinds.
  static CameraConstraintKinds& global();
  // Throws std::invalid_argument for an empty or taken name.
  void add(CameraConstraintKind kind);
  const CameraConstraintKind* find(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, CameraConstraintKind> kinds_;
};

}  // namespace sightline::camera
