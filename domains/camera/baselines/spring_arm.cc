#include "sightline/domains/camera/baselines/spring_arm.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "sightline/domains/camera/baselines/baseline_frame.h"

namespace sightline::camera {

namespace {

// Unreal's camera-lag substep: 1/60 s at most, so the lag does not depend on the frame rate.
constexpr double kMaxLagSubstep = 1.0 / 60.0;

// The arm for a yaw: from the look-at point to the profile's preferred spot, as if the
// character's feet were at the origin.
Eigen::Vector3d arm_vector(const CameraProfile& profile, const CharacterShape& shape, double yaw) {
  CharacterState at_origin;
  at_origin.yaw = yaw;
  return ideal_camera_position(at_origin, profile.height.desired, profile.distance.desired,
                               profile.orientation.desired) -
         shape.look_at(Eigen::Vector3d::Zero());
}

SpringArmOptions checked(SpringArmOptions options) {
  if (std::string why = options.validate(); !why.empty()) {
    throw std::invalid_argument("spring-arm: " + why);
  }
  return options;
}

}  // namespace

std::string SpringArmOptions::validate() const {
  auto finite_nonnegative = [](double v) { return std::isfinite(v) && v >= 0; };
  if (!(std::isfinite(probe_radius) && probe_radius > 0)) return "probe_radius must be > 0 (m)";
  if (!finite_nonnegative(lag_speed)) return "lag_speed must be >= 0 (1/s; 0 disables the lag)";
  if (!finite_nonnegative(rotation_lag_speed)) {
    return "rotation_lag_speed must be >= 0 (1/s; 0 disables the lag)";
  }
  if (!target_offset.allFinite()) return "target_offset must be finite (m)";
  if (!(std::isfinite(max_speed) && max_speed > 0)) return "max_speed must be > 0 (m/s)";
  return "";
}

SpringArm::SpringArm(const Scene& scene, const CameraProfile& profile, SpringArmOptions options)
    : scene_(&scene),
      profile_(&profile),
      options_(checked(options)),
      problem_(scene, profile),
      probe_(problem_.scene_at_time(), options_.probe_radius) {
  reset(scene.start_camera_position());
}

void SpringArm::reset(const Eigen::Vector3d& position) {
  frame_.position = position;
  first_update_ = true;
}

const CameraFrame& SpringArm::update(const CharacterState& character, double dt) {
  const auto started = std::chrono::steady_clock::now();
  if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("update needs dt > 0");
  const Eigen::Vector3d previous = frame_.position;
  // First, so the probe below sees the movers where they are at this frame's time.
  problem_.set_frame(character, previous, dt);
  const Eigen::Vector3d look = scene_->character().look_at(character.position);
  pivot_ = look + options_.target_offset;

  // 1. Lag of the arm's end: the pivot and the yaw each close a fraction min(1, speed x h)
  // of their gap per substep h (exponential approach; speed 0 means no lag at all).
  if (first_update_) {
    lagged_pivot_ = pivot_;
    lagged_yaw_ = character.yaw;
    first_update_ = false;
  } else {
    const int substeps = std::max(1, static_cast<int>(std::ceil(dt / kMaxLagSubstep - 1e-9)));
    const double h = dt / substeps;
    const double move = options_.lag_speed > 0 ? std::min(1.0, options_.lag_speed * h) : 1.0;
    const double turn =
        options_.rotation_lag_speed > 0 ? std::min(1.0, options_.rotation_lag_speed * h) : 1.0;
    for (int i = 0; i < substeps; ++i) {
      lagged_pivot_ += (pivot_ - lagged_pivot_) * move;
      lagged_yaw_ = wrap_degrees(lagged_yaw_ + turn * shortest_turn(lagged_yaw_, character.yaw));
    }
  }
  desired_end_ = lagged_pivot_ + arm_vector(*profile_, scene_->character(), lagged_yaw_);

  // 2. The probe, from the real pivot: the camera stops where the sphere first touches.
  Eigen::Vector3d position = desired_end_;
  pulled_in_ = false;
  if (const std::optional<double> t = probe_.first_contact(pivot_, desired_end_)) {
    position = pivot_ + *t * (desired_end_ - pivot_);
    pulled_in_ = true;
  }

  describe_baseline_frame(problem_, previous, position, look, max_step(dt), frame_);
  frame_.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return frame_;
}

}  // namespace sightline::camera
