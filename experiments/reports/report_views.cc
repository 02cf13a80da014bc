#include "sightline/experiments/reports/report_views.h"

#include <stb_image_write.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "sightline/domains/camera/scene_at_time.h"
#include "sightline/experiments/reports/report_movers.h"

namespace sightline::experiments {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

// A 2D orthographic view: world axes (u_axis, v_axis) mapped to pixels, v flipped when
// `v_up` (so y grows upward in the side view).
struct PlaneView {
  int u_axis = 0, v_axis = 2;
  bool v_up = false;
  double u0 = 0, v0 = 0, scale = 1;  // world minimum corner and pixels per metre
  int width = 0, height = 0;
  double margin = 24;

  double px(const Eigen::Vector3d& p) const { return margin + (p[u_axis] - u0) * scale; }
  double py(const Eigen::Vector3d& p) const {
    return v_up ? height - margin - (p[v_axis] - v0) * scale : margin + (p[v_axis] - v0) * scale;
  }
};

PlaneView fit_view(const camera::Scene& scene, const RunDrawing& run, int u_axis, int v_axis,
                   bool v_up, int width) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  auto grow = [&](const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const TraceRow& r : *run.trace) {
    grow(r.character);
    grow(r.character + Eigen::Vector3d(0, scene.character().size.y(), 0));
    grow(r.camera);
  }
  // The geometry near the action, not a whole generated city: boxes within 6 m of the paths.
  const Eigen::Vector3d near_lo = (lo.array() - 6).matrix(), near_hi = (hi.array() + 6).matrix();
  for (const auto& s : scene.solids()) {
    if ((s.box.max.array() >= near_lo.array()).all() && (s.box.min.array() <= near_hi.array()).all()) {
      grow(s.box.min.cwiseMax(near_lo));
      grow(s.box.max.cwiseMin(near_hi));
    }
  }
  // The ground is always in the side view of box scenes; a level has its own floors.
  if (scene.level() == nullptr) grow(Eigen::Vector3d(lo.x(), 0, lo.z()));
  PlaneView view;
  view.u_axis = u_axis;
  view.v_axis = v_axis;
  view.v_up = v_up;
  view.u0 = lo[u_axis] - 0.5;
  view.v0 = lo[v_axis] - 0.5;
  const double du = hi[u_axis] - lo[u_axis] + 1, dv = hi[v_axis] - lo[v_axis] + 1;
  view.width = width;
  view.scale = (width - 2 * view.margin) / du;
  view.height = static_cast<int>(std::ceil(dv * view.scale + 2 * view.margin));
  if (view.height > width * 1.2) {  // very tall: fit the height instead
    view.height = static_cast<int>(width * 1.2);
    view.scale = (view.height - 2 * view.margin) / dv;
  }
  return view;
}

// An arrow from a to b in pixels: a line and a small head.
void arrow(std::ostringstream& out, double ax, double ay, double bx, double by,
           const std::string& colour, double stroke) {
  const double dx = bx - ax, dy = by - ay, len = std::hypot(dx, dy);
  if (len < 1e-6) return;
  const double ux = dx / len, uy = dy / len, head = std::min(6.0, len * 0.6);
  out << "<line x1='" << num(ax) << "' y1='" << num(ay) << "' x2='" << num(bx) << "' y2='"
      << num(by) << "' stroke='" << colour << "' stroke-width='" << stroke << "'/>";
  out << "<polygon fill='" << colour << "' points='" << num(bx) << ',' << num(by) << ' '
      << num(bx - head * ux + head * 0.5 * uy) << ',' << num(by - head * uy - head * 0.5 * ux)
      << ' ' << num(bx - head * ux - head * 0.5 * uy) << ','
      << num(by - head * uy + head * 0.5 * ux) << "'/>";
}

void write_to_vector(void* context, void* data, int size);

// A level drawn under a top or side view, ray cast through Scene::first_hit one ray per
// pixel. Top view: a section looking down from 2.5 m above the highest point of the
// character's path (so ceilings and roofs above the walk are cut away), surfaces shaded by
// height from dark (low) to light (high). Side view: a section looking along the depth axis
// from 1 m before the nearest point of the paths, shaded by how far the surface is behind
// the section plane and by its slope.
std::vector<unsigned char> level_backdrop_png(const camera::Scene& scene, const RunDrawing& run,
                                              const PlaneView& view) {
  const std::vector<TraceRow>& trace = *run.trace;
  const int depth_axis = 3 - view.u_axis - view.v_axis;
  double path_top = -INFINITY, path_bottom = INFINITY, depth_near = INFINITY;
  for (const TraceRow& r : trace) {
    path_top = std::max({path_top, r.character.y(), r.camera.y()});
    path_bottom = std::min({path_bottom, r.character.y(), r.camera.y()});
    depth_near = std::min({depth_near, r.character[depth_axis], r.camera[depth_axis]});
  }
  const double cut = path_top + 2.5;
  const double span = std::max(1.0, cut - (path_bottom - 3));
  constexpr double kDepth = 40;  // metres the side section looks into
  std::vector<unsigned char> pixels(static_cast<std::size_t>(view.width) * view.height * 3);
  for (int j = 0; j < view.height; ++j) {
    for (int i = 0; i < view.width; ++i) {
      Eigen::Vector3d origin = Eigen::Vector3d::Zero();
      origin[view.u_axis] = view.u0 + (i + 0.5 - view.margin) / view.scale;
      const double v = view.v_up ? (view.height - view.margin - (j + 0.5)) / view.scale
                                 : (j + 0.5 - view.margin) / view.scale;
      origin[view.v_axis] = view.v0 + v;
      Eigen::Vector3d end = origin;
      if (view.v_up) {
        origin[depth_axis] = depth_near - 1;
        end[depth_axis] = depth_near - 1 + kDepth;
      } else {
        origin.y() = cut;
        end.y() = path_bottom - 60;
      }
      Eigen::Vector3d colour(0.984, 0.980, 0.969);  // the page's background: nothing there
      if (const auto hit = scene.first_hit(origin, end)) {
        const double light = 0.55 + 0.45 * std::abs(hit->normal.y());
        double shade;
        if (view.v_up) {
          shade = 0.85 - 0.5 * std::min(1.0, hit->t);  // near: light, far: dark
        } else {
          const double height = cut + hit->t * (end.y() - cut);
          shade = 0.35 + 0.6 * std::clamp((height - (cut - span)) / span, 0.0, 1.0);
        }
        colour = light * shade * Eigen::Vector3d(0.92, 0.90, 0.86);
      }
      unsigned char* px = &pixels[(static_cast<std::size_t>(j) * view.width + i) * 3];
      for (int k = 0; k < 3; ++k) px[k] = static_cast<unsigned char>(std::clamp(colour[k], 0.0, 1.0) * 255);
    }
  }
  std::vector<unsigned char> png;
  stbi_write_png_to_func(&write_to_vector, &png, view.width, view.height, 3, pixels.data(),
                         view.width * 3);
  return png;
}

std::string plane_view_svg(const camera::Scene& scene, const RunDrawing& run,
                           const PlaneView& view, const std::string& title) {
  const std::vector<TraceRow>& trace = *run.trace;
  std::ostringstream out;
  out << "<svg width='" << view.width << "' height='"
      << view.height << "' viewBox='0 0 " << view.width << ' ' << view.height
      << "' font-family='sans-serif' font-size='10'>";
  out << "<rect width='100%' height='100%' fill='#fbfaf7' stroke='#999'/>";
  out << "<text x='6' y='13' fill='#333'>" << html_escape(title) << "</text>";
  auto rect = [&](const camera::Aabb& b, const std::string& style) {
    const double x0 = view.px(b.min), x1 = view.px(b.max);
    const double y0 = view.py(b.min), y1 = view.py(b.max);
    out << "<rect x='" << num(std::min(x0, x1)) << "' y='" << num(std::min(y0, y1))
        << "' width='" << num(std::abs(x1 - x0)) << "' height='" << num(std::abs(y1 - y0))
        << "' " << style << "/>";
  };
  if (scene.level() != nullptr) {
    out << "<image x='0' y='0' width='" << view.width << "' height='" << view.height
        << "' href='data:image/png;base64," << base64(level_backdrop_png(scene, run, view))
        << "'/>";
  } else if (view.v_up) {  // the ground line
    const double gy = view.py(Eigen::Vector3d::Zero());
    out << "<line x1='0' x2='" << view.width << "' y1='" << num(gy) << "' y2='" << num(gy)
        << "' stroke='#8a7' stroke-width='1.5'/>";
  }
  // Areas, dashed; then boxes, lower ones first in the top view, translucent in the side view.
  for (const auto& a : scene.areas()) {
    const std::string colour = a.kind == camera::AreaKind::kEnclosed ? "#2b8a3e" : "#1098ad";
    rect(a.box, "fill='none' stroke='" + colour + "' stroke-dasharray='5,3'");
    Eigen::Vector3d corner = a.box.min;
    if (view.v_up) corner[1] = a.box.max.y();
    out << "<text x='" << num(view.px(corner) + 2) << "' y='" << num(view.py(corner) + (view.v_up ? 10 : -2))
        << "' fill='" << colour << "'>" << html_escape(a.name) << "</text>";
  }
  std::vector<const camera::SolidBox*> boxes;
  for (const auto& s : scene.solids()) boxes.push_back(&s);
  std::sort(boxes.begin(), boxes.end(), [](auto* a, auto* b) { return a->box.max.y() < b->box.max.y(); });
  for (const camera::SolidBox* s : boxes) {
    const double h = std::clamp(s->box.max.y() / 6.0, 0.0, 1.0);
    const int shade = static_cast<int>(190 - 100 * h);
    char style[96];
    std::snprintf(style, sizeof style, "fill='rgb(%d,%d,%d)' fill-opacity='%s' stroke='#555'",
                  shade, shade, shade + 8, view.v_up ? "0.45" : "0.9");
    rect(s->box, style);
  }
  out << movers_svg(scene, run, [&](const Eigen::Vector3d& p) {
    return Eigen::Vector2d(view.px(p), view.py(p));
  });
  // Paths, subsampled to at most ~400 points each.
  const std::size_t stride = std::max<std::size_t>(1, trace.size() / 400);
  auto path = [&](auto point, const std::string& colour, double width) {
    out << "<polyline fill='none' stroke='" << colour << "' stroke-width='" << width << "' points='";
    for (std::size_t i = 0; i < trace.size(); i += stride) {
      const Eigen::Vector3d p = point(trace[i]);
      out << num(view.px(p)) << ',' << num(view.py(p)) << ' ';
    }
    out << "'/>";
  };
  const double look_height = scene.character().look_at_height;
  path([&](const TraceRow& r) { return Eigen::Vector3d(r.character + Eigen::Vector3d(0, view.v_up ? look_height : 0, 0)); },
       "#1c7ed6", 2);
  path([](const TraceRow& r) { return r.camera; }, run.colour, 1.5);
  // Arrows about once a second: the character's facing, the camera's view direction.
  const std::size_t every = std::max<std::size_t>(1, trace.size() / std::max<std::size_t>(1, static_cast<std::size_t>(trace.back().t - trace.front().t + 1)));
  for (std::size_t i = 0; i < trace.size(); i += every) {
    const TraceRow& r = trace[i];
    const double yaw = r.character_yaw * kPi / 180;
    const Eigen::Vector3d base = r.character + Eigen::Vector3d(0, view.v_up ? look_height : 0, 0);
    const Eigen::Vector3d tip = base + 0.9 * Eigen::Vector3d(std::sin(yaw), 0, std::cos(yaw));
    arrow(out, view.px(base), view.py(base), view.px(tip), view.py(tip), "#1c7ed6", 1.5);
    Eigen::Vector3d look = r.target - r.camera;
    if (look.norm() > 1e-9) {
      look = r.camera + 1.0 * look.normalized();
      arrow(out, view.px(r.camera), view.py(r.camera), view.px(look), view.py(look), run.colour, 1);
    }
  }
  for (std::size_t i = 0; i < trace.size(); ++i) {
    if (i < run.occluded.size() && run.occluded[i] && (i % 2 == 0)) {
      out << "<circle cx='" << num(view.px(trace[i].camera)) << "' cy='"
          << num(view.py(trace[i].camera)) << "' r='2' fill='#e03131'/>";
    }
    if (trace[i].cut) {
      out << "<circle cx='" << num(view.px(trace[i].camera)) << "' cy='"
          << num(view.py(trace[i].camera)) << "' r='5' fill='none' stroke='#c2255c' stroke-width='2'/>";
    }
  }
  // Start markers.
  out << "<circle cx='" << num(view.px(trace.front().camera)) << "' cy='" << num(view.py(trace.front().camera))
      << "' r='3' fill='" << run.colour << "'/>";
  // A one-metre scale bar.
  out << "<line x1='" << view.width - 10 - view.scale << "' x2='" << view.width - 10 << "' y1='"
      << view.height - 8 << "' y2='" << view.height - 8 << "' stroke='#333' stroke-width='2'/>"
      << "<text x='" << num(view.width - 10 - view.scale) << "' y='" << view.height - 11
      << "' fill='#333'>1 m</text>";
  out << "</svg>";
  return out.str();
}

// Ray against the character's body: entry distance along d (unit), or +inf.
double ray_box(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const camera::Aabb& b) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-12) {
      if (o[k] < b.min[k] || o[k] > b.max[k]) return std::numeric_limits<double>::infinity();
      continue;
    }
    double a = (b.min[k] - o[k]) / d[k], c = (b.max[k] - o[k]) / d[k];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

void write_to_vector(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<unsigned char>*>(context);
  const auto* p = static_cast<const unsigned char*>(data);
  bytes->insert(bytes->end(), p, p + size);
}

}  // namespace

std::string top_view_svg(const camera::Scene& scene, const RunDrawing& run, int width) {
  if (!run.trace || run.trace->empty()) return "";
  return plane_view_svg(scene, run, fit_view(scene, run, 0, 2, false, width),
                        "top view (x right, z down)");
}

std::string side_view_svg(const camera::Scene& scene, const RunDrawing& run, int width) {
  if (!run.trace || run.trace->empty()) return "";
  double x_lo = 1e300, x_hi = -1e300, z_lo = 1e300, z_hi = -1e300;
  for (const TraceRow& r : *run.trace) {
    x_lo = std::min(x_lo, r.character.x());
    x_hi = std::max(x_hi, r.character.x());
    z_lo = std::min(z_lo, r.character.z());
    z_hi = std::max(z_hi, r.character.z());
  }
  const int u = (x_hi - x_lo) >= (z_hi - z_lo) ? 0 : 2;
  return plane_view_svg(scene, run, fit_view(scene, run, u, 1, true, width),
                        std::string("side view (") + (u == 0 ? "x" : "z") + " right, y up)");
}

std::vector<unsigned char> camera_view_png(const camera::Scene& scene, const TraceRow& row,
                                           bool occluded, int width, int height) {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
  const Eigen::Vector3d eye = row.camera;
  Eigen::Vector3d forward = row.target - eye;
  if (forward.norm() < 1e-9) forward = Eigen::Vector3d::UnitZ();
  forward.normalize();
  Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitY());
  if (right.norm() < 1e-9) right = Eigen::Vector3d::UnitX();
  right.normalize();
  const Eigen::Vector3d up = right.cross(forward);
  const double half_h = std::tan(30.0 * kPi / 180), half_w = half_h * width / height;
  const Eigen::Vector3d light = Eigen::Vector3d(0.4, 0.9, 0.3).normalized();
  const camera::Aabb body = scene.character().body_at(row.character);
  const bool has_level = scene.level() != nullptr;
  // Movers where they were at this frame's time (a SceneAtTime answers for them too).
  camera::SceneAtTime at(scene);
  at.set_time(row.t);
  constexpr double kFar = 200;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double sx = (2.0 * (i + 0.5) / width - 1) * half_w;
      const double sy = (1 - 2.0 * (j + 0.5) / height) * half_h;
      const Eigen::Vector3d d = (forward + sx * right + sy * up).normalized();
      double best = kFar;
      Eigen::Vector3d colour(0.70 + 0.2 * sy, 0.82 + 0.1 * sy, 0.95);  // sky
      Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
      Eigen::Vector3d base = Eigen::Vector3d::Zero();
      int what = 0;  // 0 sky, 1 ground, 2 box, 3 character
      // The checkered ground at y = 0 stands in for the floor of box scenes; a level has
      // its own floors.
      if (!has_level && d.y() < -1e-9 && eye.y() > 0) {
        best = -eye.y() / d.y();
        what = 1;
      }
      if (const auto hit = at.first_hit(eye, eye + kFar * d); hit && hit->t * kFar < best) {
        best = hit->t * kFar;
        what = 2;
        normal = hit->normal.squaredNorm() > 0 ? hit->normal : Eigen::Vector3d(-d);
        if (hit->source == camera::SurfaceHit::Source::kMover) {
          base = Eigen::Vector3d(0.40, 0.42, 0.86);  // movers blue, apart from walls and her
        } else if (hit->source == camera::SurfaceHit::Source::kBox) {
          const unsigned h = static_cast<unsigned>(hit->index) * 2654435761u;
          const double tint = ((h >> 8) & 0xff) / 255.0 * 0.15;
          base = Eigen::Vector3d(0.72 + tint, 0.68 + tint * 0.5, 0.60);
        } else {
          // Level surfaces: floors greenish grey, walls warm grey, by how much they face up.
          const double up_facing = std::abs(normal.y());
          base = up_facing > 0.7 ? Eigen::Vector3d(0.60, 0.64, 0.56)
                                 : Eigen::Vector3d(0.74, 0.69, 0.62);
        }
      }
      if (const double tc = ray_box(eye, d, body); tc < best) {
        best = tc;
        what = 3;
        normal = body.nearest_face_normal(eye + tc * d);
        base = Eigen::Vector3d(1.0, 0.45, 0.1);
      }
      if (what == 1) {
        const Eigen::Vector3d p = eye + best * d;
        const bool dark = (static_cast<long>(std::floor(p.x())) + static_cast<long>(std::floor(p.z()))) & 1;
        base = dark ? Eigen::Vector3d(0.55, 0.62, 0.50) : Eigen::Vector3d(0.62, 0.69, 0.56);
      }
      if (what != 0) {
        const double lambert = 0.45 + 0.55 * std::max(0.0, normal.dot(light));
        const double fog = std::min(1.0, best / 80.0);
        colour = (1 - fog) * lambert * base + fog * Eigen::Vector3d(0.8, 0.85, 0.9);
      }
      unsigned char* px = &pixels[(static_cast<std::size_t>(j) * width + i) * 3];
      for (int k = 0; k < 3; ++k) px[k] = static_cast<unsigned char>(std::clamp(colour[k], 0.0, 1.0) * 255);
    }
  }
  // A cross at the look-at point (the image centre), a red border when it is hidden.
  auto set = [&](int i, int j, unsigned char r, unsigned char g, unsigned char b) {
    if (i < 0 || j < 0 || i >= width || j >= height) return;
    unsigned char* px = &pixels[(static_cast<std::size_t>(j) * width + i) * 3];
    px[0] = r, px[1] = g, px[2] = b;
  };
  for (int k = -4; k <= 4; ++k) {
    set(width / 2 + k, height / 2, 255, 255, 255);
    set(width / 2, height / 2 + k, 255, 255, 255);
  }
  if (occluded) {
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < width; ++i) { set(i, k, 224, 49, 49); set(i, height - 1 - k, 224, 49, 49); }
      for (int j = 0; j < height; ++j) { set(k, j, 224, 49, 49); set(width - 1 - k, j, 224, 49, 49); }
    }
  }
  std::vector<unsigned char> png;
  stbi_write_png_to_func(&write_to_vector, &png, width, height, 3, pixels.data(), width * 3);
  return png;
}

std::string line_plot_svg(const std::string& title, const std::vector<PlotSeries>& series,
                          int width, int height) {
  double t0 = 1e300, t1 = -1e300, v0 = 0, v1 = -1e300;
  for (const PlotSeries& s : series) {
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      t0 = std::min(t0, s.t[i]);
      t1 = std::max(t1, s.t[i]);
      if (std::isfinite(s.v[i])) {
        v0 = std::min(v0, s.v[i]);
        v1 = std::max(v1, s.v[i]);
      }
    }
  }
  if (!(t1 > t0)) t1 = t0 + 1;
  if (!(v1 > v0)) v1 = v0 + 1;
  const double left = 48, right = 8, top = 20, bottom = 22 + 14.0 * ((series.size() + 2) / 3);
  const double pw = width - left - right, ph = height - top - bottom;
  auto X = [&](double t) { return left + (t - t0) / (t1 - t0) * pw; };
  auto Y = [&](double v) { return top + ph - (v - v0) / (v1 - v0) * ph; };
  std::ostringstream out;
  out << "<svg width='" << width << "' height='" << height
      << "' font-family='sans-serif' font-size='10'><rect width='100%' height='100%' fill='#fff'/>"
      << "<text x='" << left << "' y='13' fill='#333'>" << html_escape(title) << "</text>"
      << "<rect x='" << left << "' y='" << top << "' width='" << num(pw) << "' height='" << num(ph)
      << "' fill='none' stroke='#bbb'/>";
  for (int k = 0; k <= 4; ++k) {
    const double v = v0 + (v1 - v0) * k / 4, t = t0 + (t1 - t0) * k / 4;
    char label[32];
    std::snprintf(label, sizeof label, "%.3g", v);
    out << "<text x='" << left - 3 << "' y='" << num(Y(v) + 3) << "' text-anchor='end' fill='#555'>"
        << label << "</text><line x1='" << left << "' x2='" << num(left + pw) << "' y1='" << num(Y(v))
        << "' y2='" << num(Y(v)) << "' stroke='#eee'/>";
    std::snprintf(label, sizeof label, "%.3g s", t);
    out << "<text x='" << num(X(t)) << "' y='" << num(top + ph + 12) << "' text-anchor='middle' fill='#555'>"
        << label << "</text>";
  }
  for (std::size_t s = 0; s < series.size(); ++s) {
    const PlotSeries& p = series[s];
    const std::size_t stride = std::max<std::size_t>(1, p.t.size() / 500);
    out << "<path fill='none' stroke='" << p.colour << "' stroke-width='1.2' d='";
    bool pen_down = false;
    for (std::size_t i = 0; i < p.t.size(); i += stride) {
      if (!std::isfinite(p.v[i])) {
        pen_down = false;
        continue;
      }
      out << (pen_down ? 'L' : 'M') << num(X(p.t[i])) << ',' << num(Y(p.v[i])) << ' ';
      pen_down = true;
    }
    out << "'/>";
    const double lx = left + (s % 3) * (pw / 3), ly = top + ph + 26 + 14.0 * (s / 3);
    out << "<rect x='" << num(lx) << "' y='" << num(ly - 8) << "' width='10' height='3' fill='"
        << p.colour << "'/><text x='" << num(lx + 14) << "' y='" << num(ly - 4) << "' fill='#333'>"
        << html_escape(p.label) << "</text>";
  }
  out << "</svg>";
  return out.str();
}

std::string base64(const std::vector<unsigned char>& bytes) {
  using namespace boost::archive::iterators;
  using Encoder = base64_from_binary<transform_width<std::vector<unsigned char>::const_iterator, 6, 8>>;
  // Encode a zero-padded copy (transform_width must not read past the end), then turn the
  // characters that only encode padding into '='.
  const std::size_t pad = (3 - bytes.size() % 3) % 3;
  std::vector<unsigned char> padded(bytes);
  padded.resize(bytes.size() + pad, 0);
  std::string out(Encoder(padded.cbegin()), Encoder(padded.cend()));
  for (std::size_t i = 0; i < pad; ++i) out[out.size() - 1 - i] = '=';
  return out;
}

}  // namespace sightline::experiments
