#include "sightline/domains/camera/motion_prediction.h"

#include <algorithm>
#include <cmath>

namespace sightline::camera {

namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
// The previous frame counts for the turn rate only when it is this recent (seconds): after a
// pause or a jump in time, a yaw difference is not a rate.
constexpr double kMaxRateInterval = 0.25;

// v turned by `degrees` about +y, the way yaw turns (yaw 0 faces +z, 90 faces +x).
Eigen::Vector3d turned(const Eigen::Vector3d& v, double degrees) {
  const double a = degrees * kRadiansPerDegree;
  const double c = std::cos(a), s = std::sin(a);
  return {v.x() * c + v.z() * s, v.y(), v.z() * c - v.x() * s};
}

// The point `fraction` of the way along `step` from p, pulled back by `margin` metres along
// the step (never behind p).
Eigen::Vector3d short_of(const Eigen::Vector3d& p, const Eigen::Vector3d& step, double fraction,
                         double margin) {
  const double length = step.norm();
  if (length == 0) return p;
  const double travel = std::max(0.0, fraction * length - margin);
  return p + (travel / length) * step;
}

}  // namespace

MotionPrediction::MotionPrediction(const Scene& scene, const Anticipation& settings)
    : scene_(&scene), settings_(&settings) {
  // Clamped: the profile is validated by the problem that owns this, after construction.
  const int n = settings.lookahead == Lookahead::kNone
                    ? 0
                    : std::clamp(settings.samples, 1, Anticipation::kMaxSamples);
  geometry_.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) geometry_.push_back(std::make_unique<SceneAtTime>(scene));
}

void MotionPrediction::update(const CharacterState& character) {
  if (geometry_.empty()) return;
  if (started_ && character.t == last_t_) return;  // the same frame again
  const double since = character.t - last_t_;
  turn_rate_ = spin_rate_ = last_turn_ = 0;
  if (started_ && since > 0 && since <= kMaxRateInterval) {
    last_turn_ = shortest_turn(last_yaw_, character.yaw);
    spin_rate_ = last_turn_ / since;
    turn_rate_ = std::clamp(spin_rate_, -kMaxTurnRate, kMaxTurnRate);
  }
  started_ = true;
  last_t_ = character.t;
  last_yaw_ = character.yaw;
  const double pace = std::hypot(character.velocity.x(), character.velocity.z());
  if (pace >= kStillSpeed) {
    moving_pace_ = pace;
    moved_at_ = character.t;
  }

  size_ = static_cast<int>(geometry_.size());
  total_weight_ = 0;
  for (int k = 0; k < size_; ++k) {
    Sample& s = samples_[static_cast<std::size_t>(k)];
    s.ahead = settings_->horizon * (k + 1) / size_;
    s.weight = std::exp(-s.ahead / settings_->decay);
    total_weight_ += s.weight;
  }
  if (settings_->lookahead == Lookahead::kPath) {
    predict_path(character);
  } else {
    predict_motion(character);
  }
}

void MotionPrediction::predict_path(const CharacterState& character) {
  for (int k = 0; k < size_; ++k) {
    Sample& s = samples_[static_cast<std::size_t>(k)];
    const double t = character.t + s.ahead;
    s.look_at = scene_->character().look_at(scene_->trajectory().state_at(t).position);
    geometry_[static_cast<std::size_t>(k)]->set_time(t);
  }
}

void MotionPrediction::predict_motion(const CharacterState& character) {
  Eigen::Vector3d p = scene_->character().look_at(character.position);
  Eigen::Vector3d v = character.velocity;
  double rate = turn_rate_;
  if (std::hypot(v.x(), v.z()) < kStillSpeed && std::abs(spin_rate_) >= kSetOffTurnRate &&
      character.t - moved_at_ <= kPaceMemory) {  // setting off (see the header)
    // A facing snapped in one frame is where she turned to: no lead.
    const double lead = std::abs(last_turn_) >= kSnapTurn
                            ? 0.0
                            : std::clamp(spin_rate_ * kSetOffLead, -90.0, 90.0);
    v = moving_pace_ * turned(character.facing(), lead) + Eigen::Vector3d(0, v.y(), 0);
    rate = 0;
  }
  double tau = 0;
  for (int k = 0; k < size_; ++k) {
    Sample& s = samples_[static_cast<std::size_t>(k)];
    while (tau < s.ahead - 1e-12 && v.squaredNorm() > 0) {
      const double h = std::min(kMaxStep, s.ahead - tau);
      tau += h;
      v = turned(v, rate * h);
      const Eigen::Vector3d step = v * h;
      const auto hit = scene_->surface_hit(p, p + step, character.t);
      if (!hit) {
        p += step;
        continue;
      }
      const Eigen::Vector3d n = hit->normal;
      const Eigen::Vector3d at_wall = short_of(p, step, hit->t, kWallMargin);
      if (n.squaredNorm() == 0) {  // already touching: stay
        v.setZero();
        break;
      }
      // Slide: the rest of the step without its component into the wall, and the same for
      // the velocity (the character walks along the wall from here).
      const Eigen::Vector3d rest = (1 - hit->t) * step;
      const Eigen::Vector3d slide = rest - rest.dot(n) * n;
      v -= v.dot(n) * n;
      p = at_wall;
      if (slide.squaredNorm() == 0) continue;
      if (const auto again = scene_->surface_hit(p, p + slide, character.t)) {
        p = short_of(p, slide, again->t, kWallMargin);
        v.setZero();  // a corner: the forecast stops there
      } else {
        p += slide;
      }
    }
    tau = s.ahead;
    s.look_at = p;
    geometry_[static_cast<std::size_t>(k)]->set_time_extrapolated(character.t, s.ahead);
  }
}

}  // namespace sightline::camera
