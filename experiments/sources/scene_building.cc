#include "sightline/experiments/sources/scene_building.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "sightline/domains/camera/scene_at_time.h"

namespace sightline::experiments::scene_building {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

using Eigen::Vector3d;

Rect lane(const Vector3d& a, const Vector3d& b, double width, double ea, double eb) {
  const Vector3d d = (b - a).normalized();
  const Vector3d p = a - ea * d, q = b + eb * d;
  const double wx = std::abs(d.x()) < 0.5 ? width / 2 : 0,
               wz = std::abs(d.z()) < 0.5 ? width / 2 : 0;
  return {std::min(p.x(), q.x()) - wx, std::min(p.z(), q.z()) - wz, std::max(p.x(), q.x()) + wx,
          std::max(p.z(), q.z()) + wz};
}

void carve_walls(const std::vector<Rect>& open, double thickness, double y0, double y1,
                 std::vector<camera::SolidBox>& boxes) {
  std::vector<double> xs, zs;
  for (const Rect& r : open) {
    for (double x : {r.x0, r.x1, r.x0 - thickness, r.x1 + thickness}) xs.push_back(x);
    for (double z : {r.z0, r.z1, r.z0 - thickness, r.z1 + thickness}) zs.push_back(z);
  }
  for (auto* v : {&xs, &zs}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end(), [](double a, double b) { return b - a < 1e-9; }),
             v->end());
  }
  auto wall_cell = [&](std::size_t i, std::size_t j) {
    const double x = (xs[i] + xs[i + 1]) / 2, z = (zs[j] + zs[j + 1]) / 2;
    bool in_open = false, in_ring = false;
    for (const Rect& r : open) {
      in_open = in_open || r.holds(x, z);
      in_ring = in_ring || r.grown(thickness).holds(x, z);
    }
    return in_ring && !in_open;
  };
  // Runs of wall cells along z in each column; a run continuing the previous column's run
  // over the same z span extends its box.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> previous, current;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    current.clear();
    for (std::size_t j = 0; j + 1 < zs.size();) {
      if (!wall_cell(i, j)) {
        ++j;
        continue;
      }
      std::size_t k = j;
      while (k + 1 < zs.size() && wall_cell(i, k)) ++k;
      const auto run = std::make_pair(j, k);
      if (auto it = previous.find(run); it != previous.end()) {
        boxes[it->second].box.max.x() = xs[i + 1];
        current[run] = it->second;
      } else {
        current[run] = boxes.size();
        boxes.push_back({"wall", {{xs[i], y0, zs[j]}, {xs[i + 1], y1, zs[k]}}, {}});
      }
      j = k;
    }
    std::swap(previous, current);
  }
}

void add_ceiling(const std::vector<Rect>& open, double thickness, double y,
                 std::vector<camera::SolidBox>& boxes) {
  for (const Rect& r : open) {
    const Rect g = r.grown(thickness);
    boxes.push_back({"ceiling", {{g.x0, y, g.z0}, {g.x1, y + 0.2, g.z1}}, {}});
  }
}

camera::Trajectory walk(const std::vector<Vector3d>& points, double speed) {
  std::vector<camera::Keyframe> keys;
  double t = 0, yaw = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vector3d d = points[i] - points[i - 1];
    if (std::hypot(d.x(), d.z()) > 1e-6) {
      yaw = std::atan2(d.x(), d.z()) * 180 / kPi;
      break;
    }
  }
  keys.push_back({t, points[0], yaw});
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vector3d d = points[i] - points[i - 1];
    if (d.norm() < 1e-9) continue;
    if (std::hypot(d.x(), d.z()) > 1e-6) {
      const double turn = std::remainder(std::atan2(d.x(), d.z()) * 180 / kPi - yaw, 360.0);
      if (std::abs(turn) > 1) {
        t += 0.4 * std::max(1.0, std::abs(turn) / 90);
        yaw += turn;
        keys.push_back({t, points[i - 1], yaw});
      }
    }
    t += d.norm() / speed;
    keys.push_back({t, points[i], yaw});
  }
  return camera::Trajectory(std::move(keys));
}

std::string family_scene_name(const char* family, std::uint64_t seed) {
  return std::string(family) + "-seed-" + std::to_string(seed);
}

camera::Scene finish(std::string name, std::string description, std::vector<camera::SolidBox> boxes,
                     const std::vector<Vector3d>& path, double speed,
                     std::vector<camera::Mover> movers) {
  return finish(std::move(name), std::move(description), std::move(boxes), walk(path, speed),
                std::move(movers));
}

camera::Scene finish(std::string name, std::string description, std::vector<camera::SolidBox> boxes,
                     camera::Trajectory trajectory, std::vector<camera::Mover> movers) {
  camera::Scene scene(std::move(name), std::move(boxes), {}, camera::CharacterShape{},
                      std::move(trajectory), 60);
  scene.set_description(std::move(description));
  scene.set_movers(std::move(movers));
  for (std::size_t f = 0; f < scene.frame_count(); ++f) {
    const double t = scene.frame_time(f);
    const camera::Aabb body = scene.character().body_at(scene.character_at(t).position);
    if (auto hit = scene.solid_overlapping(body)) {
      throw std::logic_error(scene.name() + ": the walk enters solid box #" + std::to_string(*hit) +
                             " at t = " + std::to_string(t));
    }
    for (const camera::Mover& m : scene.movers()) {
      const camera::Aabb b = m.box_at(t);
      const double gap =
          std::max({b.min.x() - body.max.x(), body.min.x() - b.max.x(), b.min.z() - body.max.z(),
                    body.min.z() - b.max.z(), b.min.y() - body.max.y(), body.min.y() - b.max.y()});
      if (gap < 0.3) {
        throw std::logic_error(scene.name() + ": mover " + m.name() +
                               " meets the walk at t = " + std::to_string(t));
      }
    }
  }
  place_camera_start(scene);
  return scene;
}

void place_camera_start(camera::Scene& scene) {
  const double start = scene.trajectory().start_time();
  camera::SceneAtTime now(scene);
  now.set_time(start);
  const camera::CharacterState c = scene.character_at(start);
  const Vector3d look = scene.character().look_at(c.position);
  for (double f = 1.0; f > 0.05; f -= 0.05) {
    const Vector3d p = look + f * Vector3d(-4 * c.facing().x(), 1.0, -4 * c.facing().z());
    if (now.clearance(p, 0.5) >= 0.4 && now.line_of_sight(p, look)) {
      scene.set_camera_start(p);
      break;
    }
  }
}

}  // namespace sightline::experiments::scene_building
