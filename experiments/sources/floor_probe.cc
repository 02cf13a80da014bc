#include "sightline/experiments/sources/floor_probe.h"

namespace sightline::experiments {

FloorProbe::FloorProbe(const camera::TriangleMesh& mesh, double person_height)
    : index_(mesh), person_height_(person_height) {}

std::optional<double> FloorProbe::floor_below(double x, double z, double top, double bottom) const {
  const auto hit = index_.first_hit({x, top, z}, {x, bottom, z});
  if (!hit) return std::nullopt;
  return top + hit->t * (bottom - top);
}

bool FloorProbe::segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  return index_.segment_blocked(a, b);
}

bool FloorProbe::has_headroom(const Eigen::Vector3d& feet) const {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  return !segment_blocked(feet + 0.005 * up, feet + person_height_ * up);
}

bool FloorProbe::body_clear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  for (double h : kBodyHeights) {
    if (h < person_height_ && segment_blocked(a + h * up, b + h * up)) return false;
  }
  return true;
}

}  // namespace sightline::experiments
