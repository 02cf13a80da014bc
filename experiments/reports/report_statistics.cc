#include "sightline/experiments/reports/report_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <utility>
#include <vector>

#include "sightline/experiments/reports/report_views.h"

namespace sightline::experiments {
namespace {

const char* kPalette[] = {"#d9480f", "#5f3dc4", "#2b8a3e", "#c2255c", "#1864ab",
                          "#e67700", "#087f5b", "#862e9c", "#495057", "#a61e4d"};

std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

std::string tick_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

// A linear or logarithmic (base 10) mapping of [lo, hi] onto pixels, with its ticks.
struct Axis {
  double lo = 0, hi = 1;
  bool log = false;

  double fraction(double v) const {
    v = std::clamp(v, lo, hi);
    return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
               : (v - lo) / (hi - lo);
  }

  // Linear: steps of 1, 2 or 5 x 10^k, at most about 6 (integers only when `integral`).
  // Log: each power of 10, with 2 and 5 times it when the axis spans less than 3 decades.
  std::vector<double> ticks(bool integral = false) const {
    std::vector<double> out;
    if (log) {
      const bool fine = std::log10(hi / lo) < 3.0;
      for (int k = static_cast<int>(std::floor(std::log10(lo))); k <= std::ceil(std::log10(hi));
           ++k) {
        for (double m : {1.0, 2.0, 5.0}) {
          if (m != 1.0 && !fine) continue;
          const double v = m * std::pow(10.0, k);
          if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) out.push_back(v);
        }
      }
      return out;
    }
    const double raw = (hi - lo) / 5.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    double step = power;
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
      step = m * power;
      if (step >= raw) break;
    }
    if (integral) step = std::max(1.0, std::round(step));
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) out.push_back(v);
    return out;
  }
};

struct Series {
  std::string label;
  std::vector<std::pair<double, double>> points;  // data coordinates
};

// A framed plot: title, axes with ticks and labels, one polyline per series, a legend on the
// right. Every coordinate is clamped into the plotting area, so all lie in the viewBox.
std::string chart_svg(const std::string& title, const Axis& x, const std::string& x_label,
                      const Axis& y, bool y_integral, const std::string& y_label,
                      const std::vector<Series>& series, const StatisticsFigureOptions& options) {
  const double width = options.width, height = options.height;
  const double left = 56, right = 170, top = 26, bottom = 42;
  const double pw = width - left - right, ph = height - top - bottom;
  auto X = [&](double v) { return left + x.fraction(v) * pw; };
  auto Y = [&](double v) { return top + ph - y.fraction(v) * ph; };
  std::ostringstream out;
  out << "<svg class='statistics-figure' viewBox='0 0 " << options.width << ' ' << options.height
      << "' width='" << options.width << "' height='" << options.height
      << "' font-family='sans-serif' font-size='10'>"
      << "<rect x='0' y='0' width='" << options.width << "' height='" << options.height
      << "' fill='#fff'/>"
      << "<text x='" << num(left) << "' y='16' font-size='12' fill='#222'>" << html_escape(title)
      << "</text>";
  for (double v : y.ticks(y_integral)) {
    out << "<line x1='" << num(left) << "' x2='" << num(left + pw) << "' y1='" << num(Y(v))
        << "' y2='" << num(Y(v)) << "' stroke='#eee'/>"
        << "<text x='" << num(left - 4) << "' y='" << num(Y(v) + 3)
        << "' text-anchor='end' fill='#555'>" << tick_text(v) << "</text>";
  }
  for (double v : x.ticks()) {
    out << "<line x1='" << num(X(v)) << "' x2='" << num(X(v)) << "' y1='" << num(top + ph)
        << "' y2='" << num(top + ph + 4) << "' stroke='#555'/>"
        << "<text x='" << num(X(v)) << "' y='" << num(top + ph + 15)
        << "' text-anchor='middle' fill='#555'>" << tick_text(v) << "</text>";
  }
  out << "<rect x='" << num(left) << "' y='" << num(top) << "' width='" << num(pw) << "' height='"
      << num(ph) << "' fill='none' stroke='#999'/>"
      << "<text x='" << num(left + pw / 2) << "' y='" << num(height - 8)
      << "' text-anchor='middle' fill='#333'>" << html_escape(x_label) << "</text>"
      << "<text x='12' y='" << num(top + ph / 2) << "' text-anchor='middle' fill='#333' "
      << "transform='rotate(-90 12 " << num(top + ph / 2) << ")'>" << html_escape(y_label)
      << "</text>";
  for (std::size_t s = 0; s < series.size(); ++s) {
    const char* colour = kPalette[s % (sizeof kPalette / sizeof *kPalette)];
    out << "<polyline fill='none' stroke='" << colour << "' stroke-width='1.6' points='";
    for (std::size_t i = 0; i < series[s].points.size(); ++i)
      out << (i ? " " : "") << num(X(series[s].points[i].first)) << ','
          << num(Y(series[s].points[i].second));
    out << "'/>";
    const double ly = top + 8 + 15.0 * static_cast<double>(s);
    if (ly > height - 4) continue;  // more solvers than fit: the CSV has them all
    out << "<line x1='" << num(left + pw + 10) << "' x2='" << num(left + pw + 28) << "' y1='"
        << num(ly) << "' y2='" << num(ly) << "' stroke='" << colour << "' stroke-width='2'/>"
        << "<text x='" << num(left + pw + 32) << "' y='" << num(ly + 3) << "' fill='#333'>"
        << html_escape(series[s].label) << "</text>";
  }
  out << "</svg>";
  return out.str();
}

}  // namespace

std::string cactus_svg(const TimeProfiles& p, const StatisticsFigureOptions& options) {
  // The time axis ends at the limit (every solved run is within it) and starts at 0, or at the
  // decade below the fastest solved run when the solved times span a factor of 10 or more.
  Axis x;
  x.hi = p.time_limit > 0 ? p.time_limit : 1.0;
  double fastest = x.hi;
  for (const auto& curve : p.cactus)
    for (const CactusPoint& point : curve)
      if (point.seconds > 0) fastest = std::min(fastest, point.seconds);
  if (x.hi / fastest >= 10.0) {
    x.log = true;
    x.lo = std::pow(10.0, std::floor(std::log10(fastest)));
  }
  Axis y;
  std::size_t most = 1;
  for (const auto& runs : p.runs) most = std::max(most, runs.size());
  y.hi = static_cast<double>(most);

  std::vector<Series> series;
  for (std::size_t s = 0; s < p.solvers.size(); ++s) {
    Series line{p.solvers[s] + " (" + std::to_string(p.cactus[s].size()) + "/" +
                    std::to_string(p.runs[s].size()) + ")",
                {{x.lo, 0.0}}};
    for (const CactusPoint& point : p.cactus[s]) {
      line.points.emplace_back(point.seconds, point.runs_solved - 1);
      line.points.emplace_back(point.seconds, point.runs_solved);
    }
    line.points.emplace_back(x.hi, static_cast<double>(p.cactus[s].size()));
    series.push_back(std::move(line));
  }
  return chart_svg("Cactus plot: runs solved within a time (solved/runs in the legend)", x,
                   std::string("time, s") + (x.log ? " (log scale)" : ""), y, true, "runs solved",
                   series, options);
}

std::string performance_profile_svg(const TimeProfiles& p, const StatisticsFigureOptions& options) {
  Axis x;
  x.log = true;
  x.lo = 1.0;
  x.hi = std::max(2.0, 1.2 * (p.taus.empty() ? 1.0 : p.taus.back()));
  Axis y;  // 0..1
  std::vector<Series> series;
  for (std::size_t s = 0; s < p.solvers.size(); ++s) series.push_back({p.solvers[s], {}});
  if (!p.ratios.empty()) {
    std::vector<double> before;
    for (std::size_t t = 0; t < p.taus.size(); ++t) {
      const std::vector<double> rho = performance_profile_at(p.ratios, p.taus[t]);
      for (std::size_t s = 0; s < series.size(); ++s) {
        if (t > 0) series[s].points.emplace_back(p.taus[t], before[s]);  // the step's riser
        series[s].points.emplace_back(p.taus[t], rho[s]);
      }
      before = rho;
    }
    for (std::size_t s = 0; s < series.size(); ++s) series[s].points.emplace_back(x.hi, before[s]);
  }
  return chart_svg(
      "Performance profile (Dolan-More): instances solved within a factor tau of the best", x,
      "tau = time / best time on the instance (log scale)", y, false, "fraction of instances",
      series, options);
}

std::string statistics_report_section(const Suite& suite, const SuiteOutcome& outcome,
                                      const StatisticsFigureOptions& options) {
  const TimeProfiles p = problem_time_profiles(suite, outcome);
  if (p.solvers.empty()) return "";
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", p.time_limit);
  std::ostringstream out;
  out << "<h2>Solved against time</h2><p class='legend'>Problem runs; a run is solved when it "
         "is feasible, its solver stopped on its own (completed, proven optimal or target "
         "reached) and its time is within the limit of "
      << limit
      << " s (the suite's time limit, else the slowest run). The cactus plot counts every run "
         "(instance x seed); the performance profile takes each solver's median run per "
         "instance. The numbers are in <code>cactus.csv</code> and <code>profiles.csv</code>."
         "</p>"
      << cactus_svg(p, options) << performance_profile_svg(p, options);
  return out.str();
}

}  // namespace sightline::experiments
