#include "sightline/domains/camera/baselines/pull_forward.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "sightline/domains/camera/baselines/baseline_frame.h"

namespace sightline::camera {

namespace {

// -ln(0.01): Cinemachine's damping time is when 99% of a step is done.
constexpr double kLogNegligibleResidual = 4.605170185988091;
constexpr int kMaxRadiusSteps = 16;

PullForwardOptions checked(PullForwardOptions options) {
  if (std::string why = options.validate(); !why.empty()) {
    throw std::invalid_argument("pull-forward: " + why);
  }
  return options;
}

// The fraction of a step a damper with time constant T covers in dt (1 when T = 0).
double damped_fraction(double dt, double time) {
  return time > 0 ? 1 - std::exp(-kLogNegligibleResidual * dt / time) : 1.0;
}

}  // namespace

std::string PullForwardOptions::validate() const {
  auto finite_nonnegative = [](double v) { return std::isfinite(v) && v >= 0; };
  if (!finite_nonnegative(camera_radius)) return "camera_radius must be >= 0 (m)";
  if (!(std::isfinite(minimum_distance_from_target) && minimum_distance_from_target > 0)) {
    return "minimum_distance_from_target must be > 0 (m)";
  }
  if (!finite_nonnegative(damping)) return "damping must be >= 0 (s)";
  if (!finite_nonnegative(damping_when_occluded)) return "damping_when_occluded must be >= 0 (s)";
  if (!finite_nonnegative(slush)) return "slush must be >= 0 (m)";
  if (!(std::isfinite(max_speed) && max_speed > 0)) return "max_speed must be > 0 (m/s)";
  return "";
}

PullForward::PullForward(const Scene& scene, const CameraProfile& profile,
                         PullForwardOptions options)
    : scene_(&scene), profile_(&profile), options_(checked(options)), problem_(scene, profile) {
  reset(scene.start_camera_position());
}

void PullForward::reset(const Eigen::Vector3d& position) {
  frame_.position = position;
  first_update_ = true;
}

Eigen::Vector3d PullForward::pull_in_front(const Eigen::Vector3d& preferred,
                                           const Eigen::Vector3d& look) {
  occluded_ = false;
  const Eigen::Vector3d offset = preferred - look;
  const double distance = offset.norm();
  const double min_distance = options_.minimum_distance_from_target;
  if (distance <= min_distance) return preferred;  // too close to have anything in between
  const Eigen::Vector3d dir = offset / distance;
  // 1. Along the line from the target out to the preferred spot, the first obstacle.
  double s = distance;  // the camera's distance from the look-at point along dir
  const Eigen::Vector3d start = look + min_distance * dir;
  if (const auto hit = problem_.scene_at_time().first_hit(start, preferred)) {
    occluded_ = true;
    s = std::max(min_distance, min_distance + hit->t * (distance - min_distance) - options_.slush);
  }
  // 2. Keep camera_radius from every box: pull in by the shortfall until clear. The distance
  // field is 1-Lipschitz, so each step is at most what is needed; a few steps settle it.
  const double r = options_.camera_radius;
  if (r > 0) {
    for (int i = 0; i < kMaxRadiusSteps && s > min_distance; ++i) {
      const double shortfall = r - problem_.scene_at_time().clearance(look + s * dir, r);
      if (shortfall <= 0) break;
      s = std::max(min_distance, s - std::max(shortfall, 1e-6));
    }
  }
  return look + s * dir;
}

const CameraFrame& PullForward::update(const CharacterState& character, double dt) {
  const auto started = std::chrono::steady_clock::now();
  if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("update needs dt > 0");
  const Eigen::Vector3d previous = frame_.position;
  // First, so the probes below see the movers where they are at this frame's time.
  problem_.set_frame(character, previous, dt);
  const Eigen::Vector3d look = scene_->character().look_at(character.position);
  preferred_ = ideal_camera_position(character, profile_->height.desired,
                                     profile_->distance.desired, profile_->orientation.desired);
  corrected_ = pull_in_front(preferred_, look);

  // 3. Damping of the correction: in (growing) with damping_when_occluded, out with damping.
  const Eigen::Vector3d correction = corrected_ - preferred_;
  if (first_update_) {
    shown_correction_ = correction;
    first_update_ = false;
  } else {
    const bool growing = correction.squaredNorm() > shown_correction_.squaredNorm();
    const double time = growing ? options_.damping_when_occluded : options_.damping;
    shown_correction_ += (correction - shown_correction_) * damped_fraction(dt, time);
  }
  const Eigen::Vector3d position = preferred_ + shown_correction_;

  describe_baseline_frame(problem_, previous, position, look, max_step(dt), frame_);
  frame_.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return frame_;
}

}  // namespace sightline::camera
