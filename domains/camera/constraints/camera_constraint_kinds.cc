#include "sightline/domains/camera/constraints/camera_constraint_kinds.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

#include "sightline/csp/kinds/constraint_entry.h"
#include "sightline/domains/camera/constraints/clearance.h"
#include "sightline/domains/camera/constraints/future_visibility.h"
#include "sightline/domains/camera/constraints/occlusion.h"
#include "sightline/domains/camera/constraints/smooth_constraints.h"
#include "sightline/domains/camera/spec_reading.h"

namespace sightline::camera {
namespace {

// violation = 1 when the segment from the camera to a fixed point of the world is blocked
// (at the frame's time, movers included), else 0: a goal, a door, a second subject to keep
// in view. A step function, like the look-at point's visibility: its gradient is 0 where it
// is defined, and said so rather than estimated by differences.
class PointInViewConstraint : public csp::Constraint {
 public:
  PointInViewConstraint(const CameraConstraintContext& c, Eigen::Vector3d point, double weight,
                        bool hard)
      : Constraint({c.cam_x, c.cam_y, c.cam_z}, weight, hard), scene_(&c.scene), point_(point) {}
  std::string_view kind() const override { return "camera.keep_point_in_view"; }
  double query_cost() const override { return 1; }  // one sight line
  double violation(std::span<const double> values) const override {
    const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
    return scene_->line_of_sight(camera, point_) ? 0.0 : 1.0;
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override {
    std::fill(gradient.begin(), gradient.end(), 0.0);
    return violation(values);
  }

 private:
  const SceneAtTime* scene_;
  Eigen::Vector3d point_;
};

// A profile term's kind: `build(context, weight, hard)` makes the constraint; from_profile
// reads the weight and hardness from the profile (null when `enabled` says it is left out);
// an `extras:` entry gives them as every constraint does (weight, hard).
template <class Build, class FromProfile>
CameraConstraintKind profile_term(std::string name, std::string label, std::string description,
                                  Build build, FromProfile from_profile) {
  CameraConstraintKind kind;
  kind.name = std::move(name);
  kind.label = std::move(label);
  kind.description = std::move(description);
  kind.make = [build](const CameraConstraintContext& c, const csp::Spec& entry) {
    return build(c, csp::read_weight(entry), csp::read_hard(entry));
  };
  kind.from_profile = [build, from_profile](const CameraConstraintContext& c,
                                           const CameraProfile& profile)
      -> std::unique_ptr<csp::Constraint> {
    const std::optional<std::pair<double, bool>> term = from_profile(profile);
    if (!term) return nullptr;
    return build(c, term->first, term->second);
  };
  return kind;
}

using Term = std::optional<std::pair<double, bool>>;  // weight and hardness, or left out

// Sets the hardness the entry or the profile asks for on a kind built soft.
std::unique_ptr<csp::Constraint> with_hard(std::unique_ptr<csp::Constraint> c, bool hard) {
  c->set_hard(hard);
  return c;
}

// The profile's terms, in the order each frame's problem holds them (thesis section 3.1 and
// docs/CAMERA.md): the four framing terms, the sight line, the body, clearance, anticipation.
void add_profile_terms(CameraConstraintKinds& kinds) {
  kinds.add(profile_term(
      "camera.height", "height", "|desired height - (camera y - character y)| (metres)",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return with_hard(std::make_unique<HeightConstraint>(c.cam_y, c.frame, w), hard);
      },
      [](const CameraProfile& p) { return Term{{p.height.weight, false}}; }));
  kinds.add(profile_term(
      "camera.distance", "distance",
      "|desired distance - horizontal distance to the character| (metres)",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return with_hard(std::make_unique<DistanceConstraint>(c.cam_x, c.cam_z, c.frame, w), hard);
      },
      [](const CameraProfile& p) { return Term{{p.distance.weight, false}}; }));
  kinds.add(profile_term(
      "camera.orientation", "orientation",
      "angle between the camera's bearing and the desired one behind the character (degrees)",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return with_hard(std::make_unique<OrientationConstraint>(c.cam_x, c.cam_z, c.frame, w),
                         hard);
      },
      [](const CameraProfile& p) { return Term{{p.orientation.weight, false}}; }));
  kinds.add(profile_term(
      "camera.frame_coherence", "frame coherence", "camera speed since the last frame (m/s)",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return with_hard(
            std::make_unique<FrameCoherenceConstraint>(c.cam_x, c.cam_y, c.cam_z, c.frame, w), hard);
      },
      [](const CameraProfile& p) { return Term{{p.frame_coherence_weight, false}}; }));
  kinds.add(profile_term(
      "camera.look_at_visible", "look-at visible",
      "1 when the sight line to the character's look-at point is blocked",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return std::make_unique<LookAtVisibleConstraint>(c.cam_x, c.cam_y, c.cam_z, c.scene,
                                                         c.frame, w, hard);
      },
      [](const CameraProfile& p) { return Term{{p.look_at_weight, p.look_at_hard}}; }));
  kinds.add(profile_term(
      "camera.visible_fraction", "body visible", "1 - the visible fraction of the body (9 samples)",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return with_hard(std::make_unique<BodyVisibilityConstraint>(c.cam_x, c.cam_y, c.cam_z,
                                                                    c.scene, c.frame, w),
                         hard);
      },
      [](const CameraProfile& p) {
        return p.visible_fraction_weight > 0 ? Term{{p.visible_fraction_weight, false}}
                                             : Term{};
      }));
  kinds.add(profile_term(
      "camera.clearance", "clearance",
      "how far the clearance sphere around the camera goes into solids (metres)",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return std::make_unique<ClearanceConstraint>(c.cam_x, c.cam_y, c.cam_z, c.scene, c.frame,
                                                     w, hard);
      },
      [](const CameraProfile& p) { return Term{{p.clearance_weight, p.clearance_hard}}; }));
  kinds.add(profile_term(
      "camera.future_visible", "future visible",
      "weighted fraction of the predicted look-at points hidden (anticipation)",
      [](const CameraConstraintContext& c, double w, bool hard) {
        return with_hard(std::make_unique<FutureVisibleConstraint>(c.cam_x, c.cam_y, c.cam_z,
                                                                   c.prediction, w),
                         hard);
      },
      [](const CameraProfile& p) {
        return p.anticipation.lookahead != Lookahead::kNone && p.anticipation.weight > 0
                   ? Term{{p.anticipation.weight, false}}
                   : Term{};
      }));
}

void add_builtin_camera_kinds(CameraConstraintKinds& kinds) {
  add_profile_terms(kinds);
  CameraConstraintKind point;
  point.name = "camera.keep_point_in_view";
  point.description = "a fixed point of the world (point: [x, y, z]) visible from the camera";
  point.fields = {"point"};
  point.make = [](const CameraConstraintContext& c, const csp::Spec& entry) {
    const Eigen::Vector3d p = detail::read_vector3(entry.at("point"), "the point to keep in view");
    return std::make_unique<PointInViewConstraint>(c, p, csp::read_weight(entry),
                                                   csp::read_hard(entry));
  };
  kinds.add(std::move(point));
}

}  // namespace

CameraConstraintKinds& CameraConstraintKinds::global() {
  static CameraConstraintKinds* kinds = [] {
    auto* k = new CameraConstraintKinds;
    add_builtin_camera_kinds(*k);
    return k;
  }();
  return *kinds;
}

void CameraConstraintKinds::add(CameraConstraintKind kind) {
  if (kind.name.empty() || !kind.make) {
    throw std::invalid_argument("a camera constraint kind needs a name and a make function");
  }
  if (kinds_.count(kind.name)) {
    throw std::invalid_argument("camera constraint kind '" + kind.name + "' is registered twice");
  }
  const std::string name = kind.name;
  const CameraConstraintKind& added = kinds_.emplace(name, std::move(kind)).first->second;
  if (added.from_profile) profile_terms_.push_back(&added);
}

const CameraConstraintKind* CameraConstraintKinds::find(const std::string& name) const {
  const auto it = kinds_.find(name);
  return it == kinds_.end() ? nullptr : &it->second;
}

std::vector<std::string> CameraConstraintKinds::names() const {
  std::vector<std::string> out;
  for (const auto& [name, kind] : kinds_) out.push_back(name);
  return out;
}

}  // namespace sightline::camera
