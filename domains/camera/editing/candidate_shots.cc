#include "sightline/domains/camera/editing/candidate_shots.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "sightline/domains/camera/editing/continuity.h"

namespace sightline::camera {
namespace {

constexpr double kFov = 40;  // degrees: the idioms' lens

ShotProperty property(const char* kind, std::vector<std::string> targets, ValueRange range,
                      double softness, double weight) {
  ShotProperty p;
  p.kind = kind;
  p.targets = std::move(targets);
  p.range = range;
  p.softness = softness;
  p.weight = weight;
  return p;
}

ShotProperty at_screen(const std::string& who, double x, double y, double weight) {
  ShotProperty p = property("screen_position", {who}, {0, 0.02}, 0.25, weight);
  p.at = {x, y};
  return p;
}

ShotProperty sized(const std::string& who, double lo, double hi, double weight = 1) {
  ShotProperty p = property("size", {who}, {lo, hi}, 0.25, weight);
  p.measure = "height";
  return p;
}

ShotProperty seen(const std::string& who, double lo, double weight) {
  return property("visible", {who}, {lo, 1}, 1, weight);
}

ShotProperty in_frame(const std::string& who, double lo, double weight,
                      Eigen::Vector4d rect = {0, 0, 1, 1}) {
  ShotProperty p = property("framed", {who}, {lo, 1}, 1, weight);
  p.rect = rect;
  return p;
}

// Where the idioms' cameras may stand: around everyone's path, 15 m out, 0.3 to 6 m up.
Aabb idiom_region(const Scene& scene) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  auto add_path = [&](const Trajectory& path) {
    for (const Keyframe& k : path.keyframes()) {
      lo = lo.cwiseMin(k.position);
      hi = hi.cwiseMax(k.position);
    }
  };
  if (scene.has_character()) add_path(scene.trajectory());
  for (const Actor& a : scene.actors()) add_path(a.trajectory);
  if (!std::isfinite(lo.x())) lo = hi = Eigen::Vector3d::Zero();
  return Aabb{{lo.x() - 15, 0.3, lo.z() - 15}, {hi.x() + 15, std::max(6.0, hi.y() + 4), hi.z() + 15}};
}

std::shared_ptr<Shot> idiom_shot(const Aabb& region, std::string name) {
  auto shot = std::make_shared<Shot>();
  shot->name = std::move(name);
  shot->fov = {kFov, kFov};
  shot->region = region;
  return shot;
}

double side_x(bool left, double offset) { return left ? 0.5 - offset : 0.5 + offset; }

Eigen::Vector3d ground(const Eigen::Vector3d& v) {
  Eigen::Vector3d g(v.x(), 0, v.z());
  const double n = g.norm();
  return n > 1e-9 ? Eigen::Vector3d(g / n) : Eigen::Vector3d(0, 0, 1);
}

Eigen::Vector3d turned(const Eigen::Vector3d& u, double degrees) {
  const double a = degrees * std::numbers::pi / 180;
  return {std::cos(a) * u.x() + std::sin(a) * u.z(), 0, -std::sin(a) * u.x() + std::cos(a) * u.z()};
}

double body_height(const PersonAtTime& p) { return std::max(0.1, p.body.max.y() - p.body.min.y()); }

// The distance at which a body of height h fills `size` of the image height.
double distance_for(double h, double size) {
  return h / (size * 2 * std::tan(kFov * std::numbers::pi / 360));
}

// Looks from `position` so the point q lands at screen point (x, y) (roughly: the local
// refinement does the rest).
CameraPose aimed(const Eigen::Vector3d& position, const Eigen::Vector3d& q, double x, double y) {
  CameraPose pose;
  pose.position = position;
  pose.fov = kFov;
  pose.look_at = q;
  const auto view = View::of(pose);
  if (!view) return pose;
  const double depth = (q - position).norm();
  const double tan_half = std::tan(kFov * std::numbers::pi / 360);
  // The screen centre sits (0.5 - x) image widths to the right of q and (0.5 - y) heights up.
  pose.look_at = q + view->right() * ((0.5 - x) * 2 * tan_half * pose.aspect * depth) +
                 view->up() * ((0.5 - y) * 2 * tan_half * depth);
  return pose;
}

}  // namespace

const char* to_string(Idiom idiom) {
  switch (idiom) {
    case Idiom::kNamed: return "named";
    case Idiom::kCloseUp: return "close-up";
    case Idiom::kMedium: return "medium";
    case Idiom::kOverShoulder: return "over-the-shoulder";
    case Idiom::kTwoShot: return "two-shot";
    case Idiom::kEstablishing: return "establishing";
  }
  return "?";
}

std::vector<CandidateShot> candidate_shots(const Scene& scene) {
  std::vector<CandidateShot> out;
  for (const auto& named : scene.named_shots()) {
    CandidateShot c;
    c.name = named->name;
    c.shot = named;
    out.push_back(std::move(c));
  }
  // The people and pairs the script names (everyone, and every pair, without one).
  std::vector<std::string> people;
  std::vector<std::pair<std::string, std::string>> pairs;
  auto add_person = [&](const std::string& who) {
    if (!who.empty() && std::find(people.begin(), people.end(), who) == people.end()) people.push_back(who);
  };
  if (const auto* script = scene.script(); script != nullptr && !script->empty()) {
    for (const ScriptEntry& e : *script) {
      add_person(e.speaker);
      add_person(e.to);
      add_person(e.action);
      if (e.speaker.empty()) continue;
      const auto pair = e.speaker < e.to ? std::make_pair(e.speaker, e.to) : std::make_pair(e.to, e.speaker);
      if (std::find(pairs.begin(), pairs.end(), pair) == pairs.end()) pairs.push_back(pair);
    }
  } else {
    if (scene.has_character()) add_person(scene.character_name());
    for (const Actor& a : scene.actors()) add_person(a.name);
    for (std::size_t i = 0; i < people.size(); ++i) {
      for (std::size_t j = i + 1; j < people.size(); ++j) pairs.emplace_back(people[i], people[j]);
    }
  }
  const Aabb region = idiom_region(scene);
  auto add = [&](Idiom idiom, const std::string& subject, const std::string& other, bool left,
                 std::shared_ptr<Shot> shot) {
    CandidateShot c;
    c.idiom = idiom;
    c.subject = subject;
    c.other = other;
    c.subject_left = left;
    c.name = shot->name;
    c.shot = std::move(shot);
    out.push_back(std::move(c));
  };
  for (const bool left : {true, false}) {
    const std::string side = left ? " (left)" : " (right)";
    for (const std::string& who : people) {
      auto close = idiom_shot(region, "close-up " + who + side);
      close->properties = {at_screen(who, side_x(left, 0.12), 0.6, 2), sized(who, 1.15, 1.5),
                           seen(who, 0.9, 3), in_frame(who, 0.55, 1)};
      add(Idiom::kCloseUp, who, "", left, close);
      auto medium = idiom_shot(region, "medium " + who + side);
      medium->properties = {at_screen(who, side_x(left, 0.15), 0.62, 2), sized(who, 0.75, 1.0),
                            seen(who, 0.9, 3), in_frame(who, 0.6, 1)};
      add(Idiom::kMedium, who, "", left, medium);
    }
    for (const auto& [a, b] : pairs) {
      for (const auto& [subject, shoulder] : {std::make_pair(a, b), std::make_pair(b, a)}) {
        auto ots = idiom_shot(region, "over-the-shoulder " + subject + " from " + shoulder + side);
        const Eigen::Vector4d half = left ? Eigen::Vector4d(0.55, 0, 1, 1) : Eigen::Vector4d(0, 0, 0.45, 1);
        ots->properties = {at_screen(subject, side_x(left, 0.15), 0.62, 2), sized(subject, 0.55, 0.8),
                           seen(subject, 0.9, 3), in_frame(shoulder, 0.15, 1, half)};
        add(Idiom::kOverShoulder, subject, shoulder, left, ots);
      }
      auto two = idiom_shot(region, "two-shot " + a + " " + b + side);
      two->properties = {at_screen(a, side_x(left, 1.0 / 6), 0.6, 1),
                         at_screen(b, side_x(!left, 1.0 / 6), 0.6, 1), sized(a, 0.45, 0.7),
                         sized(b, 0.45, 0.7), seen(a, 0.8, 2), seen(b, 0.8, 2)};
      add(Idiom::kTwoShot, a, b, left, two);
    }
    if (!people.empty()) {
      auto wide = idiom_shot(region, "establishing" + side);
      for (const std::string& who : people) {
        wide->properties.push_back(in_frame(who, 1, 2));
        wide->properties.push_back(seen(who, 0.6, 1));
        wide->properties.push_back(sized(who, 0.15, 0.4));
      }
      wide->properties.push_back(property("angle_vertical", {people.front()}, {10, 35}, 30, 1));
      add(Idiom::kEstablishing, people.front(), "", left, wide);
    }
  }
  return out;
}

int partner_at(const Scene& scene, const ShotWorld& world, int person, double t) {
  const auto& people = world.people();
  if (person < 0 || static_cast<std::size_t>(person) >= people.size()) return -1;
  if (const auto* script = scene.script(); script != nullptr) {
    std::optional<std::size_t> entry = line_of_action_entry(*script, t);
    if (!entry) {  // before the first line: the first line's pair
      for (std::size_t i = 0; i < script->size() && !entry; ++i) {
        if (!(*script)[i].speaker.empty()) entry = i;
      }
    }
    if (entry) {
      const ScriptEntry& e = (*script)[*entry];
      const std::string& other = people[person].name == e.speaker ? e.to : e.speaker;
      if (const auto found = world.find(other); found && *found != person) return *found;
    }
  }
  int nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < people.size(); ++i) {
    if (static_cast<int>(i) == person) continue;
    const double d = (people[i].aim - people[person].aim).norm();
    if (d < best) {
      best = d;
      nearest = static_cast<int>(i);
    }
  }
  return nearest;
}

namespace {

// The person the candidate's screen direction is kept against, or -1.
int reference_partner(const CandidateShot& c, const Scene& scene, const ShotWorld& world, int subject) {
  if (!c.other.empty()) {
    const auto other = world.find(c.other);
    return other ? *other : -1;
  }
  return partner_at(scene, world, subject, world.time());
}

}  // namespace

bool keeps_screen_direction(const CandidateShot& c, const Scene& scene, const ShotWorld& world,
                            const CameraPose& pose) {
  if (c.idiom == Idiom::kNamed) return true;
  const auto subject = world.find(c.subject);
  if (!subject) return true;
  const int partner = reference_partner(c, scene, world, *subject);
  if (partner < 0) return true;
  const auto view = View::of(pose);
  if (!view) return false;
  const double across = (world.people()[partner].aim - world.people()[*subject].aim).dot(view->right());
  return c.subject_left ? across > 0 : across < 0;
}

std::optional<CameraPose> idiom_start(const CandidateShot& c, const Scene& scene,
                                      const ShotWorld& world) {
  if (c.idiom == Idiom::kNamed) return std::nullopt;
  const auto subject = world.find(c.subject);
  if (!subject) return std::nullopt;
  const PersonAtTime& s = world.people()[*subject];
  const int partner = reference_partner(c, scene, world, *subject);
  const double yaw = s.yaw * std::numbers::pi / 180;
  const Eigen::Vector3d toward =
      partner >= 0 ? ground(world.people()[partner].aim - s.aim) : Eigen::Vector3d(std::sin(yaw), 0, std::cos(yaw));
  const double h = body_height(s);
  std::optional<CameraPose> best;
  // The two mirror placements; the one keeping screen direction wins.
  for (const double sign : {1.0, -1.0}) {
    CameraPose pose;
    switch (c.idiom) {
      case Idiom::kCloseUp:
      case Idiom::kMedium: {
        const bool close = c.idiom == Idiom::kCloseUp;
        const double d = distance_for(h, close ? 1.3 : 0.88);
        const Eigen::Vector3d p = s.aim + turned(toward, sign * (close ? 30 : 40)) * d;
        pose = aimed(p, s.aim, side_x(c.subject_left, close ? 0.12 : 0.15), close ? 0.6 : 0.62);
        break;
      }
      case Idiom::kOverShoulder: {
        if (partner < 0) return std::nullopt;
        const PersonAtTime& o = world.people()[partner];
        const Eigen::Vector3d lateral = turned(toward, 90) * sign;
        const Eigen::Vector3d p = o.aim + toward * 0.9 + lateral * 0.55 + Eigen::Vector3d(0, 0.1, 0);
        // toward points from the subject to the shoulder's owner: stand beyond them.
        pose = aimed(p, s.aim, side_x(c.subject_left, 0.15), 0.62);
        break;
      }
      case Idiom::kTwoShot:
      case Idiom::kEstablishing: {
        const bool wide = c.idiom == Idiom::kEstablishing;
        Eigen::Vector3d centre = s.aim;
        double spread = 0;
        if (wide) {
          centre = Eigen::Vector3d::Zero();
          for (const PersonAtTime& q : world.people()) centre += q.aim;
          centre /= static_cast<double>(world.people().size());
          for (const PersonAtTime& q : world.people()) spread = std::max(spread, 2 * (q.aim - centre).norm());
        } else if (partner >= 0) {
          centre = (s.aim + world.people()[partner].aim) / 2;
          spread = (s.aim - world.people()[partner].aim).norm();
        }
        const double tan_half = std::tan(kFov * std::numbers::pi / 360);
        const double d = std::max(distance_for(h, wide ? 0.25 : 0.55),
                                  spread / ((wide ? 0.8 : 0.5) * 2 * tan_half * 16.0 / 9.0));
        const Eigen::Vector3d p = centre + turned(toward, 90) * sign * d + Eigen::Vector3d(0, wide ? 2.5 : 0, 0);
        pose = aimed(p, centre, 0.5, 0.55);
        break;
      }
      case Idiom::kNamed: return std::nullopt;
    }
    if (!best) best = pose;
    if (keeps_screen_direction(c, scene, world, pose)) return pose;
  }
  return best;
}

}  // namespace sightline::camera
