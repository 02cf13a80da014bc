#include "experiments/floor_probe.h"

#include <algorithm>
#include <cmath>

namespace sightline::experiments {

FloorProbe::FloorProbe(const camera::TriangleMesh& mesh, double person_height)
    : mesh_(mesh), person_height_(person_height) {
  if (mesh.empty()) return;
  const camera::Aabb b = mesh.bounds();
  // About 250 000 cells at most, none under a metre.
  cell_ = std::max(1.0, std::sqrt((b.size().x() + 1) * (b.size().z() + 1) / 250000.0));
  min_x_ = b.min.x();
  min_z_ = b.min.z();
  nx_ = static_cast<int>(b.size().x() / cell_) + 1;
  nz_ = static_cast<int>(b.size().z() / cell_) + 1;
  std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * nz_ + 1, 0);
  // Two passes (count, then fill) over each triangle's footprint.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
      double x0 = 1e300, z0 = 1e300, x1 = -1e300, z1 = -1e300;
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3d v = mesh.vertex(i, c);
        x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
        z0 = std::min(z0, v.z()), z1 = std::max(z1, v.z());
      }
      for_cells(x0, z0, x1, z1, [&](std::size_t cell) {
        if (pass == 0) {
          ++count[cell];
        } else {
          triangles_[start_[cell] + count[cell]++] = i;
        }
      });
    }
    if (pass == 0) {
      start_.assign(count.size(), 0);
      for (std::size_t c = 1; c < count.size(); ++c) start_[c] = start_[c - 1] + count[c - 1];
      triangles_.resize(start_.back());
      std::fill(count.begin(), count.end(), 0);
    }
  }
}

template <class Visit>
void FloorProbe::for_cells(double x0, double z0, double x1, double z1, Visit&& visit) const {
  const auto index = [&](double v, double min, int n) {
    return std::clamp(static_cast<int>(std::floor((v - min) / cell_)), 0, n - 1);
  };
  const int i0 = index(x0, min_x_, nx_), i1 = index(x1, min_x_, nx_);
  const int k0 = index(z0, min_z_, nz_), k1 = index(z1, min_z_, nz_);
  for (int k = k0; k <= k1; ++k) {
    for (int i = i0; i <= i1; ++i) visit(static_cast<std::size_t>(k) * nx_ + i);
  }
}

std::optional<double> FloorProbe::hit(std::uint32_t i, const Eigen::Vector3d& a,
                                      const Eigen::Vector3d& d) const {
  // Moller-Trumbore, two-sided; a hair of tolerance on the edges so a segment through an
  // edge two triangles share meets one of them.
  const Eigen::Vector3d v0 = mesh_.vertex(i, 0);
  const Eigen::Vector3d e1 = mesh_.vertex(i, 1) - v0, e2 = mesh_.vertex(i, 2) - v0;
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return std::nullopt;
  const double inv = 1.0 / det;
  const Eigen::Vector3d s = a - v0;
  const double u = s.dot(p) * inv;
  if (u < -1e-9 || u > 1 + 1e-9) return std::nullopt;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < -1e-9 || u + v > 1 + 1e-9) return std::nullopt;
  const double t = e2.dot(q) * inv;
  if (t < 0 || t > 1) return std::nullopt;
  return t;
}

std::optional<double> FloorProbe::floor_below(double x, double z, double top, double bottom) const {
  if (mesh_.empty()) return std::nullopt;
  const Eigen::Vector3d a(x, top, z), d(0, bottom - top, 0);
  std::optional<double> first;
  for_cells(x, z, x, z, [&](std::size_t cell) {
    for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
      const auto t = hit(triangles_[k], a, d);
      if (t && (!first || *t < *first)) first = t;
    }
  });
  if (!first) return std::nullopt;
  return top + *first * (bottom - top);
}

bool FloorProbe::segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (mesh_.empty()) return false;
  const Eigen::Vector3d d = b - a;
  bool blocked = false;
  for_cells(std::min(a.x(), b.x()), std::min(a.z(), b.z()), std::max(a.x(), b.x()),
            std::max(a.z(), b.z()), [&](std::size_t cell) {
              for (std::uint32_t k = start_[cell]; !blocked && k < start_[cell + 1]; ++k) {
                blocked = hit(triangles_[k], a, d).has_value();
              }
            });
  return blocked;
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
