#include "sightline/experiments/runs/independent_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline::experiments {

SolidBox moving_box_at(const MovingBox& mover, double t) {
  // Walk the keyframes from the end: the last one at or before t starts the leg holding t.
  const std::size_t n = mover.times.size();
  Eigen::Vector3d base = mover.positions.front();
  if (t >= mover.times[n - 1]) {
    base = mover.positions[n - 1];
  } else if (t > mover.times[0]) {
    std::size_t k = n - 1;
    while (mover.times[k] > t) --k;  // stops: times[0] < t
    const double w = (t - mover.times[k]) / (mover.times[k + 1] - mover.times[k]);
    base = (1 - w) * mover.positions[k] + w * mover.positions[k + 1];
  }
  const Eigen::Vector3d half(mover.size.x() / 2, 0, mover.size.z() / 2);
  return {base - half, base + half + Eigen::Vector3d(0, mover.size.y(), 0)};
}

void moving_boxes_at(const std::vector<MovingBox>& movers, double t, std::vector<SolidBox>& out) {
  out.clear();
  for (const MovingBox& m : movers) out.push_back(moving_box_at(m, t));
}

bool segment_blocked(const std::vector<SolidBox>& boxes, const Eigen::Vector3d& a,
                     const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  for (const SolidBox& box : boxes) {
    // Clip the parameter interval [0, 1] by the six half-spaces p_i >= min_i, p_i <= max_i.
    double t0 = 0, t1 = 1;
    bool outside = false;
    for (int i = 0; i < 3 && !outside; ++i) {
      const double p[2] = {-d[i], d[i]};
      const double q[2] = {a[i] - box.min[i], box.max[i] - a[i]};
      for (int k = 0; k < 2; ++k) {
        if (p[k] == 0) {
          if (q[k] < 0) outside = true;  // parallel and beyond this face
        } else {
          const double r = q[k] / p[k];
          if (p[k] < 0) t0 = std::max(t0, r);
          else t1 = std::min(t1, r);
        }
      }
      if (t0 > t1) outside = true;
    }
    if (!outside) return true;
  }
  return false;
}

double distance_to_geometry(const std::vector<SolidBox>& boxes, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const SolidBox& box : boxes) {
    const Eigen::Vector3d nearest = p.cwiseMax(box.min).cwiseMin(box.max);
    best = std::min(best, (p - nearest).norm());
  }
  return best;
}

std::vector<Eigen::Vector3d> body_check_points(const Eigen::Vector3d& feet,
                                               const Eigen::Vector3d& size) {
  // A 3 x 5 x 3 grid (x, y, z) over the box inset by 10%: 45 points, dense enough that one
  // point is ~2% of the body, and independent of how the controller samples.
  std::vector<Eigen::Vector3d> points;
  points.reserve(45);
  for (int ix = 0; ix < 3; ++ix) {
    for (int iy = 0; iy < 5; ++iy) {
      for (int iz = 0; iz < 3; ++iz) {
        points.emplace_back(feet.x() + size.x() * 0.8 * (ix / 2.0 - 0.5),
                            feet.y() + size.y() * (0.1 + 0.8 * iy / 4.0),
                            feet.z() + size.z() * 0.8 * (iz / 2.0 - 0.5));
      }
    }
  }
  return points;
}

double visible_body_fraction(const std::vector<SolidBox>& boxes, const Eigen::Vector3d& eye,
                             const Eigen::Vector3d& feet, const Eigen::Vector3d& size) {
  const std::vector<Eigen::Vector3d> points = body_check_points(feet, size);
  int visible = 0;
  for (const Eigen::Vector3d& p : points) visible += !segment_blocked(boxes, eye, p);
  return static_cast<double>(visible) / static_cast<double>(points.size());
}

}  // namespace sightline::experiments
