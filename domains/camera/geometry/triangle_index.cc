#include "sightline/domains/camera/geometry/triangle_index.h"

#include <embree3/rtcore.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace sightline::camera {

namespace {

// Embree reports errors through a callback (with a message) and a per-thread code. The
// callback may run on any thread, so the last message is kept under a lock; errors are rare
// (bad build input, out of memory), never on the query path.
std::mutex error_mutex;
std::string last_error_message;

void record_embree_error(void* /*user*/, RTCError code, const char* message) {
  const std::lock_guard<std::mutex> lock(error_mutex);
  last_error_message = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                       (message != nullptr ? message : "(no message)");
}

[[noreturn]] void throw_embree_error(const char* during) {
  std::string message;
  {
    const std::lock_guard<std::mutex> lock(error_mutex);
    message = last_error_message.empty() ? std::string("unknown Embree error") : last_error_message;
  }
  throw std::runtime_error(std::string("TriangleIndex: ") + during + ": " + message);
}

// The one device of the process. Created on first use (a function-local static: C++ makes
// its initialisation thread-safe, and a throw leaves it to be tried again) and never
// released, so that a TriangleIndex destroyed during static destruction still finds it.
RTCDevice device() {
  static const RTCDevice the_device = [] {
    RTCDevice d = rtcNewDevice("verbose=0");
    if (d == nullptr) {
      throw std::runtime_error("TriangleIndex: rtcNewDevice failed (Embree error " +
                               std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) +
                               ")");
    }
    rtcSetDeviceErrorFunction(d, record_embree_error, nullptr);
    // Triangles are two-sided: an Embree built to cull back faces would let sight through
    // half of every wall, so refuse it rather than answer wrongly.
    if (rtcGetDeviceProperty(d, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED) != 0) {
      rtcReleaseDevice(d);
      throw std::runtime_error("TriangleIndex: this Embree culls back faces; two-sided "
                               "triangles need a build without EMBREE_BACKFACE_CULLING");
    }
    if (rtcGetDeviceProperty(d, RTC_DEVICE_PROPERTY_TRIANGLE_GEOMETRY_SUPPORTED) == 0) {
      rtcReleaseDevice(d);
      throw std::runtime_error("TriangleIndex: this Embree has no triangle geometry");
    }
    return d;
  }();
  return the_device;
}

bool all_finite(const Eigen::Vector3d& p) { return p.allFinite(); }

// The tolerance, in metres, within which a query counts as touching a triangle: 2^-19 of
// the largest coordinate involved (about 16 float ulps: 1.9e-5 m at 10 m, 1.9e-4 m at
// 100 m), and never below 2^-19 m. Embree works in float: the segment's ends are rounded to
// floats and the ray-triangle test itself rounds, so a segment ending exactly on a face may
// come out a few ulps short of it. Extending the segment by this much at both ends makes
// the closed segment's contacts (t = 0 and t = 1 included) reliable, at the price of also
// reporting triangles up to this far beyond the ends, far below anything a camera resolves.
constexpr double kRelativeTolerance = 1.0 / (1 << 19);

double tolerance(double scene_scale, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return kRelativeTolerance *
         std::max({1.0, scene_scale, a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
}

// The closest point of triangle (a, b, c) to p, by the Voronoi regions of its vertices,
// edges and face (Ericson, Real-Time Collision Detection, 5.1.5). With ab = b - a,
// ac = c - a, the projections d1..d6 of p - a, p - b, p - c on ab and ac, and the normal
// n = ab x ac, p's region is found by the signs of the projections and of the barycentric
// numerators (the signed areas of the sub-triangles, times |n|):
//   va = n . ((c - b) x (p - b)),  vb = n . ((a - c) x (p - c)),  vc = n . (ab x (p - a)):
//   vertex a: d1 <= 0 and d2 <= 0;  vertex b: d3 >= 0 and d4 <= d3;  vertex c: d6 >= 0, d5 <= d6
//   edge ab: vc <= 0, d1 >= 0, d3 <= 0 -> a + ab d1 / (d1 - d3)   (ac, bc alike)
//   face: the foot of p on the plane, p - n (n . (p - a)) / |n|^2.
// The numerators come from cross products, not from Ericson's products of dot products
// (d1 d4 - d3 d2 ...): on a sliver those differences cancel catastrophically and put a
// point lying on the triangle 1e-4 m off; so does the barycentric face point vb / (va + vb
// + vc), hence the projection. A degenerate triangle (n = 0) is its three edges.
Eigen::Vector3d closest_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0) return a;
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return a + t * ab;
}

Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const Eigen::Vector3d n = ab.cross(ac);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0)) {
    const Eigen::Vector3d candidates[3] = {closest_on_segment(p, a, b),
                                           closest_on_segment(p, b, c),
                                           closest_on_segment(p, c, a)};
    const Eigen::Vector3d* best = &candidates[0];
    for (const Eigen::Vector3d& q : candidates) {
      if ((q - p).squaredNorm() < (*best - p).squaredNorm()) best = &q;
    }
    return *best;
  }
  const Eigen::Vector3d ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;

  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;

  const double vc = n.dot(ab.cross(ap));
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));

  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;

  const double vb = n.dot((a - c).cross(cp));
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));

  const double va = n.dot((c - b).cross(bp));
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  return p - n * (n.dot(ap) / n2);
}

// Embree's own copies of the mesh (owned by the geometry, which the scene keeps alive): 3
// floats per vertex, 3 indices per triangle.
struct MeshView {
  const float* vertices = nullptr;
  const std::uint32_t* triangles = nullptr;

  Eigen::Vector3d vertex(std::uint32_t triangle, int corner) const {
    const float* v = vertices + 3 * static_cast<std::size_t>(triangles[3 * triangle + corner]);
    return Eigen::Vector3d(v[0], v[1], v[2]);
  }
};

// Per-call state of a nearest() query: lives on the caller's stack (thread-safe, no
// allocation) and is reached from the callback through Embree's user pointer.
struct NearestSearch {
  MeshView mesh;
  Eigen::Vector3d p;
  double slack = 0;  // added to the float radius Embree culls with
  double best = 0;   // distance of the best triangle so far (starts at the limit)
  double margin = 0;  // see triangle_beyond
  bool found = false;
  std::uint32_t triangle = 0;
  Eigen::Vector3d point;

  // True when triangle t's bounding box, or its plane, is already farther from p than `best`
  // (plus `margin`): the triangle itself is at least as far, so the exact test below could
  // not accept it. Embree calls back for every triangle of a leaf whose node meets the query
  // sphere, most of them well outside it; this rejects those for the price of a box test.
  // `margin` (1/1000 of slack, about 2e-9 of the coordinates' scale) covers the exact
  // test's own rounding, so a rejected triangle is one whose computed distance is not below
  // `best` either: the answer is the same as without the test.
  bool triangle_beyond(std::uint32_t t) const {
    const float* v0 = mesh.vertices + 3 * static_cast<std::size_t>(mesh.triangles[3 * t]);
    const float* v1 = mesh.vertices + 3 * static_cast<std::size_t>(mesh.triangles[3 * t + 1]);
    const float* v2 = mesh.vertices + 3 * static_cast<std::size_t>(mesh.triangles[3 * t + 2]);
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double lo = std::min({v0[k], v1[k], v2[k]});
      const double hi = std::max({v0[k], v1[k], v2[k]});
      const double e = p[k] < lo ? lo - p[k] : (p[k] > hi ? p[k] - hi : 0.0);
      d2 += e * e;
    }
    const double reach = best + margin;
    if (d2 > reach * reach) return true;
    // Then the triangle's plane: a wall's box holds the point, its plane may be far.
    const Eigen::Vector3d a(v0[0], v0[1], v0[2]);
    const Eigen::Vector3d n =
        (Eigen::Vector3d(v1[0], v1[1], v1[2]) - a).cross(Eigen::Vector3d(v2[0], v2[1], v2[2]) - a);
    const double height = n.dot(p - a);
    return height * height > reach * reach * n.squaredNorm();
  }
};

// The point-query callback: Embree calls it for every triangle whose bounds meet the query
// sphere. The exact distance is computed in double; when it beats the best so far the
// sphere shrinks to it (plus a slack for Embree's float position and bounds), which prunes
// the rest of the traversal, and the callback returns true to say it changed the radius.
bool nearest_callback(RTCPointQueryFunctionArguments* args) {
  auto* search = static_cast<NearestSearch*>(args->userPtr);
  const std::uint32_t t = args->primID;
  if (search->triangle_beyond(t)) return false;
  const Eigen::Vector3d q = closest_on_triangle(search->p, search->mesh.vertex(t, 0),
                                                search->mesh.vertex(t, 1),
                                                search->mesh.vertex(t, 2));
  const double distance = (q - search->p).norm();
  if (!(distance < search->best)) return false;
  search->best = distance;
  search->found = true;
  search->triangle = t;
  search->point = q;
  const float radius = std::nextafter(static_cast<float>(distance + search->slack), INFINITY);
  if (radius < args->query->radius) {
    args->query->radius = radius;
    return true;
  }
  return false;
}

}  // namespace

struct TriangleIndex::Impl {
  RTCScene scene = nullptr;
  MeshView mesh;
  double scale = 1;  // the largest absolute coordinate of the mesh, for tolerance()

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    if (scene != nullptr) rtcReleaseScene(scene);
  }

  Eigen::Vector3d vertex(std::uint32_t triangle, int corner) const {
    return mesh.vertex(triangle, corner);
  }
  Eigen::Vector3d unit_normal(std::uint32_t triangle, const float embree_ng[3]) const {
    const Eigen::Vector3d v0 = vertex(triangle, 0);
    const Eigen::Vector3d n = (vertex(triangle, 1) - v0).cross(vertex(triangle, 2) - v0);
    const double length = n.norm();
    if (length > 0) return n / length;
    // Not reached for a triangle Embree hit (it rejects zero determinants), but never NaN.
    const Eigen::Vector3d ng(embree_ng[0], embree_ng[1], embree_ng[2]);
    return ng.norm() > 0 ? ng.normalized() : Eigen::Vector3d::UnitY();
  }
};

TriangleIndex::TriangleIndex() = default;
TriangleIndex::~TriangleIndex() = default;
TriangleIndex::TriangleIndex(TriangleIndex&&) noexcept = default;
TriangleIndex& TriangleIndex::operator=(TriangleIndex&&) noexcept = default;

TriangleIndex::TriangleIndex(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return;
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t i : t) {
      if (i >= mesh.vertices.size()) {
        throw std::invalid_argument("TriangleIndex: a triangle names vertex " +
                                    std::to_string(i) + " of " +
                                    std::to_string(mesh.vertices.size()));
      }
    }
  }
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max() / 4) {
    throw std::invalid_argument("TriangleIndex: too many triangles for 32-bit ids");
  }
  const RTCDevice dev = device();
  auto impl = std::make_unique<Impl>();
  impl->scene = rtcNewScene(dev);
  if (impl->scene == nullptr) throw_embree_error("rtcNewScene");
  // Robust: watertight triangle tests (a segment through an edge shared by two triangles
  // meets at least one of them) at some speed cost; high quality: a better (SAH, split)
  // BVH, built once per level.
  rtcSetSceneFlags(impl->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl->scene, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geometry = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (geometry == nullptr) throw_embree_error("rtcNewGeometry");
  // Buffers Embree allocates itself are padded for its 16-byte vector loads.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
      mesh.vertices.size()));
  auto* triangles = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t),
      mesh.triangles.size()));
  if (vertices == nullptr || triangles == nullptr) {
    rtcReleaseGeometry(geometry);
    throw_embree_error("rtcSetNewGeometryBuffer");
  }
  double scale = 0;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.vertices[i][k];
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) triangles[3 * i + k] = mesh.triangles[i][k];
  }
  bounds_ = mesh.bounds();
  scale = std::max(bounds_.min.cwiseAbs().maxCoeff(), bounds_.max.cwiseAbs().maxCoeff());
  if (!std::isfinite(scale)) {
    rtcReleaseGeometry(geometry);
    throw std::invalid_argument("TriangleIndex: a vertex is not finite");
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(impl->scene, geometry);  // the scene now holds a reference
  rtcReleaseGeometry(geometry);
  rtcCommitScene(impl->scene);
  if (rtcGetDeviceError(dev) != RTC_ERROR_NONE) throw_embree_error("building the scene");

  impl->mesh = MeshView{vertices, triangles};
  impl->scale = scale;
  impl_ = std::move(impl);
  triangle_count_ = mesh.triangles.size();
}

// The segment a + t (b - a), t in [0, 1], is traced as the ray from a - e (b - a) along
// b - a (unnormalised) over [0, 1 + 2e], e = tolerance / |b - a|: Embree's tnear cannot be
// negative and makes no promise about hits exactly at tnear or tfar, so the closed
// segment is extended by the tolerance at both ends. A segment shorter than the tolerance
// is a point: it touches a triangle when the point lies within the tolerance of one.
namespace {

// The Embree ray for the segment extended by e (in units of d) at both ends: from origin
// (= a - e d) along d over [0, 1 + 2e].
void extended_segment_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& d, double e,
                          RTCRay& ray) {
  ray.org_x = static_cast<float>(origin.x());
  ray.org_y = static_cast<float>(origin.y());
  ray.org_z = static_cast<float>(origin.z());
  ray.tnear = 0;
  ray.dir_x = static_cast<float>(d.x());
  ray.dir_y = static_cast<float>(d.y());
  ray.dir_z = static_cast<float>(d.z());
  ray.time = 0;
  ray.tfar = static_cast<float>(1 + 2 * e);
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
}

// The same ray as lane `lane` of a packet (Embree's packets are structures of arrays).
void put_in_lane(const RTCRay& ray, int lane, RTCRay8& rays) {
  rays.org_x[lane] = ray.org_x;
  rays.org_y[lane] = ray.org_y;
  rays.org_z[lane] = ray.org_z;
  rays.tnear[lane] = ray.tnear;
  rays.dir_x[lane] = ray.dir_x;
  rays.dir_y[lane] = ray.dir_y;
  rays.dir_z[lane] = ray.dir_z;
  rays.time[lane] = ray.time;
  rays.tfar[lane] = ray.tfar;
  rays.mask[lane] = ray.mask;
  rays.id[lane] = ray.id;
  rays.flags[lane] = ray.flags;
}

}  // namespace

bool TriangleIndex::segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (!impl_ || !all_finite(a) || !all_finite(b)) return false;
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  const double tol = tolerance(impl_->scale, a, b);
  if (length <= tol) return nearest(a, tol).has_value();
  const double e = tol / length;
  const Eigen::Vector3d origin = a - e * d;

  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  extended_segment_ray(origin, d, e, ray);
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar < 0;  // set to -inf on a hit
}

std::uint32_t TriangleIndex::segments_blocked(const Eigen::Vector3d& a,
                                              std::span<const Eigen::Vector3d> ends) const {
  if (ends.size() > kMaxFan) {
    throw std::invalid_argument("TriangleIndex::segments_blocked: more than kMaxFan segments");
  }
  std::uint32_t blocked = 0;
  if (!impl_ || !all_finite(a)) return blocked;
  // Each lane is the ray segment_blocked traces for its segment (the same extended ray, the
  // same floats); segments that are points or not finite are answered one by one as there.
  constexpr int kLanes = 8;
  for (std::size_t first = 0; first < ends.size(); first += kLanes) {
    RTCRay8 rays;
    RTCRay single[kLanes];
    alignas(32) int valid[kLanes] = {0, 0, 0, 0, 0, 0, 0, 0};
    int active = 0;
    for (int lane = 0; lane < kLanes && first + lane < ends.size(); ++lane) {
      const Eigen::Vector3d& b = ends[first + lane];
      if (!all_finite(b)) continue;
      const Eigen::Vector3d d = b - a;
      const double length = d.norm();
      const double tol = tolerance(impl_->scale, a, b);
      if (length <= tol) {
        if (nearest(a, tol).has_value()) blocked |= 1u << (first + lane);
        continue;
      }
      const double e = tol / length;
      RTCRay& ray = single[lane];
      extended_segment_ray(a - e * d, d, e, ray);
      put_in_lane(ray, lane, rays);
      valid[lane] = -1;
      ++active;
    }
    if (active == 0) continue;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    if (active == 1) {
      // One ray (the 9th of a body's samples): a packet would cost more than the ray alone.
      const int lane = static_cast<int>(std::find(valid, valid + kLanes, -1) - valid);
      rtcOccluded1(impl_->scene, &context, &single[lane]);
      rays.tfar[lane] = single[lane].tfar;
    } else {
      rtcOccluded8(valid, impl_->scene, &context, &rays);
    }
    for (int lane = 0; lane < kLanes; ++lane) {
      if (valid[lane] != 0 && rays.tfar[lane] < 0) blocked |= 1u << (first + lane);
    }
  }
  return blocked;
}

std::optional<TriangleIndex::Hit> TriangleIndex::first_hit(const Eigen::Vector3d& a,
                                                           const Eigen::Vector3d& b) const {
  if (!impl_ || !all_finite(a) || !all_finite(b)) return std::nullopt;
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  const double tol = tolerance(impl_->scale, a, b);
  if (length <= tol) {
    const std::optional<Nearest> near = nearest(a, tol);
    if (!near) return std::nullopt;
    const float no_ng[3] = {0, 0, 0};
    return Hit{0, near->triangle, impl_->unit_normal(near->triangle, no_ng)};
  }
  const double e = tol / length;
  const Eigen::Vector3d origin = a - e * d;

  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit;
  RTCRay& ray = rayhit.ray;
  extended_segment_ray(origin, d, e, ray);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  // Ray parameter s = t + e (the ray starts e before a); hits within the tolerance before a
  // or beyond b are clamped onto the segment.
  Hit hit;
  hit.t = std::clamp(static_cast<double>(ray.tfar) - e, 0.0, 1.0);
  hit.triangle = rayhit.hit.primID;
  const float ng[3] = {rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z};
  // Computed from the vertices rather than taken from Embree's Ng, whose sign convention
  // and float rounding are Embree's, so the header's promise ((v1 - v0) x (v2 - v0)) holds.
  hit.normal = impl_->unit_normal(hit.triangle, ng);
  return hit;
}

std::optional<TriangleIndex::Nearest> TriangleIndex::nearest(const Eigen::Vector3d& p,
                                                             double limit) const {
  if (!impl_ || !all_finite(p) || !(limit > 0)) return std::nullopt;
  NearestSearch search;
  search.mesh = impl_->mesh;
  search.p = p;
  search.slack = tolerance(impl_->scale, p, p);
  search.best = limit;
  search.margin = 1e-3 * search.slack;

  RTCPointQuery query;
  query.x = static_cast<float>(p.x());
  query.y = static_cast<float>(p.y());
  query.z = static_cast<float>(p.z());
  query.time = 0;
  query.radius = std::isfinite(limit)
                     ? std::nextafter(static_cast<float>(limit + search.slack), INFINITY)
                     : INFINITY;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &query, &context, nearest_callback, &search);
  if (!search.found) return std::nullopt;
  return Nearest{search.best, search.triangle, search.point};
}

}  // namespace sightline::camera
