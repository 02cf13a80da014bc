#include "experiments/scene_generator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "experiments/independent_check.h"

namespace sightline::experiments {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Distance from the box to the segment a-b in the ground plane (x, z), 0 if they meet.
double ground_distance(const camera::Aabb& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // Sample finely enough for the margins used here (boxes are >= 0.3 m across).
  double best = 1e18;
  const double length = (b - a).norm();
  const int steps = std::max(1, static_cast<int>(length / 0.1));
  for (int i = 0; i <= steps; ++i) {
    const Eigen::Vector3d p = a + (b - a) * (static_cast<double>(i) / steps);
    const double dx = std::max({box.min.x() - p.x(), 0.0, p.x() - box.max.x()});
    const double dz = std::max({box.min.z() - p.z(), 0.0, p.z() - box.max.z()});
    best = std::min(best, std::hypot(dx, dz));
  }
  return best;
}

// Keyframes walking through `points` at `speed`, facing the way of travel, turning on the
// spot at each waypoint.
camera::Trajectory walk(const std::vector<Eigen::Vector3d>& points, double speed) {
  std::vector<camera::Keyframe> keys;
  double t = 0;
  double yaw = std::atan2(points[1].x() - points[0].x(), points[1].z() - points[0].z()) * 180 / kPi;
  keys.push_back({t, points[0], yaw});
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - points[i - 1];
    double heading = std::atan2(d.x(), d.z()) * 180 / kPi;
    double turn = std::remainder(heading - yaw, 360.0);
    if (std::abs(turn) > 1e-6) {
      t += 0.4 * std::max(1.0, std::abs(turn) / 90);
      yaw += turn;
      keys.push_back({t, points[i - 1], yaw});
    }
    t += d.norm() / speed;
    keys.push_back({t, points[i], yaw});
  }
  return camera::Trajectory(std::move(keys));
}

camera::Scene finish(std::string name, std::vector<camera::SolidBox> boxes,
                     std::vector<camera::Area> areas, const std::vector<Eigen::Vector3d>& path,
                     double speed) {
  camera::Scene scene(std::move(name), std::move(boxes), std::move(areas),
                      camera::CharacterShape{}, walk(path, speed), 60);
  // Start the camera behind the character, lowered toward the character until it is clear.
  const camera::CharacterState c = scene.character_at(scene.trajectory().start_time());
  const Eigen::Vector3d look = scene.character().look_at(c.position);
  for (double f = 1.0; f > 0.05; f -= 0.05) {
    const Eigen::Vector3d p =
        look + f * (Eigen::Vector3d(-4 * c.facing().x(), 1.0, -4 * c.facing().z()));
    if (scene.clearance(p, 0.5) >= 0.4 && scene.line_of_sight(p, look)) {
      scene.set_camera_start(p);
      break;
    }
  }
  return scene;
}

}  // namespace

camera::Scene generate_pillar_forest(const GeneratedSceneOptions& options) {
  std::mt19937_64 rng(options.seed);
  const double side = std::sqrt(options.area_per_box * static_cast<double>(options.boxes));
  std::uniform_real_distribution<double> coordinate(-side / 2, side / 2);
  std::uniform_real_distribution<double> unit(0, 1);
  // The walk: random waypoints in the middle of the world, each leg a few metres.
  std::vector<Eigen::Vector3d> path{{0, 0, 0}};
  const double walk_length = options.walk_seconds * options.walk_speed;
  double length = 0;
  const double inner = std::min(side / 2 - 2, 30.0);
  while (length < walk_length) {
    const double angle = unit(rng) * 2 * kPi;
    const double leg = 3 + 5 * unit(rng);
    Eigen::Vector3d next = path.back() + leg * Eigen::Vector3d(std::sin(angle), 0, std::cos(angle));
    next.x() = std::clamp(next.x(), -inner, inner);
    next.z() = std::clamp(next.z(), -inner, inner);
    if ((next - path.back()).norm() < 1) continue;
    length += (next - path.back()).norm();
    path.push_back(next);
  }
  std::vector<camera::SolidBox> boxes;
  boxes.reserve(options.boxes);
  while (boxes.size() < options.boxes) {
    const bool wall = unit(rng) < 0.25;
    const double w = wall ? 2 + 4 * unit(rng) : 0.4 + 0.8 * unit(rng);
    const double d = wall ? 0.2 + 0.2 * unit(rng) : 0.4 + 0.8 * unit(rng);
    const bool along_x = unit(rng) < 0.5;
    const double sx = along_x ? w : d, sz = along_x ? d : w;
    const double h = wall ? 1 + 2.5 * unit(rng) : 2 + 6 * unit(rng);
    const Eigen::Vector3d centre(coordinate(rng), 0, coordinate(rng));
    camera::Aabb box{{centre.x() - sx / 2, 0, centre.z() - sz / 2},
                     {centre.x() + sx / 2, h, centre.z() + sz / 2}};
    bool clear = true;
    for (std::size_t i = 1; i < path.size() && clear; ++i) {
      clear = ground_distance(box, path[i - 1], path[i]) > 0.8;
    }
    if (clear) boxes.push_back({"box-" + std::to_string(boxes.size()), box, {}});
  }
  return finish("pillar-forest-" + std::to_string(options.boxes) + "-seed-" +
                    std::to_string(options.seed),
                std::move(boxes), {}, path, options.walk_speed);
}

camera::Scene generate_city(const GeneratedSceneOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const double block = 12, street = 6;  // a block and its street repeat every 18 m
  const double pitch = block + street;
  const int per_side = std::max(2, static_cast<int>(std::ceil(std::sqrt(options.boxes / 2.0))));
  const double origin = -per_side * pitch / 2;
  std::vector<camera::SolidBox> boxes;
  std::vector<camera::Area> areas;
  // Streets run along x at z = origin + k * pitch - street / 2 and along z likewise.
  for (int i = 0; i < per_side && boxes.size() < options.boxes; ++i) {
    for (int j = 0; j < per_side && boxes.size() < options.boxes; ++j) {
      const double x0 = origin + i * pitch, z0 = origin + j * pitch;
      const double height = 4 + 12 * unit(rng);
      boxes.push_back({"building-" + std::to_string(i) + "-" + std::to_string(j),
                       {{x0, 0, z0}, {x0 + block, height, z0 + block}}, {}});
      if (boxes.size() < options.boxes && unit(rng) < 0.4) {
        // An upper floor overhanging the street by 1.5 m, its underside 3 m up.
        boxes.push_back({"overhang-" + std::to_string(i) + "-" + std::to_string(j),
                         {{x0, 3, z0 - 1.5}, {x0 + block, std::min(height, 6.0), z0}}, {}});
      }
      if (boxes.size() < options.boxes && unit(rng) < 0.15) {
        // A covered passage over the street south of the block.
        const double zs = z0 - street;
        boxes.push_back({"passage-roof-" + std::to_string(i) + "-" + std::to_string(j),
                         {{x0 + 3, 3.2, zs}, {x0 + 7, 3.5, z0}}, {}});
        areas.push_back({"passage-" + std::to_string(i) + "-" + std::to_string(j),
                         camera::AreaKind::kSemiEnclosed,
                         {{x0 + 3, 0, zs}, {x0 + 7, 3.5, z0}}, {}});
      }
    }
  }
  // The walk: along street centre lines, turning at random crossings.
  auto street_line = [&](int k) { return origin + k * pitch - street / 2; };
  int ix = per_side / 2, iz = per_side / 2;
  std::vector<Eigen::Vector3d> path{{street_line(ix), 0, street_line(iz)}};
  double length = 0;
  const double walk_length = options.walk_seconds * options.walk_speed;
  bool along_x = true;
  while (length < walk_length) {
    const int steps = 1 + static_cast<int>(unit(rng) * 2);
    const int dir = unit(rng) < 0.5 ? -1 : 1;
    int& k = along_x ? ix : iz;
    const int target = std::clamp(k + dir * steps, 1, per_side - 1);
    if (target == k) {
      along_x = !along_x;
      continue;
    }
    k = target;
    const Eigen::Vector3d next(street_line(ix), 0, street_line(iz));
    length += (next - path.back()).norm();
    path.push_back(next);
    along_x = !along_x;
  }
  return finish("city-" + std::to_string(options.boxes) + "-seed-" + std::to_string(options.seed),
                std::move(boxes), std::move(areas), path, options.walk_speed);
}

}  // namespace sightline::experiments
