#include "sightline/experiments/runs/independent_triangles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace sightline::experiments {

namespace {

double segment_point_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& p,
                              const Eigen::Vector3d& q) {
  const Eigen::Vector3d d = q - p;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0 ? std::clamp((x - p).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (x - (p + s * d)).norm();
}

}  // namespace

bool segment_meets_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                            const Eigen::Vector3d& r) {
  constexpr double kEps = 1e-9;
  const Eigen::Vector3d dir = b - a;
  const Eigen::Vector3d e1 = q - p, e2 = r - p;
  const Eigen::Vector3d h = dir.cross(e2);
  const double det = e1.dot(h);
  const double scale = e1.norm() * e2.norm() * dir.norm();
  if (scale == 0) {
    // A zero-length segment: a point on the triangle touches it.
    return dir.norm() == 0 && point_triangle_distance(a, p, q, r) <= kEps;
  }
  if (std::abs(det) <= kEps * scale) return false;  // parallel to the plane: grazes at most
  const double f = 1.0 / det;
  const Eigen::Vector3d s = a - p;
  const double u = f * s.dot(h);
  if (u < -kEps || u > 1 + kEps) return false;
  const Eigen::Vector3d qv = s.cross(e1);
  const double v = f * dir.dot(qv);
  if (v < -kEps || u + v > 1 + kEps) return false;
  const double t = f * e2.dot(qv);
  return t >= -kEps && t <= 1 + kEps;
}

double point_triangle_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& p,
                               const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
  const Eigen::Vector3d n = (q - p).cross(r - p);
  const double area2 = n.norm();
  if (area2 > 0) {
    const Eigen::Vector3d unit = n / area2;
    const double height = (x - p).dot(unit);
    const Eigen::Vector3d y = x - height * unit;  // projection onto the plane
    // Inside when y is on the inner side of all three edges.
    const bool inside = (q - p).cross(y - p).dot(n) >= 0 && (r - q).cross(y - q).dot(n) >= 0 &&
                        (p - r).cross(y - r).dot(n) >= 0;
    if (inside) return std::abs(height);
  }
  return std::min({segment_point_distance(x, p, q), segment_point_distance(x, q, r),
                   segment_point_distance(x, r, p)});
}

IndependentTriangles::IndependentTriangles(const camera::TriangleMesh& mesh) {
  triangles_.reserve(mesh.size());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (std::uint32_t i = 0; i < mesh.size(); ++i) {
    Triangle t{mesh.vertex(i, 0), mesh.vertex(i, 1), mesh.vertex(i, 2)};
    for (const auto* v : {&t.a, &t.b, &t.c}) {
      lo = lo.cwiseMin(*v);
      hi = hi.cwiseMax(*v);
    }
    triangles_.push_back(t);
  }
  if (triangles_.empty()) return;
  // About 4 triangles per occupied cell on a level's surfaces: cells of a size that splits
  // the bounds into ~ (n / 4)^(1/2) along the longest side (surfaces, not volumes).
  const Eigen::Vector3d extent = (hi - lo).cwiseMax(1e-3);
  cell_ = std::max(0.5, extent.maxCoeff() / std::max(1.0, std::sqrt(triangles_.size() / 4.0)));
  origin_ = lo - Eigen::Vector3d::Constant(1e-6);
  std::size_t total = 1;
  for (int k = 0; k < 3; ++k) {
    cells_[k] = static_cast<long>(std::floor(extent[k] / cell_)) + 1;
    total *= static_cast<std::size_t>(cells_[k]);
  }
  std::vector<std::uint32_t> counts(total + 1, 0);
  auto for_cells = [&](const Triangle& t, auto&& f) {
    const Eigen::Vector3d tl = t.a.cwiseMin(t.b).cwiseMin(t.c), th = t.a.cwiseMax(t.b).cwiseMax(t.c);
    const auto c0 = cell_of(tl), c1 = cell_of(th);
    for (long x = c0[0]; x <= c1[0]; ++x)
      for (long y = c0[1]; y <= c1[1]; ++y)
        for (long z = c0[2]; z <= c1[2]; ++z) f(static_cast<std::size_t>((x * cells_[1] + y) * cells_[2] + z));
  };
  for (const Triangle& t : triangles_) for_cells(t, [&](std::size_t c) { ++counts[c + 1]; });
  for (std::size_t c = 0; c < total; ++c) counts[c + 1] += counts[c];
  first_ = counts;
  items_.resize(first_.back());
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::uint32_t i = 0; i < triangles_.size(); ++i) {
    for_cells(triangles_[i], [&](std::size_t c) { items_[fill[c]++] = i; });
  }
}

std::array<long, 3> IndependentTriangles::cell_of(const Eigen::Vector3d& p) const {
  std::array<long, 3> c{};
  for (int k = 0; k < 3; ++k) {
    const double f = std::floor((p[k] - origin_[k]) / cell_);
    c[k] = static_cast<long>(std::clamp(f, 0.0, static_cast<double>(cells_[k] - 1)));
  }
  return c;
}

template <class Visit>
bool IndependentTriangles::visit_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                     Visit&& visit) const {
  if (triangles_.empty()) return false;
  const auto c0 = cell_of(lo), c1 = cell_of(hi);
  for (long x = c0[0]; x <= c1[0]; ++x) {
    for (long y = c0[1]; y <= c1[1]; ++y) {
      for (long z = c0[2]; z <= c1[2]; ++z) {
        const auto c = static_cast<std::size_t>((x * cells_[1] + y) * cells_[2] + z);
        for (std::uint32_t k = first_[c]; k < first_[c + 1]; ++k) {
          if (visit(items_[k])) return true;
        }
      }
    }
  }
  return false;
}

bool IndependentTriangles::segment_blocked(const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b) const {
  // Cells clamp to the grid, so a segment reaching outside the bounds still visits the
  // border cells: nothing lies outside them.
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(1e-6);
  return visit_box(a.cwiseMin(b) - pad, a.cwiseMax(b) + pad, [&](std::uint32_t i) {
    const Triangle& t = triangles_[i];
    return segment_meets_triangle(a, b, t.a, t.b, t.c);
  });
}

double IndependentTriangles::distance(const Eigen::Vector3d& p, double limit) const {
  // Every triangle nearer than r touches the cube of half-size r around p, so searching the
  // cells of growing cubes (doubling r) and stopping once the best found is within r is
  // exact; the last round covers the whole grid.
  const double whole = (Eigen::Vector3d(cells_[0], cells_[1], cells_[2]) * cell_).norm() +
                       (p - origin_).cwiseAbs().maxCoeff();
  double best = limit;
  for (double r = cell_;; r *= 2) {
    const double reach = std::min({r, limit, whole});
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(reach);
    visit_box(p - half, p + half, [&](std::uint32_t i) {
      const Triangle& t = triangles_[i];
      best = std::min(best, point_triangle_distance(p, t.a, t.b, t.c));
      return false;
    });
    if (best <= reach || reach >= limit || reach >= whole) return best;
  }
}

}  // namespace sightline::experiments
