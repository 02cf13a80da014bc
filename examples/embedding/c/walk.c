/* walk.c: reading a walk's keyframes and replaying it frame by frame (see walk.h). */
#include "walk.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HEADER "t,x,y,z,yaw"

/* Strips the line ending; returns 0 for a line too long for the buffer. */
static int chomp(char* line, FILE* f) {
  const size_t n = strlen(line);
  if (n > 0 && line[n - 1] != '\n' && !feof(f)) return 0;
  line[strcspn(line, "\r\n")] = '\0';
  return 1;
}

/* Parses "t,x,y,z,yaw" into k; returns 0 unless five finite numbers and nothing else. */
static int parse_row(const char* line, walk_keyframe* k) {
  double v[5];
  const char* p = line;
  for (int i = 0; i < 5; ++i) {
    char* end;
    v[i] = strtod(p, &end);
    if (end == p || !isfinite(v[i])) return 0;
    p = end;
    if (*p != (i < 4 ? ',' : '\0')) return 0;
    ++p;
  }
  k->t = v[0];
  k->position[0] = v[1], k->position[1] = v[2], k->position[2] = v[3];
  k->yaw = v[4];
  return 1;
}

/* Appends k to w, growing the array; returns 0 when out of memory. */
static int append(walk* w, size_t* capacity, const walk_keyframe* k) {
  if (w->count == *capacity) {
    const size_t grown = *capacity ? 2 * *capacity : 64;
    walk_keyframe* keys = realloc(w->keys, grown * sizeof *keys);
    if (!keys) return 0;
    w->keys = keys;
    *capacity = grown;
  }
  w->keys[w->count++] = *k;
  return 1;
}

int walk_read(const char* path, walk* out, char* error, size_t error_size) {
  out->keys = NULL;
  out->count = 0;
  FILE* f = fopen(path, "r");
  if (!f) {
    snprintf(error, error_size, "%s: cannot open", path);
    return -1;
  }
  char line[512];
  size_t capacity = 0, number = 1;
  const char* problem = NULL;
  if (!fgets(line, sizeof line, f) || !chomp(line, f) || strcmp(line, HEADER) != 0) {
    problem = "the first line must be '" HEADER "'";
  }
  while (!problem && fgets(line, sizeof line, f)) {
    ++number;
    walk_keyframe k;
    if (!chomp(line, f)) {
      problem = "line too long";
    } else if (line[0] == '\0') {
      continue; /* blank lines are allowed */
    } else if (!parse_row(line, &k)) {
      problem = "expected five numbers: " HEADER;
    } else if (out->count > 0 && !(k.t > out->keys[out->count - 1].t)) {
      problem = "t must increase";
    } else if (!append(out, &capacity, &k)) {
      problem = "out of memory";
    }
  }
  if (!problem && ferror(f)) problem = "read error";
  if (!problem && out->count == 0) problem = "no keyframes";
  fclose(f);
  if (problem) {
    snprintf(error, error_size, "%s:%zu: %s", path, number, problem);
    walk_free(out);
    return -1;
  }
  return 0;
}

void walk_free(walk* w) {
  free(w->keys);
  w->keys = NULL;
  w->count = 0;
}

static double wrap_degrees(double degrees) {
  double w = fmod(degrees, 360.0);
  if (w < 0) w += 360.0;
  return w >= 360.0 ? w - 360.0 : w; /* a tiny negative plus 360 can round to 360 */
}

/* The shorter signed turn from `from` to `to`, in (-180, 180]. */
static double shortest_turn(double from, double to) {
  const double d = wrap_degrees(to - from);
  return d > 180.0 ? d - 360.0 : d;
}

/* The segment [keys[i], keys[i + 1]] holding t: the last keyframe at or before t, clamped to
 * the segments there are. Binary search. */
static size_t segment_at(const walk* w, double t) {
  size_t lo = 0, hi = w->count; /* the first keyframe after t is in [lo, hi] */
  while (lo < hi) {
    const size_t mid = lo + (hi - lo) / 2;
    if (w->keys[mid].t > t) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  if (lo == 0) return 0;
  return lo - 1 < w->count - 2 ? lo - 1 : w->count - 2;
}

walk_state walk_state_at(const walk* w, double t) {
  walk_state s;
  memset(&s, 0, sizeof s);
  if (w->count == 1) {
    memcpy(s.position, w->keys[0].position, sizeof s.position);
    s.yaw = wrap_degrees(w->keys[0].yaw);
    return s;
  }
  const walk_keyframe* a = &w->keys[segment_at(w, t)];
  const walk_keyframe* b = a + 1;
  const double span = b->t - a->t;
  double u = (t - a->t) / span;
  u = u < 0 ? 0 : (u > 1 ? 1 : u);
  for (int k = 0; k < 3; ++k) {
    const double delta = b->position[k] - a->position[k];
    s.position[k] = a->position[k] + u * delta;
    s.velocity[k] = delta / span;
  }
  s.yaw = wrap_degrees(a->yaw + u * shortest_turn(a->yaw, b->yaw));
  return s;
}

size_t walk_frame_count(const walk* w, double rate) {
  /* Frames at start + k / rate for k = 0 .. floor(duration * rate), plus the last keyframe
   * when it is not (within a millionth of a frame) on that grid. */
  const double frames = (w->keys[w->count - 1].t - w->keys[0].t) * rate;
  const double whole = floor(frames + 1e-6);
  return (size_t)whole + 1 + (frames - whole > 1e-6 ? 1 : 0);
}

double walk_frame_time(const walk* w, size_t frame, double rate) {
  const double t = w->keys[0].t + (double)frame / rate;
  const double end = w->keys[w->count - 1].t;
  return t < end ? t : end;
}
