/* vector3.h: the few 3-vector operations the index needs, on plain double[3] arrays (a game
 * would use its own math library). */
#ifndef EXAMPLE_VECTOR3_H
#define EXAMPLE_VECTOR3_H

static inline void sub(const double* a, const double* b, double* out) {
  out[0] = a[0] - b[0];
  out[1] = a[1] - b[1];
  out[2] = a[2] - b[2];
}
static inline double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline void cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
static inline double distance2(const double* a, const double* b) {
  double d[3];
  sub(a, b, d);
  return dot(d, d);
}

#endif /* EXAMPLE_VECTOR3_H */
