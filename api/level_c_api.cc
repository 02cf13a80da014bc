// The levels component's C API (sightline/level.h): load_level's triangles as flat arrays.
#include "sightline/level.h"

#include <exception>
#include <string>
#include <vector>

#include "sightline/domains/camera/level/level.h"

struct sl_level {
  std::vector<double> vertices;
  std::vector<uint32_t> indices;
};

namespace {
thread_local std::string last_error;
}

extern "C" {

sl_level* sl_level_load(const char* file, const char* map) {
  if (file == nullptr) {
    last_error = "sl_level_load: file is NULL";
    return nullptr;
  }
  try {
    sightline::camera::LevelSpec spec;
    spec.file = file;
    if (map != nullptr) spec.map = map;
    const sightline::camera::Level level = sightline::camera::load_level(spec);
    auto* out = new sl_level;
    out->vertices.reserve(3 * level.mesh.vertices.size());
    for (const auto& v : level.mesh.vertices) {
      out->vertices.insert(out->vertices.end(), {v.x(), v.y(), v.z()});
    }
    out->indices.reserve(3 * level.mesh.triangles.size());
    for (const auto& t : level.mesh.triangles) out->indices.insert(out->indices.end(), t.begin(), t.end());
    last_error.clear();
    return out;
  } catch (const std::exception& e) {
    last_error = e.what();
    return nullptr;
  }
}

void sl_level_triangles(const sl_level* level, const double** vertices, size_t* vertex_count,
                        const uint32_t** indices, size_t* triangle_count) {
  if (level == nullptr) return;
  if (vertices) *vertices = level->vertices.data();
  if (vertex_count) *vertex_count = level->vertices.size() / 3;
  if (indices) *indices = level->indices.data();
  if (triangle_count) *triangle_count = level->indices.size() / 3;
}

void sl_level_destroy(sl_level* level) { delete level; }

const char* sl_level_last_error(void) { return last_error.c_str(); }

}  // extern "C"
