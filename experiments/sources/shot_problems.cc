#include "sightline/experiments/sources/shot_problems.h"

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <vector>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::experiments {
namespace {

constexpr double kPi = 3.14159265358979323846;
const char* kKinds[] = {"close-up", "medium", "over-the-shoulder", "two-shot", "group",
                        "establishing"};

std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", v);
  return text;
}

struct Person {
  std::string name;
  Eigen::Vector2d at;  // feet (x, z)
  double yaw = 0;
};

struct Box {
  Eigen::Vector3d min, max;
};

bool overlaps(const Box& b, const Eigen::Vector2d& p, double margin) {
  return p.x() > b.min.x() - margin && p.x() < b.max.x() + margin && p.y() > b.min.z() - margin &&
         p.y() < b.max.z() + margin;
}

// The kind of problem `seed` is: people count 1-4, then a shot that needs no more people.
int people_of(std::uint64_t seed) { return static_cast<int>((seed - 1) % 4) + 1; }
int kind_of(std::uint64_t seed) {
  const int people = people_of(seed);
  const int k = static_cast<int>(((seed - 1) / 4) % 6);
  if (people == 1 && k >= 2) return k % 2;  // one person: close-up or medium
  return k;
}

}  // namespace

std::string shot_problem_kind(std::uint64_t seed) { return kKinds[kind_of(seed)]; }

std::string shot_problem_yaml(std::uint64_t seed) {
  std::mt19937_64 rng(seed * 7919 + 17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int count = people_of(seed);
  const int kind = kind_of(seed);
  const char* names[] = {"ann", "ben", "cal", "dee"};
  // People: in a 5 m square, at least 1.1 m apart.
  std::vector<Person> people;
  while (static_cast<int>(people.size()) < count) {
    const Eigen::Vector2d p(-2.5 + 5 * u(rng), -2.5 + 5 * u(rng));
    bool apart = true;
    for (const Person& q : people) apart = apart && (q.at - p).norm() >= 1.1;
    if (apart) people.push_back({names[people.size()], p, 0});
  }
  Eigen::Vector2d centre(0, 0);
  for (const Person& p : people) centre += p.at;
  centre /= count;
  for (Person& p : people) {
    const Eigen::Vector2d to = count > 1 ? Eigen::Vector2d(centre - p.at) : Eigen::Vector2d(u(rng) - 0.5, u(rng) - 0.5);
    p.yaw = std::atan2(to.x(), to.y()) * 180 / kPi + (u(rng) - 0.5) * 60;
  }
  if (kind == 2) {
    // Over the shoulder is a conversation: the two face each other (within 10 degrees).
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector2d to = people[static_cast<std::size_t>(1 - i)].at - people[static_cast<std::size_t>(i)].at;
      people[static_cast<std::size_t>(i)].yaw = std::atan2(to.x(), to.y()) * 180 / kPi + (u(rng) - 0.5) * 20;
    }
  }
  // Obstacles, kept 0.6 m from everyone's feet: furniture, pillars, a wall with a doorway.
  std::vector<Box> boxes;
  auto clear_of_people = [&](const Box& b) {
    for (const Person& p : people) {
      if (overlaps(b, p.at, 0.6)) return false;
    }
    return true;
  };
  const int furniture = 2 + static_cast<int>(u(rng) * 4);
  for (int i = 0, tries = 0; i < furniture && tries < 200; ++tries) {
    const Eigen::Vector3d c(-6 + 12 * u(rng), 0, -6 + 12 * u(rng));
    const Eigen::Vector3d half(0.25 + 0.5 * u(rng), 0, 0.25 + 0.5 * u(rng));
    Box b{c - half, c + half + Eigen::Vector3d(0, 0.4 + 0.8 * u(rng), 0)};
    if (clear_of_people(b)) {
      boxes.push_back(b);
      ++i;
    }
  }
  const int pillars = static_cast<int>(u(rng) * 4);
  for (int i = 0, tries = 0; i < pillars && tries < 200; ++tries) {
    const Eigen::Vector3d c(-6 + 12 * u(rng), 0, -6 + 12 * u(rng));
    Box b{c - Eigen::Vector3d(0.2, 0, 0.2), c + Eigen::Vector3d(0.2, 3, 0.2)};
    if (clear_of_people(b)) {
      boxes.push_back(b);
      ++i;
    }
  }
  if (u(rng) < 0.5) {
    // A wall along x at z = w with a 1.2 m doorway, 3-5 m from the centre.
    const double w = (u(rng) < 0.5 ? -1 : 1) * (3 + 2 * u(rng));
    const double door = -2 + 4 * u(rng);
    Box left{{-9, 0, w - 0.1}, {door - 0.6, 2.8, w + 0.1}};
    Box right{{door + 0.6, 0, w - 0.1}, {9, 2.8, w + 0.1}};
    for (const Box& b : {left, right}) {
      if (clear_of_people(b)) boxes.push_back(b);
    }
  }

  std::ostringstream y;
  y << "name: shot-problem-" << seed << "\n";
  y << "description: " << kKinds[kind] << " of " << count << (count == 1 ? " person" : " people")
    << " (generated, seed " << seed << ")\n";
  y << "boxes:\n";
  if (boxes.empty()) y << "  []\n";
  for (const Box& b : boxes) {
    y << "  - {min: [" << num(b.min.x()) << ", " << num(b.min.y()) << ", " << num(b.min.z())
      << "], max: [" << num(b.max.x()) << ", " << num(b.max.y()) << ", " << num(b.max.z()) << "]}\n";
  }
  y << "actors:\n";
  for (const Person& p : people) {
    y << "  - {name: " << p.name << ", trajectory: [{t: 0, position: [" << num(p.at.x())
      << ", 0, " << num(p.at.y()) << "], yaw: " << num(p.yaw) << "}]}\n";
  }
  y << "shot:\n  fov: 50\n  region: {min: [-9, 0.3, -9], max: [9, 5, 9]}\n  clearance: 0.3\n";
  y << "  properties:\n";
  const std::string a = people[0].name;
  const std::string b = count > 1 ? people[1].name : a;
  const double side = u(rng) < 0.5 ? 0.333 : 0.667;
  switch (kind) {
    case 0:  // close-up
      y << "    - {kind: size, target: " << a << ", range: [0.7, 0.95]}\n"
        << "    - {kind: screen_position, target: " << a << ", at: [" << side << ", 0.6]}\n"
        << "    - {kind: angle_horizontal, target: " << a << ", range: [-30, 30], weight: 2}\n"
        << "    - {kind: visible, target: " << a << ", range: [0.7, 1], hard: true}\n";
      break;
    case 1:  // medium
      y << "    - {kind: size, target: " << a << ", range: [0.4, 0.6]}\n"
        << "    - {kind: screen_position, target: " << a << ", at: [0.5, 0.55]}\n"
        << "    - {kind: angle_horizontal, target: " << a << ", range: [-45, 45]}\n"
        << "    - {kind: angle_vertical, target: " << a << ", range: [-5, 15]}\n"
        << "    - {kind: visible, target: " << a << ", range: [0.8, 1], hard: true}\n";
      break;
    case 2:  // over the shoulder: behind a, at b
      y << "    - {kind: angle_horizontal, target: " << b << ", range: [-35, 35], weight: 2}\n"
        << "    - {kind: angle_horizontal, target: " << a << ", range: [140, -140]}\n"
        << "    - {kind: screen_position, target: " << a << ", at: [0.25, 0.5]}\n"
        << "    - {kind: screen_position, target: " << b << ", at: [0.667, 0.55]}\n"
        << "    - {kind: framed, target: " << a << ", range: [0.3, 1]}\n"
        << "    - {kind: visible, target: " << b << ", range: [0.9, 1], hard: true}\n";
      break;
    case 3:  // two-shot
      y << "    - {kind: screen_position, target: " << a << ", at: [0.333, 0.6]}\n"
        << "    - {kind: screen_position, target: " << b << ", at: [0.667, 0.6]}\n"
        << "    - {kind: size, target: " << a << ", range: [0.3, 0.6]}\n"
        << "    - {kind: angle_vertical, target: " << a << ", range: [0, 20]}\n"
        << "    - {kind: visible, target: " << a << ", range: [0.8, 1], hard: true}\n"
        << "    - {kind: visible, target: " << b << ", range: [0.8, 1], hard: true}\n";
      break;
    default: {  // group (4) and establishing (5): everyone framed
      const bool establishing = kind == 5;
      const int shown = count >= 3 && !establishing ? count - 1 : count;  // group: one excluded
      for (int i = 0; i < shown; ++i) {
        const std::string& n = people[static_cast<std::size_t>(i)].name;
        y << "    - {kind: framed, target: " << n << ", rect: [0.05, 0.05, 0.95, 0.95]}\n"
          << "    - {kind: visible, target: " << n << ", range: [0.6, 1]}\n";
        if (establishing) y << "    - {kind: size, target: " << n << ", range: [0.1, 0.25]}\n";
      }
      if (shown < count) {
        y << "    - {kind: framed, target: " << people.back().name
          << ", range: [0, 0], weight: 2}\n";  // must stay out
      }
      y << "    - {kind: angle_vertical, target: " << a << ", range: ["
        << (establishing ? "15, 45" : "5, 30") << "]}\n";
      if (count > 1) y << "    - {kind: order, targets: [" << a << ", " << b << "]}\n";
    }
  }
  return y.str();
}

camera::Scene shot_problem(std::uint64_t seed) {
  return camera::parse_scene(csp::parse_yaml(shot_problem_yaml(seed),
                                             "shot-problem-" + std::to_string(seed) + ".yaml"));
}

}  // namespace sightline::experiments
