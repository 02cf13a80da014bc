#include "sightline/domains/camera/mover.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sightline::camera {

Mover::Mover(std::string name, Eigen::Vector3d size, std::vector<MoverKeyframe> path,
             csp::SourceLocation where)
    : name_(std::move(name)), size_(size), path_(std::move(path)), where_(std::move(where)) {
  if (!size_.allFinite() || (size_.array() <= 0).any()) {
    throw std::invalid_argument("mover size must be finite and > 0 on every axis");
  }
  if (path_.empty()) throw std::invalid_argument("mover path needs at least one keyframe");
  for (std::size_t i = 0; i < path_.size(); ++i) {
    if (!std::isfinite(path_[i].t) || !path_[i].position.allFinite()) {
      throw std::invalid_argument("mover keyframe values must be finite");
    }
    if (i > 0 && !(path_[i].t > path_[i - 1].t)) {
      throw std::invalid_argument("mover keyframe times must increase strictly");
    }
  }
}

Eigen::Vector3d Mover::position_at(double t) const {
  if (t <= path_.front().t) return path_.front().position;
  if (t >= path_.back().t) return path_.back().position;
  const auto after = std::upper_bound(path_.begin(), path_.end(), t,
                                      [](double v, const MoverKeyframe& k) { return v < k.t; });
  std::size_t segment = static_cast<std::size_t>(after - path_.begin()) - 1;
  return position_at(t, &segment);
}

Eigen::Vector3d Mover::position_at(double t, std::size_t* segment) const {
  if (t <= path_.front().t) {
    *segment = 0;
    return path_.front().position;
  }
  if (t >= path_.back().t) {
    *segment = path_.size() - 1;
    return path_.back().position;
  }
  std::size_t i = std::min(*segment, path_.size() - 2);
  while (i > 0 && path_[i].t > t) --i;
  while (i + 2 < path_.size() && path_[i + 1].t <= t) ++i;
  *segment = i;
  const MoverKeyframe& a = path_[i];
  const MoverKeyframe& b = path_[i + 1];
  const double u = (t - a.t) / (b.t - a.t);
  return a.position + u * (b.position - a.position);
}

Eigen::Vector3d Mover::velocity_at(double t) const {
  if (path_.size() < 2 || t < path_.front().t || t >= path_.back().t) {
    return Eigen::Vector3d::Zero();
  }
  std::size_t i = 0;
  while (i + 2 < path_.size() && path_[i + 1].t <= t) ++i;
  return (path_[i + 1].position - path_[i].position) / (path_[i + 1].t - path_[i].t);
}

Aabb Mover::swept_box() const {
  Aabb all = Aabb::empty();
  // Linear motion between keyframes: the boxes at the keyframes bound every box between.
  for (const MoverKeyframe& k : path_) all.merge(Aabb::around_feet(k.position, size_));
  return all;
}

}  // namespace sightline::camera

namespace sightline::camera {

void Mover::place(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double t) {
  path_.resize(2);
  path_[0] = MoverKeyframe{t, position};
  path_[1] = MoverKeyframe{t + kForecastSeconds, position + kForecastSeconds * velocity};
}

}  // namespace sightline::camera
