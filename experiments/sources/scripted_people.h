// Scripted people for the seeded scene generators (conversations, tracking shots): a seeded
// random draw that makes the same scene on every machine, people as keyframed paths, and
// their YAML text (FORMATS.md "Actors"); pillars placed off everyone's path.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sightline::experiments {

// A small generator of our own (splitmix64), so a seed makes the same scene everywhere.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 0x1234567ull) {}
  double uniform(double lo, double hi);
  int integer(int lo, int hi);  // in [lo, hi]
  bool chance(double p) { return uniform(0, 1) < p; }

 private:
  std::uint64_t state_;
};

struct Key {
  double t, x, z, yaw;  // seconds; feet on the ground at (x, 0, z); degrees
};

struct Person {
  std::string name;
  std::vector<Key> path;
};

// "%.3f", with -0 written as 0.
std::string num(double v);
// The yaw (degrees, 0 along +z, 90 along +x) facing from (x0, z0) toward (x1, z1).
double yaw_toward(double x0, double z0, double x1, double z1);
// Points along a person's path every half metre (and at each key); along everyone's.
std::vector<std::pair<double, double>> path_points(const Person& person);
std::vector<std::pair<double, double>> path_points(const std::vector<Person>& people);
// Every point more than `keep_off` metres from the rectangle [x0, x1] x [z0, z1] (corners
// in any order).
bool clear_of(const std::vector<std::pair<double, double>>& points, double x0, double z0, double x1,
              double z1, double keep_off);
// The `actors:` block of a scene file.
std::string actors_yaml(const std::vector<Person>& people);
// One `boxes:` entry.
std::string box_yaml(const std::string& name, double x0, double y0, double z0, double x1, double y1, double z1);

// `count` pillars (0.3-0.8 m across, 2.5-4 m tall) within `spread` metres of the people's
// paths and never within `keep_off` metres of one, as `boxes:` entries.
std::string pillars_yaml(Draw& draw, const std::vector<Person>& people, int count, double spread,
                         double keep_off);

}  // namespace sightline::experiments
