/* sightline/sightline.h: the C API of sightline's chase camera, for engines and bindings.
 *
 * C99, opaque handles, a status code from every call and a message for the last failure; no
 * exception crosses it. It is what engine bindings (C#, GDNative, Rust) wrap.
 *
 *   sl_world*  the geometry the camera films: sightline's own index over triangles and boxes
 *              (sl_world_create_geometry) or the game's own physics through callbacks
 *              (sl_world_create_callbacks: a ray test and a clearance query).
 *   sl_camera* one camera over a world, driven each frame by the people's states
 *              (sl_camera_update -> pose, cut flag, diagnostics).
 *
 * Units: metres, seconds, degrees; y is up; yaw 0 faces +z, 90 faces +x.
 *
 * Ownership: a camera holds a reference to its world, so sl_world_destroy may come before the
 * cameras made from it are destroyed; the world is freed with the last of them. A destroyed
 * or never-created handle passed to any call is refused with SL_ERROR_INVALID_HANDLE (handles
 * are checked against the live ones), never dereferenced.
 *
 * Threads: calls on different cameras may run on different threads at once when the world's
 * callbacks may be called concurrently; calls on one camera must not overlap. The message of
 * sl_last_error() is per thread.
 */
#ifndef SIGHTLINE_SIGHTLINE_H
#define SIGHTLINE_SIGHTLINE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sl_status {
  SL_OK = 0,
  SL_ERROR_INVALID_HANDLE = 1,   /* null, destroyed or of the wrong kind */
  SL_ERROR_INVALID_ARGUMENT = 2, /* NaN, a wrong count, dt <= 0, an unknown preset or solver */
  SL_ERROR_WORLD = 3,            /* a world callback reported an error */
  SL_ERROR_OUT_OF_MEMORY = 4,
  SL_ERROR_INTERNAL = 5
} sl_status;

typedef struct sl_vec3 {
  double x, y, z;
} sl_vec3;

typedef struct sl_world sl_world;
typedef struct sl_camera sl_camera;

/* --- worlds --- */

/* The first surface on the segment a -> b at time t. Sets *hit to 1 and fills *fraction (in
 * [0, 1], 0 when a is inside solid matter) and *normal (unit, facing a; may be left zero), or
 * sets *hit to 0. Returns 0, or non-zero for an error (the camera call fails with
 * SL_ERROR_WORLD and that code in its message). The bodies of the filmed people must not
 * count. */
typedef int (*sl_first_hit_fn)(void* user, const sl_vec3* a, const sl_vec3* b, double t,
                               int* hit, double* fraction, sl_vec3* normal);
/* The signed distance from p to the nearest surface at time t, capped at limit (which may be
 * infinite): writes min(distance, limit) into *distance, negative inside solid matter when
 * the world knows inside from outside. Returns 0, or non-zero for an error. */
typedef int (*sl_clearance_fn)(void* user, const sl_vec3* p, double limit, double t,
                               double* distance);
/* Optional, faster than first_hit when given: sets *clear to 1 when nothing blocks a -> b. */
typedef int (*sl_line_of_sight_fn)(void* user, const sl_vec3* a, const sl_vec3* b, double t,
                                   int* clear);

typedef struct sl_world_callbacks {
  sl_first_hit_fn first_hit;         /* required */
  sl_clearance_fn clearance;         /* required */
  sl_line_of_sight_fn line_of_sight; /* optional (NULL: from first_hit) */
  void* user;                        /* passed back to every callback */
} sl_world_callbacks;

/* sightline's own index over triangles (vertices: 3 doubles each; indices: 3 per triangle)
 * and solid axis-aligned boxes (6 doubles each: min x, y, z, max x, y, z). Any count may be 0
 * (with a NULL pointer). */
sl_status sl_world_create_geometry(const double* vertices, size_t vertex_count,
                                   const uint32_t* indices, size_t triangle_count,
                                   const double* boxes, size_t box_count, sl_world** out);
/* The game's own world. The callbacks and `user` must stay valid while any camera of it lives. */
sl_status sl_world_create_callbacks(const sl_world_callbacks* callbacks, sl_world** out);
/* The world's own queries (for tools and tests): line of sight and clearance at time t. */
sl_status sl_world_line_of_sight(const sl_world* world, sl_vec3 a, sl_vec3 b, double t,
                                 int* clear);
sl_status sl_world_clearance(const sl_world* world, sl_vec3 p, double limit, double t,
                             double* distance);
/* Releases the caller's reference; NULL is ignored. */
void sl_world_destroy(sl_world* world);

/* --- cameras --- */

typedef struct sl_person_state {
  sl_vec3 position; /* centre of the feet */
  sl_vec3 velocity; /* metres per second */
  double yaw;       /* degrees */
} sl_person_state;

typedef struct sl_person_shape {
  sl_vec3 size;          /* box extents along x, y, z, > 0 (default 0.6, 1.8, 0.6) */
  double look_at_height; /* in (0, size.y] (default 1.5) */
} sl_person_shape;

typedef struct sl_camera_settings {
  const char* profile;  /* a preset name or a profile's YAML text; NULL: "anticipating" */
  const char* solver;   /* a camera solver or pipeline; NULL: "occlusion-octree" */
  uint64_t seed;
  const sl_person_shape* people; /* people_count shapes; the first is followed */
  size_t people_count;           /* >= 1; with people NULL, that many default shapes */
  int has_start;                 /* non-zero: the camera starts at `start` */
  sl_vec3 start;
  double frame_rate;             /* frames per second the game expects (default 60) */
} sl_camera_settings;

/* Fills *settings with the defaults: NULL profile and solver, seed 1, one default person. */
void sl_camera_settings_default(sl_camera_settings* settings);

typedef enum sl_cut_reason {
  SL_CUT_NONE = 0,
  SL_CUT_LEFT_ENCLOSED_AREA = 1,
  SL_CUT_BACKED_UP_TO_OBSTACLE = 2,
  SL_CUT_VISIBILITY_LOST = 3,
  SL_CUT_STUCK = 4,
  SL_CUT_TOO_FAST = 5
} sl_cut_reason;

typedef struct sl_pose {
  sl_vec3 position; /* where to put the camera */
  sl_vec3 target;   /* where to aim it */
  sl_vec3 up;
  int cut;          /* 1 when the camera jumped this frame */
  sl_cut_reason cut_reason;
  int look_at_visible; /* by the camera's own sight-line query */
  double cost;         /* weighted violation of the chosen position */
  double solve_seconds;
} sl_pose;

/* A camera over `world`, with the people's states at the first frame (count =
 * settings->people_count) at the game's time t. */
sl_status sl_camera_create(sl_world* world, const sl_camera_settings* settings,
                           const sl_person_state* people, size_t count, double t,
                           sl_camera** out);
/* One frame: the people's states now, dt > 0 seconds since the last update. On failure *out
 * is left as it was and the camera keeps its last good pose. */
sl_status sl_camera_update(sl_camera* camera, const sl_person_state* people, size_t count,
                           double dt, sl_pose* out);
/* The same at the game's clock t (> the last update's time): the camera's clock becomes t
 * exactly rather than the sum of the dt's. */
sl_status sl_camera_update_at(sl_camera* camera, const sl_person_state* people, size_t count,
                              double dt, double t, sl_pose* out);
/* Puts the camera at `position`, at rest. */
sl_status sl_camera_reset(sl_camera* camera, sl_vec3 position);
/* NULL is ignored. */
void sl_camera_destroy(sl_camera* camera);

/* --- messages --- */

/* The message of this thread's last failed call ("" when none failed yet). Valid until this
 * thread's next call into sightline. */
const char* sl_last_error(void);
const char* sl_status_string(sl_status status);
const char* sl_version(void);

#ifdef __cplusplus
}
#endif

#endif /* SIGHTLINE_SIGHTLINE_H */
