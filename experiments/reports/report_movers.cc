#include "sightline/experiments/reports/report_movers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sightline::experiments {
namespace {

constexpr const char* kMoverColour = "#f08c00";

std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Convex hull (Andrew's monotone chain) of a few points, counter-clockwise.
std::vector<Eigen::Vector2d> hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

void corners(const camera::Aabb& b, const ToPixel& to_pixel, std::vector<Eigen::Vector2d>* out) {
  for (int c = 0; c < 8; ++c) {
    out->push_back(to_pixel(Eigen::Vector3d(c & 1 ? b.max.x() : b.min.x(),
                                            c & 2 ? b.max.y() : b.min.y(),
                                            c & 4 ? b.max.z() : b.min.z())));
  }
}

void polygon(std::ostringstream& out, const std::vector<Eigen::Vector2d>& points,
             const std::string& style) {
  out << "<polygon " << style << " points='";
  for (const Eigen::Vector2d& p : hull(points)) out << num(p.x()) << ',' << num(p.y()) << ' ';
  out << "'/>";
}

// The trace row nearest time t (rows are in time order).
const TraceRow& row_at(const std::vector<TraceRow>& trace, double t) {
  auto it = std::lower_bound(trace.begin(), trace.end(), t,
                             [](const TraceRow& r, double v) { return r.t < v; });
  if (it == trace.end()) return trace.back();
  if (it != trace.begin() && t - std::prev(it)->t < it->t - t) return *std::prev(it);
  return *it;
}

}  // namespace

std::vector<double> mover_mark_times(const RunDrawing& run, std::size_t limit) {
  if (run.trace == nullptr || run.trace->empty() || limit == 0) return {};
  const std::vector<TraceRow>& trace = *run.trace;
  std::vector<std::size_t> frames;
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const bool hidden = i < run.occluded.size() && run.occluded[i];
    const bool was_hidden = i > 0 && i - 1 < run.occluded.size() && run.occluded[i - 1];
    if ((hidden && !was_hidden) || trace[i].cut) frames.push_back(i);
  }
  if (frames.empty()) {
    for (std::size_t k = 0; k < 3; ++k) frames.push_back((2 * k + 1) * trace.size() / 6);
  }
  std::vector<double> times;
  if (frames.size() <= limit) {
    for (std::size_t f : frames) times.push_back(trace[f].t);
  } else {
    for (std::size_t k = 0; k < limit; ++k) times.push_back(trace[frames[k * frames.size() / limit]].t);
  }
  return times;
}

std::string movers_svg(const camera::Scene& scene, const RunDrawing& run, const ToPixel& to_pixel,
                       double near) {
  if (scene.movers().empty() || run.trace == nullptr || run.trace->empty()) return "";
  std::ostringstream out;
  out << "<g class='movers'>";
  // Where each mover goes: the area its box sweeps between keyframes, and its base's path.
  for (const camera::Mover& m : scene.movers()) {
    const auto& path = m.path();
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
      std::vector<Eigen::Vector2d> points;
      corners(m.box_at(path[k].t), to_pixel, &points);
      corners(m.box_at(path[k + 1].t), to_pixel, &points);
      polygon(out, points, std::string("fill='") + kMoverColour + "' fill-opacity='0.07'");
    }
    out << "<polyline fill='none' stroke='" << kMoverColour
        << "' stroke-opacity='0.45' stroke-dasharray='3,3' points='";
    for (const camera::MoverKeyframe& key : path) {
      const Eigen::Vector2d p = to_pixel(key.position);
      out << num(p.x()) << ',' << num(p.y()) << ' ';
    }
    out << "'/>";
  }
  // Where the movers near the character were at the marked times.
  for (double t : mover_mark_times(run)) {
    const Eigen::Vector3d& feet = row_at(*run.trace, t).character;
    for (const camera::Mover& m : scene.movers()) {
      const camera::Aabb box = m.box_at(t);
      const double dx = std::max({box.min.x() - feet.x(), 0.0, feet.x() - box.max.x()});
      const double dz = std::max({box.min.z() - feet.z(), 0.0, feet.z() - box.max.z()});
      if (std::hypot(dx, dz) > near) continue;
      std::vector<Eigen::Vector2d> points;
      corners(box, to_pixel, &points);
      polygon(out, points,
              std::string("fill='") + kMoverColour + "' fill-opacity='0.35' stroke='" +
                  kMoverColour + "' stroke-width='1.2'");
      const Eigen::Vector2d label = to_pixel(box.max);
      char text[32];
      std::snprintf(text, sizeof text, "%.1f s", t);
      out << "<text x='" << num(label.x() + 1) << "' y='" << num(label.y() - 1)
          << "' font-size='8' fill='#a05a00'>" << text << "</text>";
    }
  }
  out << "</g>";
  return out.str();
}

}  // namespace sightline::experiments
