#include "sightline/experiments/reports/report.h"
#include "sightline/experiments/reports/suite_outputs.h"

#include "sightline/experiments/runs/camera_run.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "sightline/experiments/runs/independent_check.h"
#include "sightline/experiments/reports/report_statistics.h"
#include "sightline/experiments/reports/report_views.h"

namespace sightline::experiments {
namespace {

const char* kPalette[] = {"#d9480f", "#5f3dc4", "#2b8a3e", "#c2255c", "#1864ab",
                          "#e67700", "#087f5b", "#862e9c", "#495057", "#a61e4d"};

const char* kStyle = R"(
body{font-family:system-ui,sans-serif;margin:24px;color:#222;max-width:1400px}
h1{font-size:22px}h2{font-size:18px;border-bottom:1px solid #ccc;padding-top:12px}h3{font-size:15px}
table{border-collapse:collapse;font-size:12px;margin:8px 0}
td,th{border:1px solid #ccc;padding:3px 6px;text-align:right}
td:nth-child(-n+3),th{text-align:left}th{background:#f1f3f5}
.runs{display:flex;flex-wrap:wrap;gap:14px}
.run{border:1px solid #ddd;padding:6px;background:#fff}
.run h4{margin:2px 0 6px 0;font-size:13px}
.views{display:flex;gap:6px;align-items:flex-start}
.cams td{text-align:center;vertical-align:top}.cams img{display:block}
.legend{font-size:12px;color:#444}.note{color:#a61e4d}
)";

// The Markdown summary rendered as HTML: headings, paragraphs and pipe tables.
std::string markdown_to_html(const std::string& markdown) {
  std::istringstream in(markdown);
  std::ostringstream out;
  std::string line;
  bool in_table = false, header_row = false;
  auto cells = [](const std::string& row) {
    std::vector<std::string> out;
    std::string cell;
    for (std::size_t i = 1; i < row.size(); ++i) {
      if (row[i] == '|') {
        out.push_back(cell);
        cell.clear();
      } else {
        cell += row[i];
      }
    }
    for (auto& c : out) {
      c.erase(0, c.find_first_not_of(' '));
      c.erase(c.find_last_not_of(' ') + 1);
    }
    return out;
  };
  auto inline_code = [](const std::string& text) {
    std::string escaped = html_escape(text), out;
    bool open = false;
    for (char c : escaped) {
      if (c == '`') {
        out += open ? "</code>" : "<code>";
        open = !open;
      } else {
        out += c;
      }
    }
    return out;
  };
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '|') {
      if (!in_table) {
        out << "<table>";
        in_table = true;
        header_row = true;
      }
      if (line.find("---") != std::string::npos && line.find_first_not_of("|-: ") == std::string::npos) continue;
      out << "<tr>";
      for (const std::string& c : cells(line)) {
        out << (header_row ? "<th>" : "<td>") << inline_code(c) << (header_row ? "</th>" : "</td>");
      }
      out << "</tr>";
      header_row = false;
      continue;
    }
    if (in_table) {
      out << "</table>\n";
      in_table = false;
    }
    if (line.rfind("### ", 0) == 0) {
      out << "<h3>" << inline_code(line.substr(4)) << "</h3>\n";
    } else if (line.rfind("## ", 0) == 0) {
      out << "<h2>" << inline_code(line.substr(3)) << "</h2>\n";
    } else if (!line.empty()) {
      out << "<p>" << inline_code(line) << "</p>\n";
    }
  }
  if (in_table) out << "</table>\n";
  return out.str();
}

struct LoadedRun {
  const RunResult* result = nullptr;
  std::vector<TraceRow> trace;
  RunDrawing drawing;
  std::vector<double> visible_fraction;  // per frame
};

void scene_section(std::ostringstream& out, const SuiteScene& scene,
                   std::vector<LoadedRun>& runs, const Suite& suite,
                   const ReportOptions& options, const std::string& replay) {
  out << "<h2>Scene <code>" << html_escape(scene.label) << "</code></h2>";
  if (!scene.scene->description().empty()) {
    out << "<p>" << html_escape(scene.scene->description()) << "</p>";
  }
  out << replay;
  out << "<p class='legend'>Blue: the character's path and facing; coloured: the camera's path "
         "and view direction (arrows about once a second); red dots: frames whose look-at point "
         "is hidden (independent check); circles: cuts; dashed: areas (green enclosed, teal "
         "semi-enclosed); boxes darker when taller; amber: movers (faint: where they go; solid: "
         "where they were, near the character, when an occlusion began or the camera cut, "
         "labelled with the time).</p><div class='runs'>";
  for (LoadedRun& r : runs) {
    out << "<div class='run'><h4 style='color:" << r.drawing.colour << "'>"
        << html_escape(r.result->solver) << " / " << html_escape(r.result->profile) << " / seed "
        << r.result->seed << "</h4>";
    if (r.trace.empty()) {
      out << "<p class='note'>no trace (" << html_escape(r.result->status) << ": "
          << html_escape(r.result->note) << ")</p></div>";
      continue;
    }
    out << "<div class='views'>" << top_view_svg(*scene.scene, r.drawing, options.view_width)
        << side_view_svg(*scene.scene, r.drawing, options.view_width) << "</div></div>";
  }
  out << "</div>";

  // The main camera at chosen frames: the same frames for every run, side by side.
  std::size_t frames = 0;
  for (const LoadedRun& r : runs) frames = std::max(frames, r.trace.size());
  const int n = suite.camera_view_frames;
  if (frames > 0 && n > 0) {
    std::vector<std::size_t> chosen;
    for (int k = 0; k < n; ++k) chosen.push_back(static_cast<std::size_t>((k + 0.5) / n * frames));
    out << "<h3>What the main camera sees</h3><p class='legend'>Ray cast from the camera's "
           "position: the character in orange, the cross at the look-at point, a red frame when "
           "the look-at point is hidden.</p><table class='cams'><tr><th>run</th>";
    for (std::size_t f : chosen) {
      char t[48];
      std::snprintf(t, sizeof t, "frame %zu", f);
      out << "<th>" << t << "</th>";
    }
    out << "</tr>";
    for (const LoadedRun& r : runs) {
      if (r.trace.empty()) continue;
      out << "<tr><td style='color:" << r.drawing.colour << "'>" << html_escape(r.result->solver)
          << "<br>" << html_escape(r.result->profile) << "</td>";
      for (std::size_t f : chosen) {
        const std::size_t i = std::min(f, r.trace.size() - 1);
        const auto png = camera_view_png(*scene.scene, r.trace[i], r.drawing.occluded[i] != 0,
                                         options.camera_width, options.camera_height);
        char caption[64];
        std::snprintf(caption, sizeof caption, "t = %.2f s, body %.0f%% visible", r.trace[i].t,
                      100 * r.visible_fraction[i]);
        out << "<td><img alt='camera view' width='" << options.camera_width << "' height='"
            << options.camera_height << "' src='data:image/png;base64," << base64(png)
            << "'>" << caption << "</td>";
      }
      out << "</tr>";
    }
    out << "</table>";
  }

  // Plots over time.
  std::vector<PlotSeries> cost, visible, speed;
  for (const LoadedRun& r : runs) {
    if (r.trace.empty()) continue;
    const std::string label = r.result->solver + " / " + r.result->profile;
    PlotSeries c{label, r.drawing.colour, {}, {}}, v = c, s = c;
    for (std::size_t i = 0; i < r.trace.size(); ++i) {
      const TraceRow& row = r.trace[i];
      c.t.push_back(row.t);
      c.v.push_back(row.cost);
      v.t.push_back(row.t);
      v.v.push_back(r.visible_fraction[i]);
      s.t.push_back(row.t);
      if (i == 0 || row.cut || row.t <= r.trace[i - 1].t) {
        s.v.push_back(std::nan(""));  // a cut is a jump, not a speed
      } else {
        s.v.push_back((row.camera - r.trace[i - 1].camera).norm() / (row.t - r.trace[i - 1].t));
      }
    }
    cost.push_back(std::move(c));
    visible.push_back(std::move(v));
    speed.push_back(std::move(s));
  }
  if (!cost.empty()) {
    out << "<h3>Over time</h3>"
        << line_plot_svg("total cost of the chosen position", cost, options.plot_width, options.plot_height)
        << line_plot_svg("visible fraction of the body (independent check)", visible,
                         options.plot_width, options.plot_height)
        << line_plot_svg("camera speed, m/s (gaps at cuts)", speed, options.plot_width,
                         options.plot_height);
  }
}

}  // namespace

std::string report_html(const Suite& suite, const SuiteOutcome& outcome,
                        const std::string& out_dir, const ReportOptions& options) {
  std::ostringstream out;
  out << "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>sightline suite "
      << html_escape(suite.name) << "</title><style>" << kStyle << "</style>";
  // The 3D replay's code once (three.js inlined or beside); a missing three.js leaves the
  // replay out with a note saying why, rather than losing the whole report.
  ReplayOptions replay;
  replay.three_dir = options.three_dir;
  const bool beside = options.replay_assets == ReportOptions::ReplayAssets::kBeside ||
                      (options.replay_assets == ReportOptions::ReplayAssets::kSuite &&
                       suite.replay_assets_beside);
  if (beside) {
    replay.assets_dir = (std::filesystem::path(out_dir) / "report-assets").string();
    replay.assets_href = "report-assets";
  }
  std::string replay_note;
  bool with_replay = options.replay && !suite.scenes.empty();
  if (with_replay) {
    try {
      out << replay_head(replay);
    } catch (const std::runtime_error& e) {
      with_replay = false;
      replay_note = e.what();
    }
  }
  out << "</head><body>";
  out << "<h1>sightline: suite <code>" << html_escape(suite.name) << "</code></h1>";
  // Figures first (anytime curves and final costs, cactus plot, performance profile), then
  // the tables.
  out << anytime_report_section(suite, outcome, out_dir);
  out << statistics_report_section(suite, outcome);
  out << markdown_to_html(markdown_summary(suite, outcome));

  // Colours by solver label, stable across scenes.
  std::map<std::string, std::string> colour;
  for (std::size_t i = 0; i < suite.camera_solvers.size(); ++i) {
    colour[suite.camera_solvers[i].label] = kPalette[i % (sizeof kPalette / sizeof *kPalette)];
  }
  if (!replay_note.empty()) out << "<p class='note'>3D replay left out: " << html_escape(replay_note) << "</p>";

  for (const SuiteScene& scene : suite.scenes) {
    std::vector<LoadedRun> runs;
    // The independent check, boxes, movers at each row's time and a level's triangles alike (the clearance radius and
    // smooth step do not matter for these two questions).
    const MetricsInput world = metrics_input(*scene.scene, scene.scene->profile(), 0);
    for (const RunResult& r : outcome.results) {
      if (r.kind != "camera" || r.subject != scene.label) continue;
      LoadedRun loaded;
      loaded.result = &r;
      loaded.drawing.colour = colour[r.solver];
      try {
        if (r.status == "ok") {
          loaded.trace = read_trace_csv(
              (std::filesystem::path(out_dir) / "runs" / (r.id + ".trace.csv")).string());
        }
      } catch (const std::exception&) {
        loaded.trace.clear();
      }
      for (const TraceRow& row : loaded.trace) {
        loaded.drawing.occluded.push_back(
            segment_blocked(world, row.camera, row.target, row.t) ? 1 : 0);
        loaded.visible_fraction.push_back(
            visible_body_fraction(world, row.camera, row.character, row.t));
      }
      runs.push_back(std::move(loaded));
    }
    for (LoadedRun& r : runs) r.drawing.trace = &r.trace;
    std::string replay_html;
    if (with_replay) {
      // Hidden frames come from the independent check above, never the controller's flag.
      ReplayScene rs{scene.label, scene.scene.get(), {}};
      for (const LoadedRun& r : runs) {
        if (r.trace.empty()) continue;
        rs.runs.push_back({r.result->id,
                           r.result->solver + " / " + r.result->profile + " / seed " +
                               std::to_string(r.result->seed),
                           r.trace, r.drawing.occluded});
      }
      if (!rs.runs.empty()) replay_html = replay_section(rs, replay);
    }
    if (!runs.empty()) scene_section(out, scene, runs, suite, options, replay_html);
  }
  out << "<p class='legend'>Generated by <code>sightline run</code>. Per-run traces and "
         "results are in <code>runs/</code>; every number above is in <code>results.csv</code>."
         "</p></body></html>\n";
  return out.str();
}

void write_report(const Suite& suite, const SuiteOutcome& outcome, const std::string& out_dir,
                  const ReportOptions& options) {
  const std::string path = (std::filesystem::path(out_dir) / "report.html").string();
  const std::string tmp = path + ".tmp";
  {
    std::ofstream file(tmp, std::ios::binary | std::ios::trunc);
    file << report_html(suite, outcome, out_dir, options);
    if (!file) throw std::runtime_error("cannot write " + tmp);
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace sightline::experiments
