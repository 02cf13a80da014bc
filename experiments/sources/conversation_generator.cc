#include "sightline/experiments/sources/conversation_generator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/sources/scripted_people.h"

namespace sightline::experiments {

std::string conversation_yaml(const ConversationOptions& o) {
  Draw draw(o.seed);
  const double T = std::max(6.0, o.seconds);
  const int layout = o.layout >= 0 ? o.layout % 4 : draw.integer(0, 3);
  const double cx = draw.uniform(-5, 5), cz = draw.uniform(-5, 5), theta = draw.uniform(0, 2 * M_PI);
  const double ux = std::cos(theta), uz = std::sin(theta);  // the scene's main direction
  const char* names[] = {"ann", "ben", "cat"};
  std::vector<Person> people;
  double enter_at = -1, arrive_at = -1;
  if (layout == 0 || layout == 3) {
    const bool three = layout == 0 && draw.uniform(0, 1) < 0.4;
    if (three) {
      const double r = draw.uniform(1.1, 1.6);
      for (int i = 0; i < 3; ++i) {
        const double a = theta + i * 2 * M_PI / 3 + draw.uniform(-0.25, 0.25);
        const double x = cx + r * std::cos(a), z = cz + r * std::sin(a);
        const double yaw = yaw_toward(x, z, cx, cz);
        people.push_back({names[i], {{0, x, z, yaw}, {T, x, z, yaw}}});
      }
    } else {
      const double d = draw.uniform(1.4, 2.6) / 2;
      const double ax = cx - d * ux, az = cz - d * uz, bx = cx + d * ux, bz = cz + d * uz;
      people.push_back({"ann", {{0, ax, az, yaw_toward(ax, az, bx, bz)}, {T, ax, az, yaw_toward(ax, az, bx, bz)}}});
      people.push_back({"ben", {{0, bx, bz, yaw_toward(bx, bz, ax, az)}, {T, bx, bz, yaw_toward(bx, bz, ax, az)}}});
    }
    if (layout == 3) {
      // cat comes in from 7-9 m away, to the third corner of a triangle with the two.
      const double side = draw.uniform(0, 1) < 0.5 ? 1 : -1;
      const double px = -uz * side, pz = ux * side;  // perpendicular to ann-ben
      const double far = draw.uniform(7, 9), stop = draw.uniform(1.3, 1.7);
      const double sx = cx + px * far + ux * draw.uniform(-3, 3), sz = cz + pz * far + uz * draw.uniform(-3, 3);
      const double ex = cx + px * stop, ez = cz + pz * stop;
      enter_at = draw.uniform(std::min(5.0, T / 4), std::min(10.0, T / 3));
      arrive_at = enter_at + std::hypot(ex - sx, ez - sz) / draw.uniform(1.1, 1.5);
      const double walk = yaw_toward(sx, sz, ex, ez), face = yaw_toward(ex, ez, cx, cz);
      people.push_back({"cat", {{0, sx, sz, walk}, {enter_at, sx, sz, walk}, {arrive_at, ex, ez, face},
                                {std::max(T, arrive_at + 1), ex, ez, face}}});
    }
  } else if (layout == 1) {
    const double v = draw.uniform(1.0, 1.5);
    const double yaw = yaw_toward(0, 0, ux, uz);
    for (int i = 0; i < 2; ++i) {
      const double off = i == 0 ? -0.55 : 0.55;
      const double x0 = cx - uz * off, z0 = cz + ux * off;
      people.push_back({names[i], {{0, x0, z0, yaw}, {T, x0 + ux * v * T, z0 + uz * v * T, yaw}}});
    }
  } else {
    const double r = draw.uniform(2.0, 3.0), period = draw.uniform(16, 30);
    const double turn = draw.uniform(0, 1) < 0.5 ? 1 : -1;
    Person a{"ann", {}}, b{"ben", {}};
    const int per_turn = 12;
    const int keys = static_cast<int>(std::ceil(T / period * per_turn));
    for (int k = 0; k <= keys; ++k) {
      const double t = std::min(T, k * period / per_turn);
      const double ang = theta + turn * 2 * M_PI * t / period;
      const double bx = cx + r * std::cos(ang), bz = cz + r * std::sin(ang);
      // Yaws unwrapped so each step turns the short way.
      double by = yaw_toward(bx, bz, cx, cz), ay = yaw_toward(cx, cz, bx, bz);
      if (!b.path.empty()) {
        while (by - b.path.back().yaw > 180) by -= 360;
        while (by - b.path.back().yaw < -180) by += 360;
        while (ay - a.path.back().yaw > 180) ay -= 360;
        while (ay - a.path.back().yaw < -180) ay += 360;
      }
      a.path.push_back({t, cx, cz, ay});
      b.path.push_back({t, bx, bz, by});
      if (t >= T) break;
    }
    people = {a, b};
  }
  // Pillars: 1-5, never within 1.3 m of anyone's path.
  const std::string pillars = pillars_yaml(draw, people, draw.integer(1, 5), 6, 1.3);
  // The script: lines of 1.5-7 s with pauses of 0-0.6 s; cat's entrance an action.
  std::ostringstream script;
  double t = draw.uniform(0.2, 0.8);
  int speaker = 0, last = -1;
  while (t < T - 1.8) {
    if (enter_at >= 0 && t >= enter_at - 1 && t < arrive_at) {
      t = std::max(t, enter_at);
      script << "  - {t: [" << num(t) << ", " << num(arrive_at) << "], action: cat}\n";
      t = arrive_at + draw.uniform(0, 0.4);
      continue;
    }
    const int talking = enter_at >= 0 && t < enter_at ? 2 : static_cast<int>(people.size());
    if (talking == 2) {
      speaker = last < 0 ? draw.integer(0, 1) : draw.uniform(0, 1) < 0.85 ? 1 - last : last;
    } else {
      speaker = draw.integer(0, talking - 1);
      if (speaker == last && draw.uniform(0, 1) < 0.7) speaker = (speaker + 1) % talking;
    }
    const int to = talking == 2 ? 1 - speaker : (speaker + draw.integer(1, talking - 1)) % talking;
    const double length = std::min(draw.uniform(1.5, 7), T - 0.2 - t);
    if (length < 1.0) break;
    script << "  - {t: [" << num(t) << ", " << num(t + length) << "], speaker: " << people[speaker].name
           << ", to: " << people[to].name << "}\n";
    last = speaker;
    t += length + (draw.uniform(0, 1) < 0.6 ? 0 : draw.uniform(0.1, 0.6));
  }
  static const char* kLayouts[] = {"standing", "walking side by side", "one circling the other",
                                   "a third comes in and joins"};
  std::ostringstream out;
  out << "name: conversation-" << o.seed << "\n"
      << "description: a generated conversation of " << people.size() << " people, " << kLayouts[layout]
      << " (seed " << o.seed << ")\nframe_rate: 30\nactors:\n";
  out << actors_yaml(people).substr(std::string("actors:\n").size());
  if (!pillars.empty()) out << "boxes:\n" << pillars;
  out << "script:\n" << script.str();
  return out.str();
}

camera::Scene generate_conversation(const ConversationOptions& options) {
  const std::string text = conversation_yaml(options);
  return camera::parse_scene(csp::parse_yaml(text, "conversation-" + std::to_string(options.seed)));
}

}  // namespace sightline::experiments
