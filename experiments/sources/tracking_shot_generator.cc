#include "sightline/experiments/sources/tracking_shot_generator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/sources/scripted_people.h"

namespace sightline::experiments {
namespace {

// The layout is drawn in its own frame (u along the main direction, w across it) and turned
// into the scene by one of four rotations, so boxes stay axis-aligned.
struct Turn {
  int quarter = 0;
  double x(double u, double w) const { return quarter == 0 ? u : quarter == 1 ? -u : quarter == 2 ? w : -w; }
  double z(double u, double w) const { return quarter == 0 ? w : quarter == 1 ? -w : quarter == 2 ? -u : u; }
  // A box over [u0, u1] x [w0, w1], y in [y0, y1].
  std::string box(const std::string& name, double u0, double w0, double u1, double w1, double y0, double y1) const {
    return box_yaml(name, x(u0, w0), y0, z(u0, w0), x(u1, w1), y1, z(u1, w1));
  }
  Key key(double t, double u, double w, double yaw_u, double yaw_w) const {
    return {t, x(u, w), z(u, w), yaw_toward(0, 0, x(yaw_u, yaw_w), z(yaw_u, yaw_w))};
  }
};

struct Layout {
  std::string description;
  std::vector<Person> people;
  std::string boxes, movers, shot;
};

std::string region(const Turn& turn, double u0, double w0, double u1, double w1, double y0, double y1) {
  const double x0 = turn.x(u0, w0), z0 = turn.z(u0, w0), x1 = turn.x(u1, w1), z1 = turn.z(u1, w1);
  return "  region: {min: [" + num(std::min(x0, x1)) + ", " + num(y0) + ", " + num(std::min(z0, z1)) +
         "], max: [" + num(std::max(x0, x1)) + ", " + num(y1) + ", " + num(std::max(z0, z1)) + "]}\n";
}

// 0: a pair walking along a street past columns, a vehicle on the street side.
Layout street(Draw& draw, const Turn& turn, double T) {
  Layout out;
  const double v = draw.uniform(1.1, 1.7), L = v * T;
  const bool behind = draw.chance(0.5);  // one behind the other, else ben farther from the street
  const double ben_u = behind ? -draw.uniform(1.0, 1.5) : 0, ben_w = behind ? 0 : draw.uniform(0.8, 1.1);
  out.people.push_back({"ann", {turn.key(0, -L / 2, 0, 1, 0), turn.key(T, L / 2, 0, 1, 0)}});
  out.people.push_back({"ben", {turn.key(0, -L / 2 + ben_u, ben_w, 1, 0), turn.key(T, L / 2 + ben_u, ben_w, 1, 0)}});
  const double dc = draw.uniform(1.2, 2.0);  // the columns' line, on the street side
  double front = -1.0;                       // where the camera's region ends toward the people
  const bool columns = draw.chance(0.75);
  if (columns) {
    const double spacing = draw.uniform(3, 5), c = draw.uniform(0.3, 0.5) / 2, h = draw.uniform(3.5, 5);
    for (double u = -L / 2 - 6 + draw.uniform(0, spacing); u < L / 2 + 6; u += spacing) {
      out.boxes += turn.box("column", u - c, -dc - c, u + c, -dc + c, 0, h);
    }
    front = -dc - c - 0.3;
  }
  if (draw.chance(0.7)) {
    const double wall = ben_w + draw.uniform(2.0, 3.0);
    out.boxes += turn.box("building", -L / 2 - 12, wall, L / 2 + 12, wall + 2, 0, draw.uniform(6, 10));
  }
  if (draw.chance(0.7)) {
    const double lane = -dc - draw.uniform(3.5, 5.5), length = draw.uniform(4, 10);
    const double speed = draw.uniform(6, 11), start = draw.uniform(0, T / 2);
    const double sign = draw.chance(0.5) ? 1 : -1, from = -sign * (L / 2 + 25), to = sign * (L / 2 + 25);
    const double sx = turn.quarter < 2 ? length : 2.3, sz = turn.quarter < 2 ? 2.3 : length;
    out.movers = "  - name: vehicle\n    size: [" + num(sx) + ", " + num(draw.uniform(1.6, 3.2)) + ", " +
                 num(sz) + "]\n    path:\n      - {t: " + num(start) + ", position: [" +
                 num(turn.x(from, lane)) + ", 0, " + num(turn.z(from, lane)) + "]}\n      - {t: " +
                 num(start + std::abs(to - from) / speed) + ", position: [" + num(turn.x(to, lane)) +
                 ", 0, " + num(turn.z(to, lane)) + "]}\n";
  }
  const double lo = draw.uniform(0.5, 0.7), size = draw.uniform(0.2, 0.3);
  out.shot = "  fov: 50\n" + region(turn, -L / 2 - 10, -dc - 9, L / 2 + 10, front, 0.5, 6) +
             "  properties:\n"
             "    - {kind: framed, target: ann, rect: [0.1, 0.1, 0.9, 0.9]}\n"
             "    - {kind: framed, target: ben, rect: [0.1, 0.1, 0.9, 0.9]}\n"
             "    - {kind: visible, target: ann, range: [" + num(lo) + ", 1], weight: 2}\n"
             "    - {kind: visible, target: ben, range: [" + num(lo) + ", 1], weight: 2}\n"
             "    - {kind: size, target: ann, range: [" + num(size) + ", " + num(size + 0.2) + "]}\n"
             "    - {kind: angle_horizontal, target: ann, range: [60, 120]}\n";
  out.description = std::string("a pair walking along a street") + (columns ? " past columns" : "") +
                    (out.movers.empty() ? "" : ", a vehicle passing") + "; a two-shot from the street side";
  return out;
}

// 1: one chasing another round the corner of a building.
Layout corner_chase(Draw& draw, const Turn& turn, double T) {
  Layout out;
  const double v = draw.uniform(2.5, 4), gap = draw.uniform(2, 4), l1 = draw.uniform(6, 10);
  const double l2 = gap + v * T - l1 + 2;
  // The path: along +u to the corner at (0, 0), then along +w.
  const auto person = [&](const std::string& name, double s0) {
    Person p{name, {}};
    const auto at = [&](double t, double s) {
      p.path.push_back(s <= l1 ? turn.key(t, -l1 + s, 0, 1, 0) : turn.key(t, 0, s - l1, 0, 1));
    };
    at(0, s0);
    if (s0 < l1 && s0 + v * T > l1) {
      const double tc = (l1 - s0) / v;
      at(tc - 0.25, l1 - 0.25 * v);  // a rounded corner: a quarter second each side
      at(tc + 0.25, l1 + 0.25 * v);
    }
    at(T, s0 + v * T);
    return p;
  };
  out.people = {person("ann", 0), person("ben", gap)};
  const double inner = draw.uniform(1.2, 2.0);
  out.boxes += turn.box("building", -l1 - 8, inner, -inner, l2 + 8, 0, draw.uniform(6, 10));
  if (draw.chance(0.6)) out.boxes += turn.box("wall", -l1 - 8, -draw.uniform(4, 6) - 1, draw.uniform(4, 6) + 1, -4, 0, 8);
  out.boxes += pillars_yaml(draw, out.people, draw.integer(0, 3), 5, 1.2);
  const double lo = draw.uniform(0.5, 0.7);
  out.shot = "  fov: 55\n" + region(turn, -l1 - 8, -3.8, 8, l2 + 8, 0.5, 5) +
             "  clearance: 0.3\n  properties:\n"
             "    - {kind: framed, target: ann, rect: [0.05, 0.05, 0.95, 0.95]}\n"
             "    - {kind: framed, target: ben, rect: [0.05, 0.05, 0.95, 0.95]}\n"
             "    - {kind: visible, target: ann, range: [" + num(lo) + ", 1]}\n"
             "    - {kind: visible, target: ben, range: [" + num(lo) + ", 1]}\n"
             "    - {kind: size, target: ann, range: [0.25, 0.5]}\n"
             "    - {kind: angle_vertical, target: ann, range: [5, 25]}\n";
  out.description = "one running after another round the corner of a building; a two-shot";
  return out;
}

// 2: three or four crossing a square.
Layout crossing(Draw& draw, const Turn& turn, double T) {
  Layout out;
  const char* names[] = {"ann", "ben", "cal", "dee"};
  const double R = draw.uniform(7, 9), a0 = draw.uniform(0, 2 * M_PI);
  const int count = draw.chance(0.4) ? 4 : 3;
  for (int i = 0; i < count; ++i) {
    const double a = a0 + i * 2 * M_PI / count + draw.uniform(-0.4, 0.4);
    const double b = a + M_PI + draw.uniform(-0.7, 0.7);
    const double u0 = R * std::cos(a), w0 = R * std::sin(a), u1 = R * std::cos(b), w1 = R * std::sin(b);
    out.people.push_back({names[i], {turn.key(0, u0, w0, u1 - u0, w1 - w0), turn.key(T, u1, w1, u1 - u0, w1 - w0)}});
  }
  const auto paths = path_points(out.people);
  // A fountain, one or two kiosks and up to three lamps, each where it touches no path.
  struct Thing {
    const char* name;
    double half, height;
    int count;
  };
  const Thing things[] = {{"fountain", draw.uniform(0.8, 1.5), 1.2, 1},
                          {"kiosk", 1.0, 3.0, draw.integer(1, 2)},
                          {"lamp", 0.1, 4.0, draw.integer(0, 3)}};
  for (const Thing& thing : things) {
    for (int k = 0, tries = 0; k < thing.count && tries < 100; ++tries) {
      const double u = draw.uniform(-R, R), w = draw.uniform(-R, R), h = thing.half;
      if (!clear_of(paths, turn.x(u - h, w - h), turn.z(u - h, w - h), turn.x(u + h, w + h), turn.z(u + h, w + h), 1.0)) continue;
      out.boxes += turn.box(thing.name, u - h, w - h, u + h, w + h, 0, thing.height);
      ++k;
    }
  }
  out.shot = "  fov: [40, 70]\n" + region(turn, -R - 7, -R - 7, R + 7, R + 7, 1, 8) +
             "  properties:\n"
             "    - {kind: angle_vertical, target: ben, range: [15, 40]}\n"
             "    - {kind: size, target: ben, range: [0.15, 0.35]}\n";
  for (const Person& p : out.people) {
    out.shot += "    - {kind: framed, target: " + p.name + ", rect: [0.05, 0.05, 0.95, 0.95]}\n"
                "    - {kind: visible, target: " + p.name + ", range: [0.6, 1]}\n";
  }
  out.description = std::string(count == 4 ? "four" : "three") + " people crossing a square, each their own way; a group shot";
  return out;
}

// 3: one circling another, over the shoulder of the one who circles.
Layout circling(Draw& draw, const Turn& turn, double T) {
  Layout out;
  const double r = draw.uniform(1.5, 2.5), period = draw.uniform(8, 16), a0 = draw.uniform(0, 2 * M_PI);
  const double sense = draw.chance(0.5) ? 1 : -1;
  Person a{"ann", {}}, b{"ben", {}};
  const int keys = static_cast<int>(std::ceil(T / period * 16));
  for (int k = 0; k <= keys; ++k) {
    const double t = std::min(T, k * T / keys), ang = a0 + sense * 2 * M_PI * t / period;
    const double bu = r * std::cos(ang), bw = r * std::sin(ang);
    Key ka = turn.key(t, 0, 0, bu, bw), kb = turn.key(t, bu, bw, -bu, -bw);
    if (!a.path.empty()) {  // yaws unwrapped, so each step turns the short way
      while (ka.yaw - a.path.back().yaw > 180) ka.yaw -= 360;
      while (ka.yaw - a.path.back().yaw < -180) ka.yaw += 360;
      while (kb.yaw - b.path.back().yaw > 180) kb.yaw -= 360;
      while (kb.yaw - b.path.back().yaw < -180) kb.yaw += 360;
    }
    a.path.push_back(ka);
    b.path.push_back(kb);
  }
  out.people = {a, b};
  out.boxes = pillars_yaml(draw, out.people, draw.integer(1, 4), 5, 1.3);
  out.shot = "  fov: 45\n" + region(turn, -r - 6, -r - 6, r + 6, r + 6, 0.5, 3) +
             "  properties:\n"
             "    - {kind: angle_horizontal, target: ann, range: [-35, 35], weight: 2}\n"
             "    - {kind: screen_position, target: ann, at: [0.6, 0.6]}\n"
             "    - {kind: screen_position, target: ben, at: [0.25, 0.5]}\n"
             "    - {kind: framed, target: ben, range: [0.3, 1]}\n"
             "    - {kind: visible, target: ann, range: [0.9, 1]}\n"
             "    - {kind: size, target: ann, range: [0.4, 0.7]}\n";
  out.description = "one circling another, who turns to face them; over the shoulder of the one circling";
  return out;
}

}  // namespace

std::string tracking_shot_yaml(const TrackingShotOptions& o) {
  Draw draw(o.seed * 7919 + 17);
  const double T = std::max(4.0, o.seconds);
  const int layout = o.layout >= 0 ? o.layout % 4 : draw.integer(0, 3);
  const Turn turn{draw.integer(0, 3)};
  const Layout l = layout == 0 ? street(draw, turn, T)
                   : layout == 1 ? corner_chase(draw, turn, T)
                   : layout == 2 ? crossing(draw, turn, T)
                                 : circling(draw, turn, T);
  std::ostringstream out;
  out << "name: tracking-shot-" << o.seed << "\n"
      << "description: " << l.description << " (generated, seed " << o.seed << ")\n"
      << "frame_rate: 30\n"
      << actors_yaml(l.people);
  if (!l.boxes.empty()) out << "boxes:\n" << l.boxes;
  if (!l.movers.empty()) out << "movers:\n" << l.movers;
  out << "shot:\n" << l.shot;
  return out.str();
}

camera::Scene generate_tracking_shot(const TrackingShotOptions& options) {
  return camera::parse_scene(
      csp::parse_yaml(tracking_shot_yaml(options), "tracking-shot-" + std::to_string(options.seed)));
}

}  // namespace sightline::experiments
