/* main.c: sightline's chase camera embedded in a C program, over the program's own world.
 *
 * A game that embeds sightline keeps its own physics: the camera asks the game's world its
 * questions (what does this segment hit first, is this sight line clear, how far is the
 * nearest surface) through three callbacks. This example plays the game: it loads a Quake III
 * level's triangles, indexes them with its own bounding-volume hierarchy (bvh.h), replays a
 * recorded walk (walk.h) and films it at 60 frames per second, writing one CSV row per frame
 * and a summary of cuts, visibility and time per frame.
 *
 *   usage: sightline_c_example [walk.csv] [trace_out.csv]
 *   defaults: oa_thor-walk1.csv and trace.csv in the current folder (the build copies the
 *   walk next to the executable);
 *   SIGHTLINE_EXAMPLE_PK3 and SIGHTLINE_EXAMPLE_MAP choose another level.
 *   Exit: 0 done, 1 an error, 77 the level's .pk3 is not installed (a skip).
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bvh.h"
#include "sightline/level.h"
#include "sightline/sightline.h"
#include "walk.h"

#define FRAME_RATE 60.0
#define DEFAULT_PK3 "/usr/share/games/openarena/baseoa/pak6-patch088.pk3"
#define DEFAULT_MAP "oa_thor"
#define EXIT_SKIP 77

/* The callbacks' user data: the index, and how often the camera asked it (one camera on one
 * thread here, so plain counters do). */
typedef struct game_world {
  bvh index;
  unsigned long first_hits, lines_of_sight, clearances;
} game_world;

static void to_array(const sl_vec3* v, double out[3]) {
  out[0] = v->x, out[1] = v->y, out[2] = v->z;
}

/* --- the world callbacks: the level is static, so the time t is not needed --- */

static int first_hit(void* user, const sl_vec3* a, const sl_vec3* b, double t, int* hit,
                     double* fraction, sl_vec3* normal) {
  game_world* world = user;
  double pa[3], pb[3];
  bvh_hit h;
  (void)t;
  ++world->first_hits;
  to_array(a, pa);
  to_array(b, pb);
  *hit = bvh_first_hit(&world->index, pa, pb, &h);
  if (*hit) {
    *fraction = h.fraction;
    normal->x = h.normal[0], normal->y = h.normal[1], normal->z = h.normal[2];
  }
  return 0;
}

static int line_of_sight(void* user, const sl_vec3* a, const sl_vec3* b, double t, int* clear) {
  game_world* world = user;
  double pa[3], pb[3];
  (void)t;
  ++world->lines_of_sight;
  to_array(a, pa);
  to_array(b, pb);
  *clear = bvh_line_of_sight(&world->index, pa, pb);
  return 0;
}

static int clearance(void* user, const sl_vec3* p, double limit, double t, double* distance) {
  game_world* world = user;
  double pp[3];
  (void)t;
  ++world->clearances;
  to_array(p, pp);
  *distance = bvh_clearance(&world->index, pp, limit);
  return 0;
}

/* --- small helpers --- */

static double now_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) return 0; /* no clock: timings read 0 */
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char* env_or(const char* name, const char* fallback) {
  const char* value = getenv(name);
  return value && value[0] ? value : fallback;
}

static int file_exists(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) return 0;
  fclose(f);
  return 1;
}

static int sightline_failed(const char* call, sl_status status) {
  fprintf(stderr, "%s: %s: %s\n", call, sl_status_string(status), sl_last_error());
  return 1;
}

static int compare_doubles(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

/* The p-th quantile (nearest rank) of n sorted values. */
static double quantile(const double* sorted, size_t n, double p) {
  size_t rank = (size_t)ceil(p * (double)n);
  return sorted[rank > 0 ? rank - 1 : 0];
}

static sl_person_state person_at(const walk* w, double t) {
  const walk_state s = walk_state_at(w, t);
  sl_person_state p;
  p.position.x = s.position[0], p.position.y = s.position[1], p.position.z = s.position[2];
  p.velocity.x = s.velocity[0], p.velocity.y = s.velocity[1], p.velocity.z = s.velocity[2];
  p.yaw = s.yaw;
  return p;
}

/* --- the run --- */

typedef struct run_totals {
  size_t frames, cuts, hidden;
  double* update_us; /* wall time of each sl_camera_update, microseconds */
} run_totals;

static int write_row(FILE* trace, size_t frame, double t, const sl_person_state* c,
                     const sl_pose* pose) {
  return fprintf(trace, "%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%.6g,%.1f\n",
                 frame, t, c->position.x, c->position.y, c->position.z, c->yaw, pose->position.x,
                 pose->position.y, pose->position.z, pose->target.x, pose->target.y, pose->target.z,
                 pose->cut ? 1 : 0, pose->cost, pose->solve_seconds * 1e6) >= 0;
}

/* Films the walk: one camera update and one trace row per frame. Returns 0 or 1. */
static int film(sl_camera* camera, const walk* w, FILE* trace, run_totals* totals) {
  double previous_t = 0;
  for (size_t k = 0; k < totals->frames; ++k) {
    const double t = walk_frame_time(w, k, FRAME_RATE);
    const sl_person_state person = person_at(w, t);
    /* Frame 0 is an update too: sl_camera_create places the camera but returns no pose (and
     * the C API has no getter), so the camera's first frame is an update with the first state
     * and a nominal dt of one frame, as sightline's own experiment runner does. */
    const double dt = k == 0 ? 1.0 / FRAME_RATE : t - previous_t;
    sl_pose pose;
    const double start = now_seconds();
    const sl_status status = sl_camera_update(camera, &person, 1, dt, &pose);
    totals->update_us[k] = (now_seconds() - start) * 1e6;
    if (status != SL_OK) return sightline_failed("sl_camera_update", status);
    if (pose.cut) ++totals->cuts;
    if (!pose.look_at_visible) ++totals->hidden;
    if (!write_row(trace, k, t, &person, &pose)) {
      fprintf(stderr, "cannot write the trace\n");
      return 1;
    }
    previous_t = t;
  }
  return 0;
}

/* Creates the camera at the walk's first frame and films the walk. Returns 0 or 1. */
static int film_walk(game_world* world, sl_world* sl, const walk* w, FILE* trace,
                     run_totals* totals) {
  sl_camera_settings settings;
  sl_camera_settings_default(&settings); /* the "anticipating" profile, one default person */
  const double t0 = walk_frame_time(w, 0, FRAME_RATE);
  const sl_person_state first = person_at(w, t0);
  sl_camera* camera = NULL;
  const sl_status status = sl_camera_create(sl, &settings, &first, 1, t0, &camera);
  if (status != SL_OK) return sightline_failed("sl_camera_create", status);
  world->first_hits = world->lines_of_sight = world->clearances = 0; /* count updates only */
  int failed = fprintf(trace,
                       "frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,"
                       "target_x,target_y,target_z,cut,cost,solve_us\n") < 0;
  if (failed) {
    fprintf(stderr, "cannot write the trace\n");
  } else {
    failed = film(camera, w, trace, totals);
  }
  sl_camera_destroy(camera);
  return failed;
}

static void print_summary(const game_world* world, const walk* w, run_totals* totals) {
  const double n = (double)totals->frames;
  qsort(totals->update_us, totals->frames, sizeof *totals->update_us, compare_doubles);
  printf("frames: %zu over %.1f s (%zu keyframes)\n", totals->frames,
         w->keys[w->count - 1].t - w->keys[0].t, w->count);
  printf("cuts: %zu\n", totals->cuts);
  printf("frames with look_at_visible = 0 (the camera's own flag): %zu\n", totals->hidden);
  printf("update time per frame: median %.1f us, p99 %.1f us\n",
         quantile(totals->update_us, totals->frames, 0.5),
         quantile(totals->update_us, totals->frames, 0.99));
  printf("world queries per frame: %.1f line_of_sight, %.1f first_hit, %.1f clearance\n",
         (double)world->lines_of_sight / n, (double)world->first_hits / n,
         (double)world->clearances / n);
}

/* Films the walk into the trace file at `trace_path` and prints the summary. Returns 0 or 1. */
static int run(game_world* world, sl_world* sl, const walk* w, const char* trace_path) {
  run_totals totals = {walk_frame_count(w, FRAME_RATE), 0, 0, NULL};
  totals.update_us = malloc(totals.frames * sizeof *totals.update_us);
  FILE* trace = fopen(trace_path, "w");
  int failed = 1;
  if (!totals.update_us) {
    fprintf(stderr, "out of memory\n");
  } else if (!trace) {
    fprintf(stderr, "%s: cannot create the trace file\n", trace_path);
  } else {
    failed = film_walk(world, sl, w, trace, &totals);
  }
  if (trace && fclose(trace) != 0 && !failed) {
    fprintf(stderr, "%s: cannot write the trace file\n", trace_path);
    failed = 1;
  }
  if (!failed) {
    print_summary(world, w, &totals);
    printf("trace: %s\n", trace_path);
  }
  free(totals.update_us);
  return failed;
}

/* Loads the level and indexes its triangles into world->index. Returns 0 or 1. */
static int load_world(const char* pk3, const char* map, game_world* world) {
  sl_level* level = sl_level_load(pk3, map);
  if (!level) {
    fprintf(stderr, "sl_level_load: %s\n", sl_level_last_error());
    return 1;
  }
  const double* vertices;
  const uint32_t* indices;
  size_t vertex_count, triangle_count;
  sl_level_triangles(level, &vertices, &vertex_count, &indices, &triangle_count);
  const double start = now_seconds();
  const int built = bvh_build(&world->index, vertices, indices, triangle_count);
  const double seconds = now_seconds() - start;
  sl_level_destroy(level); /* the index keeps its own copy of the triangles */
  if (built != 0) {
    fprintf(stderr, "out of memory building the index\n");
    return 1;
  }
  printf("map %s in %s: %zu triangles, %zu vertices\n", map, pk3, triangle_count, vertex_count);
  printf("own BVH: %zu triangles, %zu nodes, built in %.1f ms\n", world->index.triangle_count,
         world->index.node_count, seconds * 1e3);
  return 0;
}

int main(int argc, char** argv) {
  const char* walk_path = argc > 1 ? argv[1] : "oa_thor-walk1.csv";
  const char* trace_path = argc > 2 ? argv[2] : "trace.csv";
  const char* pk3 = env_or("SIGHTLINE_EXAMPLE_PK3", DEFAULT_PK3);
  const char* map = env_or("SIGHTLINE_EXAMPLE_MAP", DEFAULT_MAP);
  if (argc > 3) {
    fprintf(stderr, "usage: %s [walk.csv] [trace_out.csv]\n", argv[0]);
    return 1;
  }
  if (!file_exists(pk3)) {
    printf("skipped: %s is not installed (OpenArena's data; or set SIGHTLINE_EXAMPLE_PK3)\n", pk3);
    return EXIT_SKIP;
  }
  printf("sightline %s, C API, the example's own world\n", sl_version());

  walk w;
  char error[512];
  if (walk_read(walk_path, &w, error, sizeof error) != 0) {
    fprintf(stderr, "%s\n", error);
    return 1;
  }
  game_world world = {{NULL, 0, NULL, 0}, 0, 0, 0};
  sl_world* sl = NULL;
  int failed = load_world(pk3, map, &world);
  if (!failed) {
    const sl_world_callbacks callbacks = {first_hit, clearance, line_of_sight, &world};
    const sl_status status = sl_world_create_callbacks(&callbacks, &sl);
    failed = status != SL_OK ? sightline_failed("sl_world_create_callbacks", status)
                             : run(&world, sl, &w, trace_path);
  }
  sl_world_destroy(sl); /* after the camera: the callbacks' user data is `world` */
  bvh_free(&world.index);
  walk_free(&w);
  return failed;
}
