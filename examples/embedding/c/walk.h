/* walk.h: the character's walk, as a game would replay a recorded path: timed keyframes read
 * from a CSV file, and the character's state at any time in between.
 *
 * The example has no game to drive the character, so it replays a walk made by
 * `sightline level walk`. Between keyframes the feet move in a straight line and the yaw turns
 * the shorter way round (a turn of exactly 180 degrees goes through increasing yaw). The
 * frames run from the first keyframe to the last at a fixed rate; when the walk is not a whole
 * number of frames long, one more, shorter frame ends exactly on the last keyframe.
 */
#ifndef EXAMPLE_WALK_H
#define EXAMPLE_WALK_H

#include <stddef.h>

typedef struct walk_keyframe {
  double t;           /* seconds, strictly increasing */
  double position[3]; /* centre of the feet, metres */
  double yaw;         /* degrees; 0 faces +z, 90 faces +x */
} walk_keyframe;

typedef struct walk {
  walk_keyframe* keys;
  size_t count; /* >= 1 */
} walk;

typedef struct walk_state {
  double position[3];
  double velocity[3]; /* metres per second: the current segment's */
  double yaw;         /* degrees in [0, 360) */
} walk_state;

/* Reads a file of `t,x,y,z,yaw` rows under that header line. Returns 0, or -1 with a message
 * naming the file and line in `error`. */
int walk_read(const char* path, walk* out, char* error, size_t error_size);
void walk_free(walk* w);

/* The state at time t, in [first keyframe, last keyframe]. At a keyframe the velocity is that
 * of the segment starting there (of the last segment at the last keyframe). */
walk_state walk_state_at(const walk* w, double t);

/* The number of frames at `rate` per second, both ends included, and the time of one. */
size_t walk_frame_count(const walk* w, double rate);
double walk_frame_time(const walk* w, size_t frame, double rate);

#endif /* EXAMPLE_WALK_H */
