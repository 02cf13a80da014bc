// The public API's per-frame cost on a real Quake III walk (oa_thor-walk1, 66,906 triangles):
// the C API with the world answered by callbacks over the embedding example's own BVH
// (examples/embedding/c/bvh.h, what a game's physics would be) against the C++ API with
// sightline's own index (make_geometry_world: Embree). Both run the default camera
// (anticipating, occlusion-octree) over the whole walk, one update per frame, and report the
// per-frame wall and CPU time (p50_us, p99_us, cpu_p99_us) and the frames whose look-at point
// the camera itself saw hidden. docs/BENCHMARKS.md, "Public API".
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <memory>

#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/metrics.h"
#include "sightline/camera.h"
#include "sightline/sightline.h"

extern "C" {
#include "bvh.h"
}

namespace {

const char* kWalk = SIGHTLINE_SOURCE_DIR "/experiments/scenes/levels/oa_thor-walk1.yaml";

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Walk {
  sightline::camera::Scene scene;
  std::vector<double> vertices;
  std::vector<uint32_t> indices;
};

const Walk* walk() {
  static std::unique_ptr<Walk> w = [] () -> std::unique_ptr<Walk> {
    try {
      auto out = std::make_unique<Walk>(Walk{sightline::camera::read_scene_file(kWalk), {}, {}});
      const auto& mesh = out->scene.level()->mesh;
      for (const auto& v : mesh.vertices) out->vertices.insert(out->vertices.end(), {v.x(), v.y(), v.z()});
      for (const auto& t : mesh.triangles) out->indices.insert(out->indices.end(), t.begin(), t.end());
      return out;
    } catch (const std::exception&) {
      return nullptr;  // the map is not installed
    }
  }();
  return w.get();
}

sl_person_state c_state(const sightline::camera::CharacterState& s) {
  return sl_person_state{{s.position.x(), s.position.y(), s.position.z()},
                         {s.velocity.x(), s.velocity.y(), s.velocity.z()}, s.yaw};
}

// Runs the walk through `update(state, dt) -> look_at_visible`, timing each frame.
template <class Update>
void run_walk(benchmark::State& state, const Walk& w, Update&& update) {
  std::vector<double> wall_us, cpu_us;
  int hidden = 0;
  const std::size_t frames = w.scene.frame_count();
  double previous = w.scene.frame_time(0) - 1.0 / w.scene.frame_rate();
  for (std::size_t i = 0; i < frames; ++i) {
    const double t = w.scene.frame_time(i);
    const auto character = w.scene.character_at(t);
    const double dt = t - previous > 0 ? t - previous : 1.0 / w.scene.frame_rate();
    previous = t;
    const auto wall0 = std::chrono::steady_clock::now();
    const double cpu0 = cpu_now();
    if (!update(character, dt)) ++hidden;
    cpu_us.push_back(1e6 * (cpu_now() - cpu0));
    wall_us.push_back(1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
  }
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["p50_us"] = sightline::experiments::percentile(wall_us, 50);
  state.counters["p99_us"] = sightline::experiments::percentile(wall_us, 99);
  state.counters["cpu_p50_us"] = sightline::experiments::percentile(cpu_us, 50);
  state.counters["cpu_p99_us"] = sightline::experiments::percentile(cpu_us, 99);
  state.counters["camera_saw_hidden"] = hidden;
}

struct CallbackWorld {
  bvh index{};
};

int first_hit(void* user, const sl_vec3* a, const sl_vec3* b, double, int* hit, double* fraction,
              sl_vec3* normal) {
  const double pa[3] = {a->x, a->y, a->z}, pb[3] = {b->x, b->y, b->z};
  bvh_hit h;
  *hit = bvh_first_hit(&static_cast<CallbackWorld*>(user)->index, pa, pb, &h);
  if (*hit) {
    *fraction = h.fraction;
    *normal = sl_vec3{h.normal[0], h.normal[1], h.normal[2]};
  }
  return 0;
}
int line_of_sight(void* user, const sl_vec3* a, const sl_vec3* b, double, int* clear) {
  const double pa[3] = {a->x, a->y, a->z}, pb[3] = {b->x, b->y, b->z};
  *clear = bvh_line_of_sight(&static_cast<CallbackWorld*>(user)->index, pa, pb);
  return 0;
}
int clearance(void* user, const sl_vec3* p, double limit, double, double* distance) {
  const double pp[3] = {p->x, p->y, p->z};
  *distance = bvh_clearance(&static_cast<CallbackWorld*>(user)->index, pp, limit);
  return 0;
}

void BM_CApiCallbacks(benchmark::State& state) {
  const Walk* w = walk();
  if (!w) return state.SkipWithError("oa_thor is not installed (openarena-088-data)");
  CallbackWorld game;
  bvh_build(&game.index, w->vertices.data(), w->indices.data(), w->indices.size() / 3);
  for (auto _ : state) {
    sl_world_callbacks callbacks{first_hit, clearance, line_of_sight, &game};
    sl_world* world = nullptr;
    sl_world_create_callbacks(&callbacks, &world);
    sl_camera_settings settings;
    sl_camera_settings_default(&settings);
    const double t0 = w->scene.frame_time(0);
    const sl_person_state first = c_state(w->scene.character_at(t0));
    sl_camera* camera = nullptr;
    if (sl_camera_create(world, &settings, &first, 1, t0, &camera) != SL_OK) {
      return state.SkipWithError(sl_last_error());
    }
    run_walk(state, *w, [&](const sightline::camera::CharacterState& s, double dt) {
      const sl_person_state p = c_state(s);
      sl_pose pose;
      sl_camera_update(camera, &p, 1, dt, &pose);
      return pose.look_at_visible != 0;
    });
    sl_camera_destroy(camera);
    sl_world_destroy(world);
  }
  bvh_free(&game.index);
}

void BM_CppApiOwnIndex(benchmark::State& state) {
  const Walk* w = walk();
  if (!w) return state.SkipWithError("oa_thor is not installed (openarena-088-data)");
  sightline::WorldGeometry g;
  for (std::size_t i = 0; i < w->vertices.size(); i += 3) {
    g.vertices.push_back({w->vertices[i], w->vertices[i + 1], w->vertices[i + 2]});
  }
  g.triangle_indices.assign(w->indices.begin(), w->indices.end());
  const auto world = sightline::make_geometry_world(g);
  for (auto _ : state) {
    const double t0 = w->scene.frame_time(0);
    const auto s0 = w->scene.character_at(t0);
    std::vector<sightline::PersonState> people{{{s0.position.x(), s0.position.y(), s0.position.z()},
                                                {s0.velocity.x(), s0.velocity.y(), s0.velocity.z()},
                                                s0.yaw}};
    sightline::Camera camera(world, sightline::CameraSettings{}, people, t0);
    run_walk(state, *w, [&](const sightline::camera::CharacterState& s, double dt) {
      people[0] = {{s.position.x(), s.position.y(), s.position.z()},
                   {s.velocity.x(), s.velocity.y(), s.velocity.z()}, s.yaw};
      return camera.update(people, dt).look_at_visible;
    });
  }
}

BENCHMARK(BM_CApiCallbacks)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CppApiOwnIndex)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
