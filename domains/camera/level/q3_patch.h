// Quake III bezier patches as triangles.
//
// A patch face (type 2) is a grid of width x height control points (both odd, >= 3, stored
// row by row, width varying fastest) made of biquadratic bezier sub-patches: sub-patch (a, b)
// takes the 3 x 3 control points whose corners are (2a, 2b) and (2a + 2, 2b + 2), so
// neighbours share an edge of control points. Each sub-patch is sampled at a fixed level of
// kPatchLevel segments per side on one grid shared across the patch (no cracks at the seams),
// and each grid cell becomes two triangles.
//
// Why a fixed level: the camera needs occluders within a few centimetres, not a smooth
// silhouette. With 8 segments a quarter circle (the tightest curve Quake III patches usually
// bend per sub-patch) deviates from its chords by r (1 - cos(45/8 deg)) = 0.5% of its radius:
// 0.6 units (2 cm) on a 128-unit (4 m) arch. And a fixed level makes the triangle count a
// simple function of the patch size, which tests check independently.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sightline::camera::q3 {

inline constexpr int kPatchLevel = 8;  // segments per side of one 3 x 3 sub-patch

// Why a width x height patch of `control_points` points cannot be tessellated, or nullptr
// when it can (both sizes odd and >= 3, width * height == control_points).
const char* patch_size_problem(std::int64_t width, std::int64_t height,
                               std::int64_t control_points);

// Triangles a valid width x height patch becomes:
// ((width - 1) / 2) * ((height - 1) / 2) sub-patches of 2 kPatchLevel^2 triangles.
std::int64_t patch_triangle_count(std::int64_t width, std::int64_t height);

// Appends the tessellation of a valid patch (patch_size_problem() == nullptr): its grid
// vertices to `vertices` and its triangles, indices into `vertices`, to `triangles`. The
// triangles are counter-clockwise seen from the side (d/du) x (d/dv) points to, u along the
// width and v along the height, which is the front of a Quake III patch.
void tessellate_patch(std::span<const Eigen::Vector3f> control, int width, int height,
                      std::vector<Eigen::Vector3f>& vertices,
                      std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace sightline::camera::q3
