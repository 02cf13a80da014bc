#include "sightline/domains/camera/constraints/camera_constraint_kinds.h"

#include <algorithm>
#include <stdexcept>

#include "sightline/csp/kinds/constraint_entry.h"
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

void add_builtin_camera_kinds(CameraConstraintKinds& kinds) {
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
  kinds_.emplace(name, std::move(kind));
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
