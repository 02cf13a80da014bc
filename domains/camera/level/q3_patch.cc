#include "sightline/domains/camera/level/q3_patch.h"

#include <algorithm>
#include <cassert>

namespace sightline::camera::q3 {

const char* patch_size_problem(std::int64_t width, std::int64_t height,
                               std::int64_t control_points) {
  if (width < 3 || height < 3) return "a patch needs at least 3 x 3 control points";
  if (width % 2 == 0 || height % 2 == 0) {
    return "a patch's width and height must be odd (3 x 3 sub-patches sharing edges)";
  }
  // Both sizes are below 2^31 here, so the product cannot overflow an int64.
  if (width * height != control_points) {
    return "a patch's width x height differs from its number of control points";
  }
  return nullptr;
}

std::int64_t patch_triangle_count(std::int64_t width, std::int64_t height) {
  return ((width - 1) / 2) * ((height - 1) / 2) * 2 * kPatchLevel * kPatchLevel;
}

namespace {

// Quadratic Bernstein weights at t in [0, 1].
std::array<double, 3> bernstein(double t) {
  const double s = 1 - t;
  return {s * s, 2 * s * t, t * t};
}

}  // namespace

void tessellate_patch(std::span<const Eigen::Vector3f> control, int width, int height,
                      std::vector<Eigen::Vector3f>& vertices,
                      std::vector<std::array<std::uint32_t, 3>>& triangles) {
  assert(patch_size_problem(width, height, static_cast<std::int64_t>(control.size())) == nullptr);
  const int sub_u = (width - 1) / 2;
  const int sub_v = (height - 1) / 2;
  const int columns = sub_u * kPatchLevel + 1;  // grid samples along u
  const int rows = sub_v * kPatchLevel + 1;
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.reserve(vertices.size() + static_cast<std::size_t>(columns) * rows);
  for (int row = 0; row < rows; ++row) {
    // The sub-patch holding this sample row (the last row belongs to the last sub-patch).
    const int b = std::min(row / kPatchLevel, sub_v - 1);
    const auto wv = bernstein(static_cast<double>(row - b * kPatchLevel) / kPatchLevel);
    for (int column = 0; column < columns; ++column) {
      const int a = std::min(column / kPatchLevel, sub_u - 1);
      const auto wu = bernstein(static_cast<double>(column - a * kPatchLevel) / kPatchLevel);
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
          const auto index = static_cast<std::size_t>(2 * b + j) * width + (2 * a + i);
          p += (wv[j] * wu[i]) * control[index].cast<double>();
        }
      }
      vertices.push_back(p.cast<float>());
    }
  }
  triangles.reserve(triangles.size() + static_cast<std::size_t>(columns - 1) * (rows - 1) * 2);
  for (int row = 0; row + 1 < rows; ++row) {
    for (int column = 0; column + 1 < columns; ++column) {
      const std::uint32_t v00 = base + static_cast<std::uint32_t>(row * columns + column);
      const std::uint32_t v10 = v00 + 1;                                    // +u
      const std::uint32_t v01 = v00 + static_cast<std::uint32_t>(columns);  // +v
      const std::uint32_t v11 = v01 + 1;
      triangles.push_back({v00, v10, v01});
      triangles.push_back({v10, v11, v01});
    }
  }
}

}  // namespace sightline::camera::q3
