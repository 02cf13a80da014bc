// TriangleMesh: a level's solid surfaces as a plain indexed triangle list.
//
// Every level source (Quake III maps, meshes read through assimp) is turned into this one
// shape, in the scene's frame (metres, y up) once loaded, so the geometry queries
// (triangle_index.h), the walk generator and the report know nothing of file formats.
// Vertices are floats: that is what Embree indexes, and a float resolves 1e-5 m over a
// 100 m level, far finer than any camera decision.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "sightline/domains/camera/geometry/aabb.h"

namespace sightline::camera {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  // Indices into `vertices`, counter-clockwise seen from the front (the side the normal
  // (v1 - v0) x (v2 - v0) points to). Triangles have no inside: both sides block sight.
  std::vector<std::array<std::uint32_t, 3>> triangles;

  std::size_t size() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }
  Eigen::Vector3d vertex(std::uint32_t triangle, int corner) const {
    return vertices[triangles[triangle][corner]].cast<double>();
  }
  // Bounds of the vertices used by triangles (Aabb::empty() when there are none).
  Aabb bounds() const {
    Aabb b = Aabb::empty();
    for (const auto& t : triangles) {
      for (std::uint32_t i : t) b.merge(vertices[i].cast<double>().eval());
    }
    return b;
  }
  // Appends another mesh's triangles (indices shifted).
  void append(const TriangleMesh& other) {
    const auto offset = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (auto t : other.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
};

}  // namespace sightline::camera
