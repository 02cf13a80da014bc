#include "sightline/domains/camera/composition/group_framing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace sightline::camera {
namespace {

constexpr double kRadians = 3.14159265358979323846 / 180.0;
constexpr double kPullMargin = 0.3;  // metres kept from what the arm meets

const Shot& shot_of(const Scene& scene) {
  if (!scene.shot()) throw std::invalid_argument("group-framing needs a scene with a shot: block");
  return *scene.shot();
}

}  // namespace

GroupFraming::GroupFraming(const Scene& scene, double max_speed)
    : scene_(&scene), max_speed_(max_speed), problem_(scene, shot_of(scene), scene.trajectory().start_time()) {
  const Shot& shot = *scene.shot();
  // The offset an engine user would set: the first target's angle properties, or its front.
  const int first = problem_.wanted().front();
  double bearing = 0, elevation = 15;
  for (std::size_t i = 0; i < shot.properties.size(); ++i) {
    const ShotProperty& p = shot.properties[i];
    if (problem_.targets()[i].size() != 1 || problem_.targets()[i][0] != first) continue;
    if (p.kind == "angle_horizontal") {
      bearing = arc_middle(p.range);
    } else if (p.kind == "angle_vertical" && std::isfinite(p.range.lo) && std::isfinite(p.range.hi)) {
      elevation = (p.range.lo + p.range.hi) / 2;
    }
  }
  const double yaw = (problem_.world().people()[static_cast<std::size_t>(first)].yaw + bearing) * kRadians;
  offset_ = Eigen::Vector3d(std::cos(elevation * kRadians) * std::sin(yaw), std::sin(elevation * kRadians),
                            std::cos(elevation * kRadians) * std::cos(yaw));
}

void GroupFraming::reset(const Eigen::Vector3d& position) {
  position_ = position;
  started_ = false;
}

const CameraFrame& GroupFraming::update(const CharacterState& character, double dt) {
  const auto began = std::chrono::steady_clock::now();
  problem_.set_time(character.t);
  const Shot& shot = problem_.shot();
  // The group's centre and the radius of the sphere round their boxes.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int t : problem_.wanted()) centre += problem_.world().people()[static_cast<std::size_t>(t)].body.centre();
  centre /= static_cast<double>(problem_.wanted().size());
  double radius = 0;
  for (int t : problem_.wanted()) {
    const Aabb& b = problem_.world().people()[static_cast<std::size_t>(t)].body;
    radius = std::max(radius, (b.centre() - centre).norm() + b.size().norm() / 2);
  }
  const double fov = (shot.fov.lo + shot.fov.hi) / 2;
  const double distance = 1.1 * radius / std::sin(fov * kRadians / 2);
  Eigen::Vector3d wanted = centre + distance * offset_;
  // The deoccluder: pull in to just short of the first solid from the centre.
  if (const std::optional<SurfaceHit> hit = scene_->surface_hit(centre, wanted, character.t)) {
    wanted = centre + std::max(0.0, hit->t * distance - kPullMargin) * offset_;
  }
  for (int k = 0; k < 3; ++k) wanted[k] = std::clamp(wanted[k], shot.region.min[k], shot.region.max[k]);
  frame_.cut = false;
  frame_.cut_reason = CutReason::kNone;
  if (!started_) {
    position_ = wanted;
    started_ = true;
  } else {
    const Eigen::Vector3d step = (1 - std::exp(-dt / 0.2)) * (wanted - position_);
    if (step.norm() > max_step(dt)) {
      frame_.cut = true;
      frame_.cut_reason = CutReason::kTooFast;
    }
    position_ += step;
  }
  CameraPose pose;
  pose.position = position_;
  pose.look_at = centre;
  if ((pose.look_at - pose.position).norm() < 1e-6) pose.look_at += Eigen::Vector3d::UnitZ();
  pose.fov = fov;
  pose.roll = std::clamp(0.0, shot.roll.lo, shot.roll.hi);
  pose.aspect = shot.aspect;
  const ShotEvaluation e = problem_.evaluate(pose);
  fill_frame(problem_, pose, e.feasible, wanted, frame_);
  frame_.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return frame_;
}

}  // namespace sightline::camera
