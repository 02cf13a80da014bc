// Meshes as levels through assimp: the branch of load_level (level.h) for every extension
// that is not a Quake III map (glTF 2.0 .gltf/.glb, .obj, .fbx, .dae, .ply and the rest
// assimp reads).
//
// Every triangle of every mesh of every node, with the node's full transform (its own and
// its ancestors') applied, then `transform` (scale, up). Points and lines are skipped;
// polygons are triangulated by assimp.
#pragma once

#include "sightline/domains/camera/level/level.h"

namespace sightline::camera {

// Throws csp::InputError naming the file for a missing or unreadable file, a format assimp
// cannot read (with assimp's own reason) and NaN or infinite vertices.
Level load_mesh_level(const LevelSpec& spec, const LevelTransform& transform);

}  // namespace sightline::camera
