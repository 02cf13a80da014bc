#include "sightline/domains/camera/scene.h"

#include <algorithm>
#include <cmath>

#include "sightline/domains/camera/constraints/clearance.h"

namespace sightline::camera {
namespace {

template <class T>
std::vector<Aabb> boxes_of(const std::vector<T>& items) {
  std::vector<Aabb> out;
  out.reserve(items.size());
  for (const T& item : items) out.push_back(item.box);
  return out;
}

}  // namespace

Scene::Scene(std::string name, std::vector<SolidBox> solids, std::vector<Area> areas,
             CharacterShape character, Trajectory trajectory, double frame_rate)
    : name_(std::move(name)),
      solids_(std::move(solids)),
      areas_(std::move(areas)),
      character_(character),
      trajectory_(std::move(trajectory)),
      frame_rate_(frame_rate),
      solid_tree_(boxes_of(solids_)),
      area_tree_(boxes_of(areas_)),
      triangles_(std::make_shared<const TriangleIndex>()) {}

Aabb Scene::world_bounds() const {
  Aabb bounds = solid_tree_.bounds();
  if (!area_tree_.empty()) bounds.merge(area_tree_.bounds());
  if (!triangles_->empty()) bounds.merge(triangles_->bounds());
  for (const Mover& m : movers_) bounds.merge(m.swept_box());
  return bounds;
}

void Scene::set_level(std::shared_ptr<const Level> level) {
  level_ = std::move(level);
  triangles_ = level_ ? std::make_shared<const TriangleIndex>(level_->mesh)
                      : std::make_shared<const TriangleIndex>();
}

std::optional<SurfaceHit> Scene::first_hit(const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b) const {
  std::optional<SurfaceHit> best;
  if (const auto box = solid_tree_.first_hit(a, b)) {
    SurfaceHit hit;
    hit.t = box->t;
    hit.source = SurfaceHit::Source::kBox;
    hit.index = box->box;
    // The face entered, whose outward normal faces the start.
    if (hit.t > 0) hit.normal = solid_tree_.box(box->box).nearest_face_normal(a + hit.t * (b - a));
    best = hit;
  }
  if (const auto tri = triangles_->first_hit(a, b); tri && (!best || tri->t < best->t)) {
    SurfaceHit hit;
    hit.t = tri->t;
    hit.source = SurfaceHit::Source::kTriangle;
    hit.index = tri->triangle;
    hit.normal = tri->normal.dot(b - a) > 0 ? -tri->normal : tri->normal;
    best = hit;
  }
  return best;
}

void Scene::set_actors(std::vector<Actor> actors) {
  actors_ = std::move(actors);
  for (const Actor& a : actors_) {
    std::vector<MoverKeyframe> path;
    for (const Keyframe& k : a.trajectory.keyframes()) path.push_back({k.t, k.position});
    movers_.emplace_back(a.name, a.shape.size, std::move(path), a.where);
  }
}

std::optional<SurfaceHit> Scene::surface_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                             double t) const {
  if (!world_) return first_hit(a, b);
  const auto hit = world_->first_hit({a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}, t);
  if (!hit) return std::nullopt;
  SurfaceHit h;
  h.t = std::clamp(hit->fraction, 0.0, 1.0);
  h.source = SurfaceHit::Source::kBox;
  h.normal = Eigen::Vector3d(hit->normal.x, hit->normal.y, hit->normal.z);
  return h;
}

std::optional<NearestSurface> Scene::nearest_surface(const Eigen::Vector3d& p,
                                                     double limit) const {
  std::optional<NearestSurface> best;
  if (const auto box = solid_tree_.nearest(p, limit)) {
    best = NearestSurface{box->signed_distance,
                          signed_distance_gradient(solid_tree_.box(box->box), p)};
  }
  if (triangles_->empty()) return best;
  if (level_->solid && level_->solid->solid_at(p)) {
    // Inside solid matter: minus the distance to the nearest face, whose gradient points
    // deeper in (away from that face is further inside); -limit when no face is that close.
    NearestSurface inside{-limit, Eigen::Vector3d::Zero()};
    if (const auto tri = triangles_->nearest(p, limit)) {
      const Eigen::Vector3d toward = tri->point - p;
      const double norm = toward.norm();
      inside.signed_distance = -tri->distance;
      if (norm > 0) inside.gradient = toward / norm;
    }
    if (!best || inside.signed_distance < best->signed_distance) best = inside;
    return best;
  }
  if (best && best->signed_distance <= 0) return best;  // inside a box: no face is nearer
  if (const auto tri = triangles_->nearest(p, best ? best->signed_distance : limit)) {
    const Eigen::Vector3d away = p - tri->point;
    const double norm = away.norm();
    best = NearestSurface{tri->distance,
                          norm > 0 ? Eigen::Vector3d(away / norm) : Eigen::Vector3d::Zero()};
  }
  return best;
}

bool Scene::open_at(const Eigen::Vector3d& p) const {
  if (level_ && level_->solid && level_->solid->solid_at(p)) return false;
  const auto box = solid_tree_.nearest(p, 0.0);
  return !box;
}

void Scene::set_profile(CameraProfile profile, std::string source) {
  profile_ = std::move(profile);
  profile_source_ = std::move(source);
}

Eigen::Vector3d Scene::start_camera_position() const {
  if (camera_start_) return *camera_start_;
  const CharacterState start = character_at(trajectory_.start_time());
  const Eigen::Vector3d ideal = ideal_camera_position(
      start, profile_.height.desired, profile_.distance.desired, profile_.orientation.desired);
  if (level_ == nullptr) return ideal;
  // On a level the ideal spot may be inside a wall or behind one: pull in along the line
  // from the look-at point toward it, as a spring arm does, to the farthest point that is
  // open, clear of surfaces and sees the look-at point.
  const Eigen::Vector3d look = character_.look_at(start.position);
  const double r = profile_.clearance_radius;
  return pulled_in_start(look, ideal, [&](const Eigen::Vector3d& p) {
    return clearance(p, r + 1e-6) >= r && line_of_sight(p, look);
  });
}

double Scene::clearance(const Eigen::Vector3d& p, double limit) const {
  double d = limit;
  if (const auto box = solid_tree_.nearest(p, limit)) d = box->signed_distance;
  if (triangles_->empty()) return d;
  if (level_->solid && level_->solid->solid_at(p)) {
    // Inside solid matter: the depth is the distance to the nearest face (or `limit` when
    // none is that close), counted negative.
    const auto tri = triangles_->nearest(p, limit);
    return std::min(d, tri ? -tri->distance : -limit);
  }
  if (d <= 0) return d;  // inside or touching a box: no triangle is nearer
  if (const auto tri = triangles_->nearest(p, d)) d = tri->distance;
  return d;
}

std::vector<std::size_t> Scene::areas_containing(const Eigen::Vector3d& p) const {
  std::vector<std::size_t> out;
  area_tree_.for_each_containing(p, [&](BoxTree::BoxIndex i) { out.push_back(i); });
  std::sort(out.begin(), out.end());
  return out;
}

std::optional<std::size_t> Scene::innermost_area(const Eigen::Vector3d& p) const {
  std::optional<std::size_t> best;
  double best_volume = 0;
  area_tree_.for_each_containing(p, [&](BoxTree::BoxIndex i) {
    const double v = areas_[i].box.volume();
    if (!best || v < best_volume || (v == best_volume && i < *best)) {
      best = i;
      best_volume = v;
    }
  });
  return best;
}

std::optional<std::size_t> Scene::solid_overlapping(const Aabb& box) const {
  const auto hit = solid_tree_.any_overlapping(box);
  if (!hit) return std::nullopt;
  return *hit;
}

}  // namespace sightline::camera
