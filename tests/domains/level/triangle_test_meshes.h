// Meshes for the TriangleIndex tests: random triangle soups (with degenerate triangles), a
// closed box of 12 triangles, and a 100k-triangle procedural level (terrain and walls); and
// random query points in a region or on a mesh's triangles.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>

#include "sightline/domains/camera/geometry/triangle_mesh.h"

namespace sightline::camera::test_meshes {

using Eigen::Vector3d;

// n random triangles in the cube [-10, 10]^3 + offset, sides up to ~4 m; every 100th is
// degenerate (two equal corners, or three collinear), which must never be hit by a ray but
// still has a distance.
inline TriangleMesh random_soup(std::mt19937_64& rng, int n, const Vector3d& offset) {
  std::uniform_real_distribution<double> pos(-10, 10);
  std::uniform_real_distribution<double> spread(-2, 2);
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i) {
    const Vector3d c(pos(rng), pos(rng), pos(rng));
    Vector3d v[3];
    for (auto& x : v) x = c + Vector3d(spread(rng), spread(rng), spread(rng));
    if (i % 100 == 1) v[2] = v[1];
    if (i % 100 == 2) v[2] = v[0] + 0.5 * (v[1] - v[0]);
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const auto& x : v) mesh.vertices.push_back((x + offset).cast<float>());
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

// A closed box: 8 shared corners, 12 triangles, front faces outward.
inline TriangleMesh box_mesh(const Vector3d& lo, const Vector3d& hi) {
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k) {
    mesh.vertices.emplace_back(Vector3d((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                        (k & 4) ? hi.z() : lo.z())
                                   .cast<float>());
  }
  // Each face as a quad (corner bits) counter-clockwise seen from outside.
  const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5},   // -x, +x
                                     {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
                                     {0, 2, 3, 1}, {4, 5, 7, 6}};  // -z, +z
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

// A 100k-triangle level: a 224 x 224 heightfield over 160 m x 160 m (hills and ripples), and
// 40 walls and pillars (closed boxes) standing on it.
inline TriangleMesh procedural_level() {
  TriangleMesh mesh;
  const int n = 224;
  const double extent = 80;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = -extent + 2 * extent * i / (n - 1);
      const double z = -extent + 2 * extent * j / (n - 1);
      const double y = 3 * std::sin(x / 7) * std::cos(z / 11) + 0.5 * std::sin(x / 1.3 + z / 2.1) +
                       noise(rng);
      mesh.vertices.emplace_back(Vector3d(x, y, z).cast<float>());
    }
  }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(i * n + j); };
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      mesh.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  std::uniform_real_distribution<double> pos(-70, 70);
  std::uniform_real_distribution<double> size(0.3, 12);
  for (int k = 0; k < 40; ++k) {
    const Vector3d lo(pos(rng), -4, pos(rng));
    mesh.append(box_mesh(lo, lo + Vector3d(size(rng), 2 + size(rng) / 2, size(rng))));
  }
  return mesh;
}

// The largest absolute coordinate of the mesh (at least 1): the scale tolerances follow.
inline double scale_of(const TriangleMesh& mesh) {
  const Aabb b = mesh.bounds();
  return std::max({1.0, b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff()});
}

// A uniform random point of `region`.
inline Vector3d random_point_in(const Aabb& region, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  return Vector3d(region.min + region.size().cwiseProduct(Vector3d(unit(rng), unit(rng), unit(rng))));
}

// A uniform random point of a random triangle of `mesh` (exactly on it up to double rounding).
inline Vector3d random_point_on(const TriangleMesh& mesh, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  const auto i = static_cast<std::uint32_t>(rng() % mesh.size());
  const Vector3d a = mesh.vertex(i, 0), b = mesh.vertex(i, 1), c = mesh.vertex(i, 2);
  double u = unit(rng), v = unit(rng);
  if (u + v > 1) u = 1 - u, v = 1 - v;
  return Vector3d(a + u * (b - a) + v * (c - a));
}

}  // namespace sightline::camera::test_meshes
