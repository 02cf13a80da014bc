#include "sightline/experiments/sources/scripted_people.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sightline::experiments {

double Draw::uniform(double lo, double hi) {
  state_ += 0x9E3779B97F4A7C15ull;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return lo + (hi - lo) * static_cast<double>(z >> 11) / 9007199254740992.0;
}

int Draw::integer(int lo, int hi) { return std::min(hi, lo + static_cast<int>(uniform(0, hi - lo + 1))); }

std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", std::abs(v) < 5e-4 ? 0.0 : v);
  return text;
}

double yaw_toward(double x0, double z0, double x1, double z1) {
  return std::atan2(x1 - x0, z1 - z0) * 180 / M_PI;
}

std::vector<std::pair<double, double>> path_points(const Person& p) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < p.path.size(); ++i) {
    out.emplace_back(p.path[i].x, p.path[i].z);
    if (i + 1 == p.path.size()) break;
    const double dx = p.path[i + 1].x - p.path[i].x, dz = p.path[i + 1].z - p.path[i].z;
    const int steps = static_cast<int>(std::hypot(dx, dz) / 0.5);
    for (int s = 1; s < steps; ++s) {
      out.emplace_back(p.path[i].x + dx * s / steps, p.path[i].z + dz * s / steps);
    }
  }
  return out;
}

std::vector<std::pair<double, double>> path_points(const std::vector<Person>& people) {
  std::vector<std::pair<double, double>> out;
  for (const Person& p : people) {
    for (const auto& q : path_points(p)) out.push_back(q);
  }
  return out;
}

bool clear_of(const std::vector<std::pair<double, double>>& points, double x0, double z0, double x1,
              double z1, double keep_off) {
  return std::all_of(points.begin(), points.end(), [&](const auto& q) {
    const double dx = std::max({0.0, std::min(x0, x1) - q.first, q.first - std::max(x0, x1)});
    const double dz = std::max({0.0, std::min(z0, z1) - q.second, q.second - std::max(z0, z1)});
    return std::hypot(dx, dz) > keep_off;
  });
}

std::string actors_yaml(const std::vector<Person>& people) {
  std::ostringstream out;
  out << "actors:\n";
  for (const Person& p : people) {
    out << "  - name: " << p.name << "\n    trajectory:\n";
    for (const Key& k : p.path) {
      out << "      - {t: " << num(k.t) << ", position: [" << num(k.x) << ", 0, " << num(k.z)
          << "], yaw: " << num(k.yaw) << "}\n";
    }
  }
  return out.str();
}

std::string box_yaml(const std::string& name, double x0, double y0, double z0, double x1, double y1, double z1) {
  return "  - {name: " + name + ", min: [" + num(std::min(x0, x1)) + ", " + num(y0) + ", " +
         num(std::min(z0, z1)) + "], max: [" + num(std::max(x0, x1)) + ", " + num(y1) + ", " +
         num(std::max(z0, z1)) + "]}\n";
}

std::string pillars_yaml(Draw& draw, const std::vector<Person>& people, int count, double spread,
                         double keep_off) {
  const std::vector<std::pair<double, double>> paths = path_points(people);
  std::string out;
  for (int i = 0, tries = 0; i < count && tries < 200 && !paths.empty(); ++tries) {
    const auto& near = paths[static_cast<std::size_t>(draw.integer(0, static_cast<int>(paths.size()) - 1))];
    const double px = near.first + draw.uniform(-spread, spread), pz = near.second + draw.uniform(-spread, spread);
    const double w = draw.uniform(0.3, 0.8) / 2, h = draw.uniform(2.5, 4);
    if (!clear_of(paths, px - w, pz - w, px + w, pz + w, keep_off)) continue;
    out += box_yaml("pillar", px - w, 0, pz - w, px + w, h, pz + w);
    ++i;
  }
  return out;
}

}  // namespace sightline::experiments
