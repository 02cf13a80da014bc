// Level: triangle-mesh geometry loaded from a file, solid for the camera (FORMATS.md, the
// scene's `level:` block).
//
// Two sources, chosen by the file's extension:
//  - Quake III arena maps (IBSP version 46), a `.bsp` or a map inside a `.pk3` (a zip):
//    read by q3_bsp.h (polygons, meshes and tessellated bezier patches of the solid
//    surfaces that are neither sky nor nodraw), with the map's brushes as a SolidVolume.
//  - Every other extension goes to assimp (mesh_import.h): glTF 2.0, OBJ, FBX, DAE, PLY ...
//    every triangle of every mesh, node transforms applied. No solid volume.
// Then `scale` and `up` (level_transform.h) map file units to the scene's metres, y up.
// Bad files throw csp::InputError naming the file (and, for a scene, the line of its
// `level:` block): missing, unknown map, truncated or corrupt, NaN vertices, no triangles.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/geometry/solid_volume.h"
#include "sightline/domains/camera/geometry/triangle_mesh.h"
#include "sightline/domains/camera/level/level_transform.h"

namespace sightline::camera {

struct LevelSpec {
  std::string file;  // path to open (already resolved against the scene file's folder)
  std::string map;   // a .pk3's map name ("oa_thor" or "maps/oa_thor.bsp"); empty: the only one
  // Absent: the format's default (1 and y; 0.03125 and z for .bsp and .pk3).
  std::optional<double> scale;
  std::optional<UpAxis> up;
  csp::SourceLocation where;  // the scene's `level:` block, for messages
};

// True for the extensions read as Quake III maps (.bsp, .pk3; any case).
bool is_quake3_level(const std::string& file);

struct Level {
  std::string file;    // as given in the spec
  std::string map;     // the map read from a .pk3 (empty otherwise)
  std::string format;  // for people: "Quake III BSP (IBSP 46)", "glTF 2.0 (assimp)" ...
  LevelTransform transform;
  TriangleMesh mesh;   // metres, y up
  std::shared_ptr<const SolidVolume> solid;  // null when the format has no solid volumes
  double load_seconds = 0;  // reading and converting, wall clock
};

// Loads a level. Throws csp::InputError for every bad input (see the header comment).
Level load_level(const LevelSpec& spec);

}  // namespace sightline::camera
