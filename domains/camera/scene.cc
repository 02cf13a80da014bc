#include "domains/camera/scene.h"

#include <algorithm>

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
      area_tree_(boxes_of(areas_)) {}

Aabb Scene::world_bounds() const {
  Aabb bounds = solid_tree_.bounds();
  if (!area_tree_.empty()) bounds.merge(area_tree_.bounds());
  return bounds;
}

void Scene::set_profile(CameraProfile profile, std::string source) {
  profile_ = std::move(profile);
  profile_source_ = std::move(source);
}

Eigen::Vector3d Scene::start_camera_position() const {
  if (camera_start_) return *camera_start_;
  return ideal_camera_position(character_at(trajectory_.start_time()), profile_.height.desired,
                               profile_.distance.desired, profile_.orientation.desired);
}

double Scene::clearance(const Eigen::Vector3d& p, double limit) const {
  const auto nearest = solid_tree_.nearest(p, limit);
  return nearest ? nearest->signed_distance : limit;
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
