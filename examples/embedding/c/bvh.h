/* bvh.h: the example's own spatial index over a level's triangles, standing in for a game's
 * physics engine.
 *
 * sightline can index triangles itself (sl_world_create_geometry), but a game already has a
 * physics world and should let the camera ask it instead. This bounding-volume hierarchy
 * plays that part: it answers the three questions sightline's callback world asks (the first
 * hit on a segment, any hit on a segment, the distance to the nearest surface).
 *
 * The tree is built once (bvh_build.c: binned surface-area heuristic over the triangles'
 * bounding boxes); the queries (bvh_query.c) are read-only, allocation-free and safe to run
 * from several threads at once. Triangles are two-sided and have no inside, so distances are
 * never negative. Needle and point triangles are left out: they block no sight line.
 */
#ifndef EXAMPLE_BVH_H
#define EXAMPLE_BVH_H

#include <stddef.h>
#include <stdint.h>

/* Nodes deeper than this become leaves, so a query's fixed stack of BVH_MAX_DEPTH + 1 entries
 * never overflows. */
#define BVH_MAX_DEPTH 63

typedef struct bvh_node {
  double lo[3], hi[3]; /* bounding box of everything below */
  uint32_t first;      /* leaf: first triangle in bvh.triangles; inner: the second child */
  uint32_t count;      /* leaf: number of triangles (> 0); inner: 0 (first child = next node) */
} bvh_node;

typedef struct bvh {
  bvh_node* nodes;
  size_t node_count;
  double* triangles;     /* 9 doubles per triangle (3 corners), in leaf order */
  size_t triangle_count; /* indexed: the level's, less the needles */
} bvh;

/* What first_hit found. */
typedef struct bvh_hit {
  double fraction;  /* in [0, 1]: the hit is at a + fraction (b - a) */
  double normal[3]; /* unit, facing a */
} bvh_hit;

/* Builds the index over `triangle_count` triangles (3 indices each into `vertices`, 3 doubles
 * per vertex; finite, and indices within the vertices, as sl_level_triangles gives them).
 * Returns 0, or -1 when out of memory (with *index left empty). */
int bvh_build(bvh* index, const double* vertices, const uint32_t* indices, size_t triangle_count);
void bvh_free(bvh* index);

/* The nearest triangle on the segment a -> b: returns 1 and fills *hit, or returns 0. */
int bvh_first_hit(const bvh* index, const double a[3], const double b[3], bvh_hit* hit);
/* 1 when no triangle touches the segment a -> b (stops at the first one found). */
int bvh_line_of_sight(const bvh* index, const double a[3], const double b[3]);
/* min(distance from p to the nearest triangle, limit); limit may be INFINITY. */
double bvh_clearance(const bvh* index, const double p[3], double limit);

#endif /* EXAMPLE_BVH_H */
