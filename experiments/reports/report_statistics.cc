#include "sightline/experiments/reports/report_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
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
  // An optional band around the line (the interquartile range): the lower edge, then the
  // upper edge, each at the line's x values; drawn translucent under it.
  std::vector<double> band_lo, band_hi;
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
    const Series& line = series[s];
    if (!line.band_lo.empty() && line.band_lo.size() == line.points.size()) {
      out << "<polygon fill='" << colour << "' fill-opacity='0.15' stroke='none' points='";
      for (std::size_t i = 0; i < line.points.size(); ++i)
        out << num(X(line.points[i].first)) << ',' << num(Y(line.band_lo[i])) << ' ';
      for (std::size_t i = line.points.size(); i-- > 0;)
        out << num(X(line.points[i].first)) << ',' << num(Y(line.band_hi[i])) << (i ? " " : "");
      out << "'/>";
    }
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
                {{x.lo, 0.0}}, {}, {}};
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
  for (std::size_t s = 0; s < p.solvers.size(); ++s) series.push_back({p.solvers[s], {}, {}, {}});
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

namespace {

// One run's anytime trajectory as written by the suite runner (runs/<id>.anytime.csv):
// (seconds, cost) of its feasible points, in order. Empty when missing or unreadable.
std::vector<std::pair<double, double>> read_anytime(const std::string& path) {
  std::vector<std::pair<double, double>> out;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return out;  // header
  while (std::getline(in, line)) {
    double t = 0, cost = 0, hard = 0;
    unsigned long long evaluations = 0;
    if (std::sscanf(line.c_str(), "%lf,%llu,%lf,%lf", &t, &evaluations, &cost, &hard) != 4) continue;
    if (hard <= 0 && std::isfinite(cost)) out.emplace_back(t, cost);
  }
  return out;
}

// The q-quantile of values sorted ascending (+inf allowed), interpolated.
double sorted_quantile(const std::vector<double>& v, double q) {
  const double at = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(at);
  const double frac = at - static_cast<double>(i);
  if (i + 1 >= v.size() || frac <= 0) return v[i];
  if (!std::isfinite(v[i + 1])) return v[i + 1];  // between a cost and +inf: +inf
  return v[i] + frac * (v[i + 1] - v[i]);
}

// Every value a series draws (its line and band), for changing them all alike.
template <class Lines, class F>
void for_each_value(Lines& series, F f) {
  for (auto& line : series) {
    for (auto& point : line.points) f(point.second);
    for (auto& v : line.band_lo) f(v);
    for (auto& v : line.band_hi) f(v);
  }
}

// Whether the costs above the lowest drawn, `best`, span two orders of magnitude or more: a
// curve starting at 4e6 would then crowd finals of 10310 and 10914 into one pixel of a
// linear axis.
bool spans_orders_of_magnitude(const std::vector<Series>& series, double best) {
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for_each_value(series, [&](double v) {
    if (v - best > 0) {
      smallest = std::min(smallest, v - best);
      largest = std::max(largest, v - best);
    }
  });
  return std::isfinite(smallest) && largest >= 100 * smallest;
}

// Turns every value into its excess over `best` and returns the log axis that shows them,
// from the decade below the smallest excess (where `best` itself, an excess of 0, is drawn).
Axis relative_log_axis(std::vector<Series>& series, double best) {
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for_each_value(series, [&](double& v) {
    v -= best;
    if (v > 0) smallest = std::min(smallest, v);
    largest = std::max(largest, v);
  });
  Axis y;
  y.log = true;
  y.lo = std::pow(10.0, std::floor(std::log10(smallest)));
  y.hi = std::max(largest, y.lo * 10);
  return y;
}

}  // namespace

std::string anytime_report_section(const Suite& suite, const SuiteOutcome& outcome,
                                   const std::string& out_dir, const StatisticsFigureOptions& options) {
  // problem -> solver -> runs' trajectories, in the suite's orders.
  std::vector<std::string> problems, solvers;
  std::map<std::pair<std::string, std::string>, std::vector<std::vector<std::pair<double, double>>>> runs;
  std::map<std::pair<std::string, std::string>, std::vector<double>> finals;
  const std::vector<std::string> columns = metric_columns(suite);
  double first = std::numeric_limits<double>::infinity(), last = 0;
  for (const RunResult& r : outcome.results) {
    if (r.kind != "toy" || r.status != "ok") continue;
    auto points = read_anytime((std::filesystem::path(out_dir) / "runs" / (r.id + ".anytime.csv")).string());
    if (points.empty()) continue;
    if (std::find(problems.begin(), problems.end(), r.subject) == problems.end()) problems.push_back(r.subject);
    if (std::find(solvers.begin(), solvers.end(), r.solver) == solvers.end()) solvers.push_back(r.solver);
    first = std::min(first, std::max(points.front().first, 1e-6));
    last = std::max({last, points.back().first, metric_value(columns, r, "time_s")});
    finals[{r.subject, r.solver}].push_back(points.back().second);
    runs[{r.subject, r.solver}].push_back(std::move(points));
  }
  if (problems.empty()) return "";
  const double limit = suite.toy_limits.time_limit_seconds > 0 ? suite.toy_limits.time_limit_seconds : last;
  Axis x;
  x.log = true;
  x.lo = std::pow(10.0, std::floor(std::log10(first)));
  x.hi = std::max(limit, x.lo * 10);
  std::vector<double> grid;
  for (int i = 0; i <= 48; ++i) grid.push_back(x.lo * std::pow(x.hi / x.lo, i / 48.0));
  std::ostringstream out;
  out << "<h2>Anytime curves</h2><p class='legend'>Each problem's best feasible cost found by "
         "each time, per solver: the median over seeds (line) and the interquartile range "
         "(band; a seed with no feasible assignment yet counts as infinite), drawn where at "
         "least half the seeds have a feasible assignment; then each "
         "solver's final costs over seeds as a box plot (whiskers: min and max). From "
         "<code>runs/&lt;id&gt;.anytime.csv</code> (seconds, evaluations, cost, hard); "
         "results.csv has the cost at 1%, 10% and 50% of the time limit. Where a problem's "
         "costs span orders of magnitude (a start far above the finals), its cost axis is "
         "the cost above the lowest one drawn, on a log scale, so close finals stay apart.</p>";
  constexpr std::size_t kMostProblems = 24;
  for (std::size_t k = 0; k < problems.size() && k < kMostProblems; ++k) {
    const std::string& problem = problems[k];
    std::vector<Series> series;
    Axis y;
    y.lo = std::numeric_limits<double>::infinity();
    y.hi = -y.lo;
    for (const std::string& solver : solvers) {
      const auto it = runs.find({problem, solver});
      if (it == runs.end()) continue;
      Series line{solver, {}, {}, {}};
      for (const double t : grid) {
        // A seed without a feasible assignment yet counts as +inf, so the quantiles of the
        // seeds' (non-increasing) best costs do not increase either.
        std::vector<double> at;
        for (const auto& run : it->second) {
          double cost = std::numeric_limits<double>::infinity();
          for (const auto& [s, c] : run) {
            if (s > t) break;
            cost = c;
          }
          at.push_back(cost);
        }
        std::sort(at.begin(), at.end());
        const double median = sorted_quantile(at, 0.5);
        if (!std::isfinite(median)) continue;
        line.points.emplace_back(t, median);
        line.band_lo.push_back(sorted_quantile(at, 0.25));
        line.band_hi.push_back(sorted_quantile(at, 0.75));  // +inf: drawn to the top
        y.lo = std::min(y.lo, line.band_lo.back());
        y.hi = std::max(y.hi, std::isfinite(line.band_hi.back()) ? line.band_hi.back() : median);
      }
      series.push_back(std::move(line));
    }
    for (Series& line : series) {
      for (double& v : line.band_hi) v = std::isfinite(v) ? v : y.hi;
    }
    if (!std::isfinite(y.lo)) continue;
    std::string y_label = "best cost (median, IQR band)";
    if (const double best = y.lo; spans_orders_of_magnitude(series, best)) {
      y = relative_log_axis(series, best);
      y_label = "best cost - " + tick_text(best) + " (log scale; " + tick_text(best) + " at the bottom)";
    } else if (y.hi - y.lo < 1e-9) {
      y.lo -= 1;
      y.hi += 1;
    }
    out << chart_svg("Anytime curve: " + problem, x, "time, s (log scale)", y, false, y_label,
                     series, options);
    // Box plot of the final costs.
    const double width = options.width, row = 18, top = 26, left = 140, right = 30;
    const double height = top + row * static_cast<double>(solvers.size()) + 30;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const std::string& solver : solvers) {
      for (double c : finals[{problem, solver}]) {
        lo = std::min(lo, c);
        hi = std::max(hi, c);
      }
    }
    if (hi - lo < 1e-9) {
      lo -= 1;
      hi += 1;
    }
    auto X = [&](double v) { return left + (v - lo) / (hi - lo) * (width - left - right); };
    out << "<svg class='statistics-figure' viewBox='0 0 " << options.width << ' ' << num(height)
        << "' width='" << options.width << "' height='" << num(height)
        << "' font-family='sans-serif' font-size='10'><rect x='0' y='0' width='" << options.width
        << "' height='" << num(height) << "' fill='#fff'/><text x='" << num(left) << "' y='16' "
        << "font-size='12' fill='#222'>" << html_escape("Final cost over seeds: " + problem) << "</text>";
    for (std::size_t s = 0; s < solvers.size(); ++s) {
      std::vector<double> v = finals[{problem, solvers[s]}];
      std::sort(v.begin(), v.end());
      const double cy = top + row * (static_cast<double>(s) + 0.5);
      out << "<text x='" << num(left - 6) << "' y='" << num(cy + 3) << "' text-anchor='end' fill='#333'>"
          << html_escape(solvers[s]) << "</text>";
      if (v.empty()) continue;
      const char* colour = kPalette[s % (sizeof kPalette / sizeof *kPalette)];
      const double q1 = sorted_quantile(v, 0.25), q2 = sorted_quantile(v, 0.5), q3 = sorted_quantile(v, 0.75);
      const double mn = v.front(), mx = v.back();
      out << "<line x1='" << num(X(mn)) << "' x2='" << num(X(mx)) << "' y1='" << num(cy) << "' y2='"
          << num(cy) << "' stroke='" << colour << "'/><rect x='" << num(X(q1)) << "' y='" << num(cy - 5)
          << "' width='" << num(std::max(1.0, X(q3) - X(q1))) << "' height='10' fill='" << colour
          << "' fill-opacity='0.3' stroke='" << colour << "'/><line x1='" << num(X(q2)) << "' x2='"
          << num(X(q2)) << "' y1='" << num(cy - 5) << "' y2='" << num(cy + 5) << "' stroke='#222'/>";
    }
    const double axis_y = top + row * static_cast<double>(solvers.size()) + 4;
    out << "<text x='" << num(left) << "' y='" << num(axis_y + 12) << "' fill='#555'>" << tick_text(lo)
        << "</text><text x='" << num(width - right) << "' y='" << num(axis_y + 12)
        << "' text-anchor='end' fill='#555'>" << tick_text(hi) << "</text><text x='"
        << num((left + width - right) / 2) << "' y='" << num(axis_y + 12)
        << "' text-anchor='middle' fill='#333'>final cost</text></svg>";
  }
  if (problems.size() > kMostProblems) {
    out << "<p class='legend'>" << problems.size() - kMostProblems
        << " more problems: their curves are in runs/*.anytime.csv.</p>";
  }
  return out.str();
}

std::string statistics_report_section(const Suite& suite, const SuiteOutcome& outcome,
                                      const StatisticsFigureOptions& options) {
  const TimeProfiles p = problem_time_profiles(suite, outcome);
  if (p.solvers.empty()) return "";
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", p.time_limit);
  std::ostringstream out;
  out << "<h2>Solved against time</h2><p class='legend'>Problem runs; "
      << html_escape(solved_rule_text(suite)) << "; and its time is within the limit of " << limit
      << " s (the suite's time limit, else the slowest run). The cactus plot counts every run "
         "(instance x seed); the performance profile takes each solver's median run per "
         "instance. The numbers are in <code>cactus.csv</code> and <code>profiles.csv</code>."
         "</p>"
      << cactus_svg(p, options) << performance_profile_svg(p, options);
  return out.str();
}

}  // namespace sightline::experiments
