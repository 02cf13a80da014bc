// The C API (sightline/sightline.h) over the C++ one: handles checked against the live ones,
// every exception turned into a status and this thread's message.
#include "sightline/sightline.h"

#include <cmath>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "api/conversions.h"
#include "sightline/camera.h"
#include "sightline/version.h"

struct sl_world {
  std::shared_ptr<const sightline::World> world;
};
struct sl_camera {
  std::unique_ptr<sightline::Camera> camera;
  // The people's states of the frame, converted; sized once, so a frame allocates nothing.
  std::vector<sightline::PersonState> people;
};

namespace {

thread_local std::string last_error;

sl_status fail(sl_status status, std::string message) {
  last_error = std::move(message);
  return status;
}

// The handles alive now, and their kind: a destroyed, foreign or null pointer is refused
// before it is dereferenced.
enum class Kind { kWorld, kCamera };
std::mutex handles_mutex;
std::unordered_map<const void*, Kind>& handles() {
  static std::unordered_map<const void*, Kind> live;
  return live;
}
void remember(const void* p, Kind k) {
  std::lock_guard lock(handles_mutex);
  handles()[p] = k;
}
bool forget(const void* p, Kind k) {
  std::lock_guard lock(handles_mutex);
  const auto it = handles().find(p);
  if (it == handles().end() || it->second != k) return false;
  handles().erase(it);
  return true;
}
bool alive(const void* p, Kind k) {
  if (p == nullptr) return false;
  std::lock_guard lock(handles_mutex);
  const auto it = handles().find(p);
  return it != handles().end() && it->second == k;
}

// A callback's error: the status is SL_ERROR_WORLD.
class WorldCallbackError : public sightline::Error {
 public:
  using sightline::Error::Error;
};

sightline::Vec3 from_c(const sl_vec3& v) { return {v.x, v.y, v.z}; }
sl_vec3 to_c(const sightline::Vec3& v) { return {v.x, v.y, v.z}; }

class CallbackWorld final : public sightline::World {
 public:
  explicit CallbackWorld(const sl_world_callbacks& c) : c_(c) {}

  std::optional<sightline::WorldHit> first_hit(const sightline::Vec3& a, const sightline::Vec3& b,
                                               double t) const override {
    const sl_vec3 ca = to_c(a), cb = to_c(b);
    int hit = 0;
    double fraction = 0;
    sl_vec3 normal{0, 0, 0};
    check(c_.first_hit(c_.user, &ca, &cb, t, &hit, &fraction, &normal), "first_hit");
    if (!hit) return std::nullopt;
    if (!std::isfinite(fraction) || !std::isfinite(normal.x) || !std::isfinite(normal.y) ||
        !std::isfinite(normal.z)) {
      throw WorldCallbackError("world callback first_hit reported a fraction or normal that is not finite");
    }
    return sightline::WorldHit{fraction, from_c(normal)};
  }
  double clearance(const sightline::Vec3& p, double limit, double t) const override {
    const sl_vec3 cp = to_c(p);
    double d = limit;
    check(c_.clearance(c_.user, &cp, limit, t, &d), "clearance");
    if (std::isnan(d)) throw WorldCallbackError("world callback clearance reported NaN");
    return std::min(d, limit);
  }
  bool line_of_sight(const sightline::Vec3& a, const sightline::Vec3& b, double t) const override {
    if (!c_.line_of_sight) return World::line_of_sight(a, b, t);
    const sl_vec3 ca = to_c(a), cb = to_c(b);
    int clear = 0;
    check(c_.line_of_sight(c_.user, &ca, &cb, t, &clear), "line_of_sight");
    return clear != 0;
  }

 private:
  static void check(int code, const char* which) {
    if (code != 0) {
      throw WorldCallbackError(std::string("world callback ") + which + " reported error " +
                               std::to_string(code));
    }
  }
  sl_world_callbacks c_;
};

// Runs `body`, turning what it throws into a status and this thread's message.
template <class Body>
sl_status guarded(Body&& body) {
  try {
    body();
    return SL_OK;
  } catch (const WorldCallbackError& e) {
    return fail(SL_ERROR_WORLD, e.what());
  } catch (const sightline::Error& e) {
    // A world error inside a camera's frame arrives as its message.
    const bool from_world = std::string(e.what()).find("world callback") != std::string::npos;
    return fail(from_world ? SL_ERROR_WORLD : SL_ERROR_INVALID_ARGUMENT, e.what());
  } catch (const std::bad_alloc&) {
    return fail(SL_ERROR_OUT_OF_MEMORY, "out of memory");
  } catch (const std::exception& e) {
    return fail(SL_ERROR_INTERNAL, e.what());
  } catch (...) {
    return fail(SL_ERROR_INTERNAL, "unknown error");
  }
}

bool finite(const sl_vec3& v) { return sightline::finite(from_c(v)); }

sl_status new_world(std::shared_ptr<const sightline::World> world, sl_world** out) {
  auto* w = new sl_world{std::move(world)};
  remember(w, Kind::kWorld);
  *out = w;
  return SL_OK;
}

// Converts into `v` (resized; no allocation once it has the capacity).
void people_of(const sl_person_state* people, std::size_t count,
               std::vector<sightline::PersonState>& v) {
  v.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    v[i] = {from_c(people[i].position), from_c(people[i].velocity), people[i].yaw};
  }
}

}  // namespace

extern "C" {

sl_status sl_world_create_geometry(const double* vertices, size_t vertex_count,
                                   const uint32_t* indices, size_t triangle_count,
                                   const double* boxes, size_t box_count, sl_world** out) {
  if (out == nullptr) return fail(SL_ERROR_INVALID_ARGUMENT, "sl_world_create_geometry: out is NULL");
  if ((vertex_count && !vertices) || (triangle_count && !indices) || (box_count && !boxes)) {
    return fail(SL_ERROR_INVALID_ARGUMENT,
                "sl_world_create_geometry: a count is non-zero but its array is NULL");
  }
  return guarded([&] {
    sightline::WorldGeometry g;
    g.vertices.resize(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) {
      g.vertices[i] = {vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]};
    }
    g.triangle_indices.assign(indices, indices + 3 * triangle_count);
    g.boxes.resize(box_count);
    for (size_t i = 0; i < box_count; ++i) {
      const double* b = boxes + 6 * i;
      g.boxes[i] = {{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
    }
    new_world(sightline::make_geometry_world(g), out);
  });
}

sl_status sl_world_create_callbacks(const sl_world_callbacks* callbacks, sl_world** out) {
  if (out == nullptr) return fail(SL_ERROR_INVALID_ARGUMENT, "sl_world_create_callbacks: out is NULL");
  if (callbacks == nullptr || callbacks->first_hit == nullptr || callbacks->clearance == nullptr) {
    return fail(SL_ERROR_INVALID_ARGUMENT,
                "sl_world_create_callbacks: first_hit and clearance callbacks are required");
  }
  return guarded([&] { new_world(std::make_shared<CallbackWorld>(*callbacks), out); });
}

sl_status sl_world_line_of_sight(const sl_world* world, sl_vec3 a, sl_vec3 b, double t, int* clear) {
  if (!alive(world, Kind::kWorld)) return fail(SL_ERROR_INVALID_HANDLE, "sl_world_line_of_sight: not a live world");
  if (clear == nullptr || !finite(a) || !finite(b) || !std::isfinite(t)) {
    return fail(SL_ERROR_INVALID_ARGUMENT, "sl_world_line_of_sight: NULL output or a value that is not finite");
  }
  return guarded([&] { *clear = world->world->line_of_sight(from_c(a), from_c(b), t) ? 1 : 0; });
}

sl_status sl_world_clearance(const sl_world* world, sl_vec3 p, double limit, double t, double* distance) {
  if (!alive(world, Kind::kWorld)) return fail(SL_ERROR_INVALID_HANDLE, "sl_world_clearance: not a live world");
  if (distance == nullptr || !finite(p) || std::isnan(limit) || !std::isfinite(t)) {
    return fail(SL_ERROR_INVALID_ARGUMENT, "sl_world_clearance: NULL output or a value that is not finite");
  }
  return guarded([&] { *distance = world->world->clearance(from_c(p), limit, t); });
}

void sl_world_destroy(sl_world* world) {
  if (world != nullptr && forget(world, Kind::kWorld)) delete world;
}

void sl_camera_settings_default(sl_camera_settings* settings) {
  if (settings == nullptr) return;
  *settings = sl_camera_settings{};
  settings->seed = 1;
  settings->people_count = 1;
  settings->frame_rate = 60;
}

sl_status sl_camera_create(sl_world* world, const sl_camera_settings* settings,
                           const sl_person_state* people, size_t count, double t, sl_camera** out) {
  if (!alive(world, Kind::kWorld)) return fail(SL_ERROR_INVALID_HANDLE, "sl_camera_create: not a live world");
  if (settings == nullptr || out == nullptr || people == nullptr) {
    return fail(SL_ERROR_INVALID_ARGUMENT, "sl_camera_create: settings, people and out must not be NULL");
  }
  return guarded([&] {
    sightline::CameraSettings s;
    if (settings->profile) s.profile = settings->profile;
    if (settings->solver) s.solver = settings->solver;
    s.seed = settings->seed;
    s.people.assign(settings->people_count, sightline::PersonShape{});
    if (settings->people) {
      for (size_t i = 0; i < settings->people_count; ++i) {
        s.people[i] = {from_c(settings->people[i].size), settings->people[i].look_at_height};
      }
    }
    s.has_start = settings->has_start != 0;
    s.start = from_c(settings->start);
    s.frame_rate = settings->frame_rate;
    std::vector<sightline::PersonState> states;
    people_of(people, count, states);
    auto camera = std::make_unique<sightline::Camera>(world->world, s, states, t);
    auto* c = new sl_camera{std::move(camera), std::move(states)};
    remember(c, Kind::kCamera);
    *out = c;
  });
}

namespace {

// One frame of a live camera (the handle checked by the caller), at the game's time t when
// given.
sl_status update_camera(const char* call, sl_camera* camera, const sl_person_state* people,
                        size_t count, double dt, std::optional<double> t, sl_pose* out) {
  if (people == nullptr || out == nullptr) {
    return fail(SL_ERROR_INVALID_ARGUMENT, std::string(call) + ": people and out must not be NULL");
  }
  return guarded([&] {
    people_of(people, count, camera->people);
    const sightline::CameraPose& p = t ? camera->camera->update(camera->people, dt, *t)
                                       : camera->camera->update(camera->people, dt);
    out->position = to_c(p.position);
    out->target = to_c(p.target);
    out->up = to_c(p.up);
    out->cut = p.cut ? 1 : 0;
    out->cut_reason = static_cast<sl_cut_reason>(p.cut_reason);
    out->look_at_visible = p.look_at_visible ? 1 : 0;
    out->cost = p.cost;
    out->solve_seconds = p.solve_seconds;
  });
}

}  // namespace

sl_status sl_camera_update(sl_camera* camera, const sl_person_state* people, size_t count, double dt,
                           sl_pose* out) {
  if (!alive(camera, Kind::kCamera)) return fail(SL_ERROR_INVALID_HANDLE, "sl_camera_update: not a live camera");
  return update_camera("sl_camera_update", camera, people, count, dt, std::nullopt, out);
}

sl_status sl_camera_update_at(sl_camera* camera, const sl_person_state* people, size_t count,
                              double dt, double t, sl_pose* out) {
  if (!alive(camera, Kind::kCamera)) return fail(SL_ERROR_INVALID_HANDLE, "sl_camera_update_at: not a live camera");
  return update_camera("sl_camera_update_at", camera, people, count, dt, t, out);
}

sl_status sl_camera_reset(sl_camera* camera, sl_vec3 position) {
  if (!alive(camera, Kind::kCamera)) return fail(SL_ERROR_INVALID_HANDLE, "sl_camera_reset: not a live camera");
  return guarded([&] { camera->camera->reset(from_c(position)); });
}

void sl_camera_destroy(sl_camera* camera) {
  if (camera != nullptr && forget(camera, Kind::kCamera)) delete camera;
}

const char* sl_last_error(void) { return last_error.c_str(); }

const char* sl_status_string(sl_status status) {
  switch (status) {
    case SL_OK: return "ok";
    case SL_ERROR_INVALID_HANDLE: return "invalid handle";
    case SL_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case SL_ERROR_WORLD: return "world error";
    case SL_ERROR_OUT_OF_MEMORY: return "out of memory";
    case SL_ERROR_INTERNAL: return "internal error";
  }
  return "unknown status";
}

const char* sl_version(void) { return SIGHTLINE_VERSION_STRING; }

}  // extern "C"
