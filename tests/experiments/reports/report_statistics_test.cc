// The report's cactus plot and performance profile: well-formed SVG (tags balanced, one root),
// one polyline per solver with every point inside the viewBox, step curves that only rise,
// the log time axis when times span decades, and the section in a problem suite's report.
#include "sightline/experiments/reports/report_statistics.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "sightline/experiments/reports/report.h"

namespace sightline::experiments {
namespace {

struct Element {
  std::string name;
  std::string attributes;
};

// A minimal XML shape check: every tag closed in order (or self-closing), one root. Returns
// the elements in document order; fails the test on a broken shape.
std::vector<Element> parse_shape(const std::string& svg) {
  std::vector<Element> elements;
  std::vector<std::string> open;
  int roots = 0;
  for (std::size_t i = svg.find('<'); i != std::string::npos; i = svg.find('<', i + 1)) {
    const std::size_t end = svg.find('>', i);
    if (end == std::string::npos) {
      ADD_FAILURE() << "unterminated tag at " << i;
      return elements;
    }
    std::string tag = svg.substr(i + 1, end - i - 1);
    if (tag.empty()) {
      ADD_FAILURE() << "empty tag at " << i;
      continue;
    }
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name) {
        ADD_FAILURE() << "</" << name << "> closes " << (open.empty() ? "nothing" : open.back());
        return elements;
      }
      open.pop_back();
      continue;
    }
    const bool self_closing = tag.back() == '/';
    if (self_closing) tag.pop_back();
    const std::size_t space = tag.find(' ');
    Element e{tag.substr(0, space), space == std::string::npos ? "" : tag.substr(space)};
    // Attribute quotes balanced.
    EXPECT_EQ(std::count(e.attributes.begin(), e.attributes.end(), '\'') % 2, 0) << tag;
    if (open.empty()) ++roots;
    elements.push_back(e);
    if (!self_closing) open.push_back(e.name);
  }
  EXPECT_TRUE(open.empty()) << "unclosed <" << (open.empty() ? "" : open.back()) << ">";
  EXPECT_EQ(roots, 1);
  // No stray '<' or '>' in text: every '>' ends a tag the loop saw.
  EXPECT_EQ(std::count(svg.begin(), svg.end(), '<'), std::count(svg.begin(), svg.end(), '>'));
  return elements;
}

std::string attribute(const Element& e, const std::string& name) {
  const std::string key = " " + name + "='";
  const std::size_t at = e.attributes.find(key);
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size();
  return e.attributes.substr(start, e.attributes.find('\'', start) - start);
}

struct Figure {
  double width = 0, height = 0;
  std::vector<std::vector<std::pair<double, double>>> polylines;
};

Figure check_figure(const std::string& svg) {
  Figure f;
  const std::vector<Element> elements = parse_shape(svg);
  if (elements.empty()) return f;
  EXPECT_EQ(elements.front().name, "svg");
  std::istringstream box(attribute(elements.front(), "viewBox"));
  double x0 = -1, y0 = -1;
  box >> x0 >> y0 >> f.width >> f.height;
  EXPECT_EQ(x0, 0.0);
  EXPECT_EQ(y0, 0.0);
  EXPECT_GT(f.width, 0.0);
  for (const Element& e : elements) {
    if (e.name != "polyline") continue;
    std::vector<std::pair<double, double>>& line = f.polylines.emplace_back();
    std::istringstream points(attribute(e, "points"));
    std::string pair;
    while (points >> pair) {
      const std::size_t comma = pair.find(',');
      const double x = std::stod(pair.substr(0, comma)), y = std::stod(pair.substr(comma + 1));
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, f.width);
      EXPECT_GE(y, 0.0);
      EXPECT_LE(y, f.height);
      line.emplace_back(x, y);
    }
    EXPECT_GE(line.size(), 2u);
  }
  return f;
}

// The curves are step functions that never fall: x never decreases, y (down the picture)
// never increases, and each segment is horizontal or vertical (a step, not a slope).
void expect_rising_steps(const Figure& f) {
  for (const auto& line : f.polylines)
    for (std::size_t i = 1; i < line.size(); ++i) {
      EXPECT_GE(line[i].first, line[i - 1].first);
      EXPECT_LE(line[i].second, line[i - 1].second);
      EXPECT_TRUE(line[i].first == line[i - 1].first || line[i].second == line[i - 1].second)
          << "a sloped segment at point " << i;
    }
}

// Three solvers on two problems, times from 1 ms to 5 s, limit 10 s: A solves everything, B
// half, C nothing.
TimeProfiles hand_made() {
  TimeProfiles p;
  p.solvers = {"A", "B<&>", "C"};  // a label that needs escaping
  p.instances = {"p", "q"};
  p.time_limit = 10;
  p.runs = {{{true, 0.001}, {true, 5.0}}, {{true, 0.5}, {false, 10.0}}, {{false, 1}, {false, 1}}};
  for (const auto& runs : p.runs) p.cactus.push_back(cactus_curve(runs, p.time_limit));
  const double inf = std::numeric_limits<double>::infinity();
  p.ratios = {{1.0, 500.0, inf}, {1.0, inf, inf}};
  p.taus = {1.0, 500.0};
  return p;
}

TEST(ReportStatistics, CactusSvgIsWellFormedWithOnePolylinePerSolverInsideTheViewBox) {
  const TimeProfiles p = hand_made();
  const std::string svg = cactus_svg(p);
  const Figure f = check_figure(svg);
  ASSERT_EQ(f.polylines.size(), 3u);
  expect_rising_steps(f);
  // Times from 1 ms to 10 s: a log axis with decade ticks.
  EXPECT_NE(svg.find("(log scale)"), std::string::npos);
  EXPECT_NE(svg.find(">0.001<"), std::string::npos);
  EXPECT_NE(svg.find(">10<"), std::string::npos);
  EXPECT_NE(svg.find("B&lt;&amp;&gt; (1/2)"), std::string::npos);
  // Heights end in the order of runs solved: A (2) above B (1) above C (0, on the x axis).
  EXPECT_LT(f.polylines[0].back().second, f.polylines[1].back().second);
  EXPECT_LT(f.polylines[1].back().second, f.polylines[2].back().second);
  EXPECT_EQ(f.polylines[2].front().second, f.polylines[2].back().second);
  // Each solved run is one riser: A's curve has two, B's one.
  auto risers = [](const std::vector<std::pair<double, double>>& line) {
    int n = 0;
    for (std::size_t i = 1; i < line.size(); ++i) n += line[i].second < line[i - 1].second;
    return n;
  };
  EXPECT_EQ(risers(f.polylines[0]), 2);
  EXPECT_EQ(risers(f.polylines[1]), 1);
  EXPECT_EQ(risers(f.polylines[2]), 0);
}

TEST(ReportStatistics, CactusTimeAxisIsLinearWhenTimesSpanLessThanADecade) {
  TimeProfiles p = hand_made();
  p.runs = {{{true, 2.0}, {true, 5.0}}, {{true, 3.0}, {false, 10.0}}, {{false, 1}, {false, 1}}};
  p.cactus.clear();
  for (const auto& runs : p.runs) p.cactus.push_back(cactus_curve(runs, p.time_limit));
  const std::string svg = cactus_svg(p);
  EXPECT_EQ(svg.find("log scale"), std::string::npos);
  const Figure f = check_figure(svg);
  EXPECT_EQ(f.polylines.size(), 3u);
  expect_rising_steps(f);
}

TEST(ReportStatistics, PerformanceProfileSvgIsWellFormedWithOnePolylinePerSolver) {
  const TimeProfiles p = hand_made();
  const Figure f = check_figure(performance_profile_svg(p));
  ASSERT_EQ(f.polylines.size(), 3u);
  expect_rising_steps(f);
  // At tau = 1 A is best on both instances (fraction 1, the top), B on none, C never: B and C
  // start at the bottom; B ends half way up, C stays at 0.
  const double top = f.polylines[0].front().second, bottom = f.polylines[2].front().second;
  EXPECT_LT(top, bottom);
  EXPECT_DOUBLE_EQ(f.polylines[1].front().second, bottom);
  EXPECT_NEAR(f.polylines[1].back().second, (top + bottom) / 2, 0.11);
  EXPECT_DOUBLE_EQ(f.polylines[2].back().second, bottom);
}

// Problem runs of solvers A and B on problem "p", as results.csv holds them.
SuiteOutcome two_solver_outcome(const Suite& suite, const std::string& stop) {
  SuiteOutcome outcome;
  const std::vector<std::string> columns = metric_columns(suite);
  for (const char* solver : {"A", "B"}) {
    RunResult r;
    r.kind = "toy";
    r.id = std::string("run-") + solver;
    r.subject = "p";
    r.solver = solver;
    r.profile = "-";
    r.status = "ok";
    r.values.assign(columns.size(), "");
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c] == "feasible") r.values[c] = "1";
      if (columns[c] == "time_s") r.values[c] = solver[0] == 'A' ? "0.5" : "2";
      if (columns[c] == "time_to_best_s") r.values[c] = "0.1";
      if (columns[c] == "stop") r.values[c] = stop;
      if (columns[c] == "cost") r.values[c] = "0";
    }
    outcome.results.push_back(r);
  }
  return outcome;
}

Suite two_solver_suite() {
  Suite suite;
  suite.name = "toy";
  suite.problems.push_back({});
  suite.problems.back().label = "p";
  suite.toy_solvers.resize(2);
  suite.toy_solvers[0].label = "A";
  suite.toy_solvers[1].label = "B";
  suite.toy_seeds = {1};
  return suite;
}

// With reference values the legend states the reference rule the figures use, not the
// solver's own stop; and where source and fallback apply, says so.
TEST(ReportStatistics, TheSolvedLegendStatesTheRuleTheSuiteUses) {
  Suite suite = two_solver_suite();
  std::string html = statistics_report_section(suite, two_solver_outcome(suite, "completed"));
  EXPECT_NE(html.find("stopped on its own"), std::string::npos) << html;
  suite.references["p"] = 0;  // given (from values: or a file: alike)
  html = statistics_report_section(suite, two_solver_outcome(suite, "time limit"));
  EXPECT_EQ(html.find("stopped on its own"), std::string::npos) << html;
  EXPECT_NE(html.find("reference value (the suite&#39;s references:), at its time to best"),
            std::string::npos)
      << html;
  suite.reference_from = "B";
  html = statistics_report_section(suite, two_solver_outcome(suite, "time limit"));
  EXPECT_NE(html.find("else the optimum B proves"), std::string::npos) << html;
  EXPECT_NE(html.find("on a problem without a reference"), std::string::npos) << html;
}

// Anytime curves from 4e6 down to 10310 and 10914: on a linear axis the two finals would be
// a pixel apart; the axis becomes the cost above 10310 on a log scale, and they separate.
TEST(ReportStatistics, AnytimeCurvesSpanningOrdersOfMagnitudeGetALogAxisAboveTheBest) {
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("sightline-anytime-" + std::to_string(::getpid()));
  std::filesystem::create_directories(out / "runs");
  std::ofstream(out / "runs" / "run-A.anytime.csv")
      << "seconds,evaluations,cost,hard\n0.001,1,4000000,0\n0.01,50,10914,0\n";
  std::ofstream(out / "runs" / "run-B.anytime.csv")
      << "seconds,evaluations,cost,hard\n0.001,1,4000000,0\n0.02,90,10310,0\n";
  Suite suite = two_solver_suite();
  suite.toy_limits.time_limit_seconds = 1;
  const std::string html = anytime_report_section(suite, two_solver_outcome(suite, "time limit"),
                                                  out.string());
  std::filesystem::remove_all(out);
  EXPECT_NE(html.find("best cost - 10310 (log scale"), std::string::npos) << html;
  const std::size_t start = html.find("<svg"), end = html.find("</svg>", start);
  const Figure f = check_figure(html.substr(start, end + 6 - start));
  ASSERT_EQ(f.polylines.size(), 2u);
  // The finals, 10914 and 10310, far apart (more than a tenth of the plot's height).
  EXPECT_GT(std::abs(f.polylines[0].back().second - f.polylines[1].back().second), f.height / 10);
}

TEST(ReportStatistics, ProblemSuiteReportHasTheSolvedAgainstTimeSection) {
  const Suite suite = two_solver_suite();
  const SuiteOutcome outcome = two_solver_outcome(suite, "completed");
  const std::string html = report_html(suite, outcome, "/nonexistent");
  EXPECT_NE(html.find("<h2>Solved against time</h2>"), std::string::npos);
  EXPECT_NE(html.find("Cactus plot"), std::string::npos);
  EXPECT_NE(html.find("Performance profile"), std::string::npos);
  // A camera-only suite (no problem runs) has no such section.
  EXPECT_EQ(statistics_report_section(suite, SuiteOutcome{}), "");
}

}  // namespace
}  // namespace sightline::experiments
