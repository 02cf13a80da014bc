// NavigationMesh: where a person can walk on a level, and the shortest routes between two
// points there, built with Recast and planned with Detour (Debian's librecast-dev).
//
// One Recast tile covers the whole level: voxelise the triangles at the person's size
// (WalkOptions), keep the floors they can stand on and step between, erode them by the
// person's radius, cut them into convex polygons and hand those to Detour. Of the
// polygons, only the largest connected region (by area, flooding over Detour's polygon
// links) is kept for walking: a level's other walkable patches (roof tops, ledges, the
// insides of pillars) are unreachable from it, and a walk must never need a jump. The
// Recast and Detour types stay in the .cc file.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "sightline/domains/camera/geometry/triangle_mesh.h"
#include "sightline/experiments/sources/level_walk.h"

namespace sightline::experiments {

class NavigationMesh {
 public:
  // A point of a route: where it is on the navigation mesh (metres, y up; the height is
  // the mesh's approximation of the floor) and whether the route turns there.
  struct RoutePoint {
    Eigen::Vector3d position;
    bool corner = false;  // true at the start, the end and where the direction changes
  };

  // Builds the mesh; `anchors` (metres, y up, may be empty) choose the region walked.
  // Throws WalkError when the level has no walkable region (the message
  // says how big the level is and what the person's size is) or Recast fails.
  NavigationMesh(const camera::TriangleMesh& mesh, const WalkOptions& options,
                 const std::vector<Eigen::Vector3d>& anchors = {});
  ~NavigationMesh();
  NavigationMesh(const NavigationMesh&) = delete;
  NavigationMesh& operator=(const NavigationMesh&) = delete;

  const NavigationMeshStats& stats() const { return stats_; }

  // A point drawn uniformly (by area, seen from above) on the largest region.
  Eigen::Vector3d random_point(std::mt19937_64& rng) const;
  // The shortest route from `from` to `to` (both on the largest region) as straight lines:
  // its corners, and between them every point where it crosses into another polygon (so
  // the heights along a straight line follow the floor's steps). Empty when no complete
  // route exists.
  std::vector<RoutePoint> route(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  NavigationMeshStats stats_;
};

// Length of a route, along its straight lines (metres).
double route_length(const std::vector<NavigationMesh::RoutePoint>& route);

}  // namespace sightline::experiments
