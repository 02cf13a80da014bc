// scene_fuzz's load_level: reads no file. Level files are not what scene_fuzz fuzzes (Quake
// III maps have q3_bsp_fuzz, meshes go to assimp), and reading one per input would make a
// run slow and depend on the machine (the shipped level scenes name 8 MB .pk3 files). The
// `level:` block is still read by the real scene reader (fields, path, map, scale, up); only
// the load is replaced, by a level of one triangle far below any scene, so that the scene's
// reading goes on past it as it would with a real level.
#include "sightline/domains/camera/level/level.h"

namespace sightline::camera {

Level load_level(const LevelSpec& spec) {
  Level level;
  level.file = spec.file;
  level.map = spec.map;
  level.format = "fuzz stub (no file read)";
  level.mesh.vertices = {{0, -1000, 0}, {1, -1000, 0}, {0, -1000, 1}};
  level.mesh.triangles = {{0, 2, 1}};
  return level;
}

}  // namespace sightline::camera
