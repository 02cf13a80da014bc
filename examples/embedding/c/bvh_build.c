/* bvh_build.c: building the example's bounding-volume hierarchy (see bvh.h for what and why).
 *
 * Top-down: each node is split along the longest axis of its triangles' centres, at the
 * cheapest of BIN_COUNT - 1 planes by the surface-area heuristic (the expected cost of a ray
 * visiting both halves), until a node holds LEAF_SIZE triangles or fewer. Triangles are
 * copied into leaf order so that a leaf reads one block of memory. The build is
 * O(n log n) and allocation happens here only.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "vector3.h"

#define LEAF_SIZE 4   /* split nodes holding more triangles than this */
#define BIN_COUNT 12  /* candidate split planes per node, plus one */
#define BOX_PAD 1e-6  /* metres added around node boxes against rounding */
#define MIN_SINE 1e-6 /* needles thinner than this (sine of an angle) are left out */

typedef struct box {
  double lo[3], hi[3];
} box;
typedef struct item {
  box bounds;
  double centre[3];
  const double* corners[3];
} item;

static box empty_box(void) {
  box b = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  return b;
}
static void grow(box* b, const box* other) {
  for (int k = 0; k < 3; ++k) {
    if (other->lo[k] < b->lo[k]) b->lo[k] = other->lo[k];
    if (other->hi[k] > b->hi[k]) b->hi[k] = other->hi[k];
  }
}
static double half_area(const box* b) {
  const double x = b->hi[0] - b->lo[0], y = b->hi[1] - b->lo[1], z = b->hi[2] - b->lo[2];
  return x * y + y * z + z * x;
}

/* A needle or a point blocks no ray, and the closest-point formulas divide by its area. */
static int is_degenerate(const double* a, const double* b, const double* c) {
  double e1[3], e2[3], n[3];
  sub(b, a, e1);
  sub(c, a, e2);
  cross(e1, e2, n);
  return dot(n, n) <= MIN_SINE * MIN_SINE * dot(e1, e1) * dot(e2, e2);
}

typedef struct builder {
  bvh* index;
  item* items;
} builder;

static int bin_of(const item* it, int axis, double start, double scale) {
  const int k = (int)((it->centre[axis] - start) * scale);
  return k < 0 ? 0 : (k >= BIN_COUNT ? BIN_COUNT - 1 : k);
}

/* Reorders items[begin, end) into two non-empty runs by the cheapest binned plane and
 * returns where the second starts. */
static size_t split(item* items, size_t begin, size_t end) {
  box centres = empty_box();
  for (size_t i = begin; i < end; ++i) {
    box c = {{items[i].centre[0], items[i].centre[1], items[i].centre[2]},
             {items[i].centre[0], items[i].centre[1], items[i].centre[2]}};
    grow(&centres, &c);
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (centres.hi[k] - centres.lo[k] > centres.hi[axis] - centres.lo[axis]) axis = k;
  }
  const double extent = centres.hi[axis] - centres.lo[axis];
  if (!(extent > 0)) return begin + (end - begin) / 2; /* all centres coincide: any halves */

  box bins[BIN_COUNT];
  size_t counts[BIN_COUNT] = {0};
  for (int k = 0; k < BIN_COUNT; ++k) bins[k] = empty_box();
  const double scale = BIN_COUNT / extent;
  for (size_t i = begin; i < end; ++i) {
    const int k = bin_of(&items[i], axis, centres.lo[axis], scale);
    grow(&bins[k], &items[i].bounds);
    ++counts[k];
  }
  /* Plane p separates bins [0, p] from [p + 1, BIN_COUNT): sweep from the right, then the left. */
  double right_cost[BIN_COUNT - 1];
  box acc = empty_box();
  size_t n = 0;
  for (int p = BIN_COUNT - 2; p >= 0; --p) {
    grow(&acc, &bins[p + 1]);
    n += counts[p + 1];
    right_cost[p] = n ? half_area(&acc) * (double)n : INFINITY;
  }
  int best = 0;
  double best_cost = INFINITY;
  acc = empty_box();
  n = 0;
  for (int p = 0; p < BIN_COUNT - 1; ++p) {
    grow(&acc, &bins[p]);
    n += counts[p];
    const double cost = n ? half_area(&acc) * (double)n + right_cost[p] : INFINITY;
    if (cost < best_cost) {
      best_cost = cost;
      best = p;
    }
  }
  /* The lowest and highest centres fall in the first and last bins, so both runs are filled. */
  size_t left = begin, right = end;
  while (left < right) {
    if (bin_of(&items[left], axis, centres.lo[axis], scale) <= best) {
      ++left;
    } else {
      const item t = items[left];
      items[left] = items[--right];
      items[right] = t;
    }
  }
  return left;
}

static void make_leaf(builder* b, bvh_node* node, size_t begin, size_t end) {
  node->first = (uint32_t)b->index->triangle_count;
  node->count = (uint32_t)(end - begin);
  for (size_t i = begin; i < end; ++i) {
    double* out = b->index->triangles + 9 * b->index->triangle_count++;
    for (int c = 0; c < 3; ++c) memcpy(out + 3 * c, b->items[i].corners[c], 3 * sizeof(double));
  }
}

static uint32_t build_node(builder* b, size_t begin, size_t end, int depth) {
  const uint32_t id = (uint32_t)b->index->node_count++;
  bvh_node* node = &b->index->nodes[id]; /* stays valid: the array never moves */
  box bounds = empty_box();
  for (size_t i = begin; i < end; ++i) grow(&bounds, &b->items[i].bounds);
  for (int k = 0; k < 3; ++k) {
    node->lo[k] = bounds.lo[k] - BOX_PAD;
    node->hi[k] = bounds.hi[k] + BOX_PAD;
  }
  if (end - begin <= LEAF_SIZE || depth >= BVH_MAX_DEPTH) {
    make_leaf(b, node, begin, end);
    return id;
  }
  const size_t mid = split(b->items, begin, end);
  build_node(b, begin, mid, depth + 1); /* the first child is the next node */
  node->first = build_node(b, mid, end, depth + 1);
  node->count = 0;
  return id;
}

int bvh_build(bvh* index, const double* vertices, const uint32_t* indices, size_t triangle_count) {
  memset(index, 0, sizeof *index);
  const size_t n = triangle_count;
  item* items = malloc((n ? n : 1) * sizeof *items);
  index->nodes = malloc((n ? 2 * n : 1) * sizeof *index->nodes);
  index->triangles = malloc((n ? 9 * n : 1) * sizeof *index->triangles);
  if (!items || !index->nodes || !index->triangles) {
    free(items);
    bvh_free(index);
    return -1;
  }
  size_t kept = 0;
  for (size_t t = 0; t < n; ++t) {
    item* it = &items[kept];
    for (int c = 0; c < 3; ++c) it->corners[c] = vertices + 3 * (size_t)indices[3 * t + c];
    if (is_degenerate(it->corners[0], it->corners[1], it->corners[2])) continue;
    it->bounds = empty_box();
    for (int c = 0; c < 3; ++c) {
      box corner;
      memcpy(corner.lo, it->corners[c], sizeof corner.lo);
      memcpy(corner.hi, it->corners[c], sizeof corner.hi);
      grow(&it->bounds, &corner);
    }
    for (int k = 0; k < 3; ++k) it->centre[k] = 0.5 * (it->bounds.lo[k] + it->bounds.hi[k]);
    ++kept;
  }
  builder b = {index, items};
  if (kept > 0) build_node(&b, 0, kept, 0);
  free(items);
  return 0;
}

void bvh_free(bvh* index) {
  free(index->nodes);
  free(index->triangles);
  memset(index, 0, sizeof *index);
}
