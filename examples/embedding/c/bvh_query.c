/* bvh_query.c: the example index's queries: first hit and line of sight on a segment, and
 * the distance to the nearest triangle (see bvh.h for what and why).
 *
 * Each walks the tree with a fixed stack (no allocation), nearer child first, and skips every
 * node that cannot beat the best answer found so far: a segment clipped at the nearest hit,
 * a distance capped at the nearest triangle yet.
 */
#include <math.h>

#include "bvh.h"
#include "vector3.h"

#define STACK_SIZE (BVH_MAX_DEPTH + 1) /* a walk holds at most one entry per level, plus one */
#define EDGE_TOLERANCE 1e-9 /* barycentric slack: a ray along a shared edge hits a triangle */

/* A node to visit. Entries are popped field by field: copied whole, the node index is loaded
 * together with its padding, which the CPU cannot forward from the narrower store that pushed
 * it (a stall that can make the walks twice as slow). */
typedef struct stack_entry {
  uint32_t node;
  double key; /* where the segment enters the node, or the node's squared distance */
} stack_entry;

/* Where the segment a + s d, s in [0, s_max], enters the box, or -1 when it misses. A 0 * inf
 * (a on a slab face, d parallel to it) is NaN and leaves that slab unbounded. */
static double segment_enters(const bvh_node* n, const double* a, const double* inv, double s_max) {
  double s0 = 0, s1 = s_max;
  for (int k = 0; k < 3; ++k) {
    double near = (n->lo[k] - a[k]) * inv[k], far = (n->hi[k] - a[k]) * inv[k];
    if (near > far) {
      const double t = near;
      near = far;
      far = t;
    }
    if (near > s0) s0 = near;
    if (far < s1) s1 = far;
  }
  return s0 <= s1 ? s0 : -1;
}

/* Möller-Trumbore, both faces: the parameter s in [0, s_max] where a + s d meets the
 * triangle, or -1. */
static double segment_triangle(const double* a, const double* d, const double* tri, double s_max) {
  double e1[3], e2[3], p[3], to_a[3], q[3];
  sub(tri + 3, tri, e1);
  sub(tri + 6, tri, e2);
  cross(d, e2, p);
  const double det = dot(e1, p);
  if (det == 0) return -1; /* parallel to the plane */
  const double inv = 1 / det;
  sub(a, tri, to_a);
  const double u = dot(to_a, p) * inv;
  if (u < -EDGE_TOLERANCE || u > 1 + EDGE_TOLERANCE) return -1;
  cross(to_a, e1, q);
  const double v = dot(d, q) * inv;
  if (v < -EDGE_TOLERANCE || u + v > 1 + EDGE_TOLERANCE) return -1;
  const double s = dot(e2, q) * inv;
  return s >= 0 && s <= s_max ? s : -1;
}

/* Walks the tree along a -> b. any = 1 stops at the first hit; otherwise the nearest is
 * found. Returns the triangle hit (its corners) and its parameter in *s, or NULL. */
static const double* trace(const bvh* index, const double* a, const double* b, int any, double* s) {
  if (index->node_count == 0) return NULL;
  double d[3], inv[3];
  sub(b, a, d);
  for (int k = 0; k < 3; ++k) inv[k] = 1 / d[k]; /* +-inf on an axis the segment is flat in */
  const double* hit = NULL;
  double best = 1;
  stack_entry stack[STACK_SIZE];
  int top = 0;
  const double root = segment_enters(&index->nodes[0], a, inv, best);
  if (root >= 0) stack[top++] = (stack_entry){0, root};
  while (top > 0) {
    const uint32_t node = stack[--top].node;
    if (stack[top].key > best) continue; /* a nearer hit was found since it was pushed */
    const bvh_node* n = &index->nodes[node];
    if (n->count > 0) {
      for (uint32_t i = n->first; i < n->first + n->count; ++i) {
        const double* tri = index->triangles + 9 * (size_t)i;
        const double t = segment_triangle(a, d, tri, best);
        if (t < 0) continue;
        hit = tri;
        best = t;
        if (any) break;
      }
      if (any && hit) break;
      continue;
    }
    const uint32_t child[2] = {node + 1, n->first};
    const double enter[2] = {segment_enters(&index->nodes[child[0]], a, inv, best),
                             segment_enters(&index->nodes[child[1]], a, inv, best)};
    const int near = enter[1] >= 0 && (enter[0] < 0 || enter[1] < enter[0]);
    if (enter[1 - near] >= 0) stack[top++] = (stack_entry){child[1 - near], enter[1 - near]};
    if (enter[near] >= 0) stack[top++] = (stack_entry){child[near], enter[near]};
  }
  *s = best;
  return hit;
}

int bvh_first_hit(const bvh* index, const double a[3], const double b[3], bvh_hit* hit) {
  double s;
  const double* tri = trace(index, a, b, 0, &s);
  if (!tri) return 0;
  double e1[3], e2[3], n[3], d[3];
  sub(tri + 3, tri, e1);
  sub(tri + 6, tri, e2);
  cross(e1, e2, n);
  sub(b, a, d);
  /* The normal facing a; not zero, as needles are not indexed. */
  const double length = sqrt(dot(n, n));
  const double sign = dot(n, d) > 0 ? -1 : 1;
  for (int k = 0; k < 3; ++k) hit->normal[k] = sign * n[k] / length;
  hit->fraction = s;
  return 1;
}

int bvh_line_of_sight(const bvh* index, const double a[3], const double b[3]) {
  double s;
  return trace(index, a, b, 1, &s) == NULL;
}

/* --- clearance --- */

static double box_distance2(const bvh_node* n, const double* p) {
  double d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double below = n->lo[k] - p[k], above = p[k] - n->hi[k];
    const double gap = below > 0 ? below : (above > 0 ? above : 0);
    d2 += gap * gap;
  }
  return d2;
}

/* The squared distance from p to the triangle (a, b, c): Ericson, "Real-Time Collision
 * Detection", 5.1.5, finding which vertex, edge or the face is nearest from dot products. */
static double point_triangle_distance2(const double* p, const double* tri) {
  const double *a = tri, *b = tri + 3, *c = tri + 6;
  double ab[3], ac[3], ap[3], bp[3], cp[3], q[3];
  sub(b, a, ab);
  sub(c, a, ac);
  sub(p, a, ap);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return distance2(p, a);
  sub(p, b, bp);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return distance2(p, b);
  sub(p, c, cp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return distance2(p, c);
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  double u, w; /* q = a + u ab + w ac */
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    u = d1 / (d1 - d3), w = 0; /* edge ab */
  } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    u = 0, w = d2 / (d2 - d6); /* edge ac */
  } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    w = (d4 - d3) / ((d4 - d3) + (d5 - d6)), u = 1 - w; /* edge bc */
  } else {
    const double sum = va + vb + vc; /* the face */
    u = vb / sum, w = vc / sum;
  }
  for (int k = 0; k < 3; ++k) q[k] = a[k] + u * ab[k] + w * ac[k];
  return distance2(p, q);
}

double bvh_clearance(const bvh* index, const double p[3], double limit) {
  /* Distances are >= 0, so a limit of 0 or less is the answer. An infinite limit squares to
   * an infinite best. */
  if (!(limit > 0) || index->node_count == 0) return limit;
  double best2 = limit * limit;
  stack_entry stack[STACK_SIZE];
  int top = 0;
  stack[top++] = (stack_entry){0, box_distance2(&index->nodes[0], p)};
  while (top > 0) {
    const uint32_t node = stack[--top].node;
    if (stack[top].key >= best2) continue;
    const bvh_node* n = &index->nodes[node];
    if (n->count > 0) {
      for (uint32_t i = n->first; i < n->first + n->count; ++i) {
        const double d2 = point_triangle_distance2(p, index->triangles + 9 * (size_t)i);
        if (d2 < best2) best2 = d2;
      }
      continue;
    }
    const uint32_t child[2] = {node + 1, n->first};
    const double d2[2] = {box_distance2(&index->nodes[child[0]], p),
                          box_distance2(&index->nodes[child[1]], p)};
    const int near = d2[1] < d2[0];
    if (d2[1 - near] < best2) stack[top++] = (stack_entry){child[1 - near], d2[1 - near]};
    if (d2[near] < best2) stack[top++] = (stack_entry){child[near], d2[near]};
  }
  const double d = sqrt(best2);
  return d < limit ? d : limit;
}
