#include "sightline/experiments/replay/replay.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "sightline/experiments/runs/html_text.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/experiments/replay/replay_sources.h"
#include "sightline/experiments/runs/stable_hash.h"

namespace sightline::experiments {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the replay's base64 buffers are little-endian, as JavaScript's typed arrays");

std::string base64_of(const void* data, std::size_t size) {
  static const char* kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < size) {
    const std::uint32_t v = (bytes[i] << 16) | (i + 1 < size ? bytes[i + 1] << 8 : 0);
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < size ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

template <typename T>
std::string base64_of(const std::vector<T>& values) {
  return base64_of(values.data(), values.size() * sizeof(T));
}

// A JSON string literal; '<' and '>' escaped so "</script>" can never end the data block.
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || c == '<' || c == '>' || c == '&') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string json_vec3(const Eigen::Vector3d& v) {
  return "[" + json_number(v.x()) + "," + json_number(v.y()) + "," + json_number(v.z()) + "]";
}

void push3(std::vector<float>& out, const Eigen::Vector3d& v) {
  out.push_back(static_cast<float>(v.x()));
  out.push_back(static_cast<float>(v.y()));
  out.push_back(static_cast<float>(v.z()));
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

// three.js and its OrbitControls from Debian's libjs-three (both UMD builds: they define the
// global THREE, and OrbitControls adds THREE.OrbitControls).
std::string three_sources(const std::string& dir) {
  const std::filesystem::path base(dir);
  const std::string three = read_file(base / "three.min.js");
  const std::string orbit = read_file(base / "examples/js/controls/OrbitControls.js");
  if (three.empty() || orbit.empty()) {
    throw std::runtime_error(
        "the 3D replay needs three.js: " +
        (base / (three.empty() ? "three.min.js" : "examples/js/controls/OrbitControls.js"))
            .string() +
        " is missing or empty (install Debian's package libjs-three)");
  }
  if (three.find("</script") != std::string::npos || orbit.find("</script") != std::string::npos) {
    throw std::runtime_error("three.js from " + dir + " contains </script> and cannot be inlined");
  }
  return three + "\n" + orbit + "\n";
}

bool same_character_track(const std::vector<TraceRow>& a, const std::vector<TraceRow>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (static_cast<float>(a[i].t) != static_cast<float>(b[i].t) ||
        (a[i].character.cast<float>() - b[i].character.cast<float>()).squaredNorm() != 0 ||
        static_cast<float>(a[i].character_yaw) != static_cast<float>(b[i].character_yaw)) {
      return false;
    }
  }
  return true;
}

// The character track of a run: t, x, y, z, yaw per frame.
std::string character_track(const std::vector<TraceRow>& trace) {
  std::vector<float> out;
  out.reserve(trace.size() * 5);
  for (const TraceRow& r : trace) {
    out.push_back(static_cast<float>(r.t));
    push3(out, r.character);
    out.push_back(static_cast<float>(r.character_yaw));
  }
  return base64_of(out);
}

// Camera and target positions are quantised to 16 bits over the scene's bounds (a step of
// extent / 65535: about 1 mm over a 60 m scene), which halves the report's largest part;
// exact Float32 would take the thesis report to 14.4 MB of its 15 MB budget. The grid's
// origin and step are floats, so the page and the tests decode with the very numbers used.
struct Grid {
  Eigen::Vector3f origin;
  float step = 1;
  std::uint16_t quantise(double v, int axis) const {
    const double q = std::round((v - origin[axis]) / static_cast<double>(step));
    return static_cast<std::uint16_t>(std::clamp(q, 0.0, 65535.0));
  }
};

Grid grid_over(const camera::Aabb& bounds) {
  Grid g;
  g.origin = bounds.min.cast<float>();
  const double extent = (bounds.max - g.origin.cast<double>()).maxCoeff();
  // Rounded up to a float that still covers the extent in 65535 steps.
  g.step = std::nextafter(static_cast<float>(std::max(extent, 1e-3) / 65535), INFINITY);
  return g;
}

std::string quantised(const std::vector<TraceRow>& trace, const Grid& grid, bool camera) {
  std::vector<std::uint16_t> out;
  out.reserve(trace.size() * 3);
  for (const TraceRow& r : trace) {
    const Eigen::Vector3d& p = camera ? r.camera : r.target;
    for (int k = 0; k < 3; ++k) out.push_back(grid.quantise(p[k], k));
  }
  return base64_of(out);
}

std::string run_json(const ReplayRun& run, int shared_track, const Grid& grid) {
  std::vector<std::uint8_t> flags;
  for (std::size_t i = 0; i < run.trace.size(); ++i) {
    flags.push_back(static_cast<std::uint8_t>((run.trace[i].cut ? 1 : 0) | (run.hidden[i] ? 2 : 0)));
  }
  std::ostringstream out;
  out << "{\"id\":" << json_string(run.id) << ",\"label\":" << json_string(run.label)
      << ",\"frames\":" << run.trace.size();
  if (shared_track >= 0) {
    out << ",\"track_of\":" << shared_track;
  } else {
    out << ",\"track\":\"" << character_track(run.trace) << "\"";
  }
  out << ",\"camera_q\":\"" << quantised(run.trace, grid, true) << "\",\"target_q\":\""
      << quantised(run.trace, grid, false) << "\",\"flags\":\"" << base64_of(flags) << "\"";
  // A composing camera's lens (a shot's tracking camera, an edited film): fov and roll per
  // frame, degrees, so the main-camera panel sees what it saw.
  if (std::any_of(run.trace.begin(), run.trace.end(), [](const TraceRow& r) { return r.fov > 0; })) {
    std::vector<float> lens;
    lens.reserve(run.trace.size() * 2);
    for (const TraceRow& r : run.trace) {
      lens.push_back(static_cast<float>(r.fov));
      lens.push_back(static_cast<float>(r.roll));
    }
    out << ",\"lens\":\"" << base64_of(lens) << "\"";
  }
  // An edited film's shots, for the timeline under the scrub bar: [name, first frame] each.
  if (std::any_of(run.trace.begin(), run.trace.end(), [](const TraceRow& r) { return !r.shot.empty(); })) {
    out << ",\"shots\":[";
    for (std::size_t i = 0, n = 0; i < run.trace.size(); ++i) {
      if (i > 0 && !run.trace[i].cut && run.trace[i].shot == run.trace[i - 1].shot) continue;
      out << (n++ ? "," : "") << "[" << json_string(run.trace[i].shot) << "," << i << "]";
    }
    out << "]";
  }
  out << "}";
  return out.str();
}

// A level's triangles: written once per page however many scenes stand on it (the levels
// suite has five walks per map), under a key that is a hash of the mesh itself.
std::string level_key(const camera::TriangleMesh& mesh) {
  return StableHash()
      .add(mesh.vertices.data(), mesh.vertices.size() * sizeof(Eigen::Vector3f))
      .add(mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]))
      .hex();
}

std::string level_json(const camera::TriangleMesh& mesh) {
  std::vector<float> positions;
  positions.reserve(mesh.vertices.size() * 3);
  for (const Eigen::Vector3f& v : mesh.vertices) {
    positions.push_back(v.x());
    positions.push_back(v.y());
    positions.push_back(v.z());
  }
  std::string indices;
  const bool small = mesh.vertices.size() <= 65536;
  if (small) {
    std::vector<std::uint16_t> idx;
    idx.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles) {
      for (std::uint32_t i : t) idx.push_back(static_cast<std::uint16_t>(i));
    }
    indices = base64_of(idx);
  } else {
    std::vector<std::uint32_t> idx;
    idx.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles) idx.insert(idx.end(), t.begin(), t.end());
    indices = base64_of(idx);
  }
  return "{\"positions\":\"" + base64_of(positions) + "\",\"indices\":\"" + indices +
         "\",\"index_type\":\"" + (small ? "u16" : "u32") + "\",\"triangles\":" +
         std::to_string(mesh.triangles.size()) + "}";
}

// The scene's data as one JSON object (see replay.js, "Data").
std::string scene_json(const ReplayScene& rs) {
  const camera::Scene& scene = *rs.scene;
  std::ostringstream out;
  out << "{\"version\":1,\"scene\":" << json_string(rs.id) << ",\"name\":" << json_string(scene.name())
      << ",\"frame_rate\":" << json_number(scene.frame_rate()) << ",\"fov\":60";
  camera::Aabb bounds = scene.world_bounds();
  for (const ReplayRun& run : rs.runs) {
    for (const TraceRow& r : run.trace) {
      bounds.merge(r.camera);
      bounds.merge(r.target);
      bounds.merge(r.character);
    }
  }
  if (!std::isfinite(bounds.min.x())) bounds = {Eigen::Vector3d(-1, 0, -1), Eigen::Vector3d(1, 2, 1)};
  out << ",\"bounds\":[" << json_vec3(bounds.min) << "," << json_vec3(bounds.max) << "]";
  const Grid grid = grid_over(bounds);
  out << ",\"grid\":{\"origin\":" << json_vec3(grid.origin.cast<double>())
      << ",\"step\":" << json_number(grid.step) << "}";
  out << ",\"character\":{\"size\":" << json_vec3(scene.character().size)
      << ",\"look_at_height\":" << json_number(scene.character().look_at_height) << "}";
  // A tracking shot's composition, drawn over the main-camera panel: the image's aspect, the
  // framed properties' rectangles and the screen positions asked for (screen units, (0, 0)
  // bottom-left).
  if (const camera::Shot* shot = scene.shot()) {
    out << ",\"shot\":{\"aspect\":" << json_number(shot->aspect) << ",\"rects\":[";
    std::size_t n = 0;
    for (const camera::ShotProperty& p : shot->properties) {
      if (p.kind != "framed" || p.range.hi <= 0) continue;
      out << (n++ ? "," : "") << "[" << json_number(p.rect[0]) << "," << json_number(p.rect[1]) << ","
          << json_number(p.rect[2]) << "," << json_number(p.rect[3]) << "]";
    }
    out << "],\"points\":[";
    n = 0;
    for (const camera::ShotProperty& p : shot->properties) {
      if (p.kind != "screen_position") continue;
      out << (n++ ? "," : "") << "[" << json_number(p.at.x()) << "," << json_number(p.at.y()) << "]";
    }
    out << "]}";
  }

  std::vector<float> boxes;
  for (const camera::SolidBox& b : scene.solids()) {
    push3(boxes, b.box.min);
    push3(boxes, b.box.max);
  }
  out << ",\"boxes\":\"" << base64_of(boxes) << "\"";
  std::vector<float> areas;
  std::string kinds;
  for (const camera::Area& a : scene.areas()) {
    push3(areas, a.box.min);
    push3(areas, a.box.max);
    kinds += a.kind == camera::AreaKind::kEnclosed ? 'e' : 's';
  }
  out << ",\"areas\":\"" << base64_of(areas) << "\",\"area_kinds\":\"" << kinds << "\"";

  if (const camera::Level* level = scene.level(); level && !level->mesh.empty()) {
    out << ",\"level\":{\"key\":\"" << level_key(level->mesh) << "\",\"triangles\":"
        << level->mesh.triangles.size() << "}";
  } else {
    out << ",\"level\":null";
  }

  out << ",\"movers\":[";
  for (std::size_t m = 0; m < scene.movers().size(); ++m) {
    const camera::Mover& mover = scene.movers()[m];
    out << (m ? "," : "") << "{\"name\":" << json_string(mover.name())
        << ",\"size\":" << json_vec3(mover.size()) << ",\"keys\":[";
    for (std::size_t k = 0; k < mover.path().size(); ++k) {
      const camera::MoverKeyframe& key = mover.path()[k];
      out << (k ? "," : "") << "[" << json_number(key.t) << "," << json_number(key.position.x())
          << "," << json_number(key.position.y()) << "," << json_number(key.position.z()) << "]";
    }
    out << "]}";
  }
  out << "]";

  // Runs: a character track identical (in Float32) to an earlier run's is written once.
  out << ",\"runs\":[";
  std::vector<std::size_t> owners;  // runs that wrote their own track
  for (std::size_t i = 0; i < rs.runs.size(); ++i) {
    int shared = -1;
    for (std::size_t o : owners) {
      if (same_character_track(rs.runs[o].trace, rs.runs[i].trace)) {
        shared = static_cast<int>(o);
        break;
      }
    }
    if (shared < 0) owners.push_back(i);
    out << (i ? "," : "") << run_json(rs.runs[i], shared, grid);
  }
  out << "]}";
  return out.str();
}

}  // namespace

std::string replay_safe_id(const std::string& id) {
  std::string out;
  for (char c : id) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_' || c == '.';
    out += keep ? c : '_';
  }
  return out.empty() ? "_" : out;
}

std::string replay_head(const ReplayOptions& options) {
  std::string out = "<style>";
  out += replay_detail::kReplayCss;
  out += "</style>\n";
  const std::string three = three_sources(options.three_dir);
  if (options.assets_dir.empty()) {
    out += "<script class='replay-three'>" + three + "</script>\n";
  } else {
    write_file(std::filesystem::path(options.assets_dir) / "three.js", three);
    out += "<script class='replay-three' src='" + html_escape(options.assets_href + "/three.js") +
           "'></script>\n";
  }
  out += "<script class='replay-head'>";
  out += replay_detail::kReplayJs;
  out += "</script>\n";
  return out;
}

std::string replay_section(const ReplayScene& scene, const ReplayOptions& options) {
  if (scene.scene == nullptr) throw std::invalid_argument("replay_section: no scene");
  for (const ReplayRun& run : scene.runs) {
    if (run.trace.empty()) throw std::invalid_argument("replay run " + run.id + ": the trace has no rows");
    if (run.hidden.size() != run.trace.size()) {
      throw std::invalid_argument("replay run " + run.id + ": " + std::to_string(run.hidden.size()) +
                                  " hidden flags for " + std::to_string(run.trace.size()) +
                                  " trace rows");
    }
  }
  const std::string json = scene_json(scene);
  std::string level_block;  // the level's triangles, when this page does not have them yet
  if (const camera::Level* level = scene.scene->level(); level && !level->mesh.empty()) {
    const std::string key = level_key(level->mesh);
    if (!options.levels_on_page || options.levels_on_page->insert(key).second) {
      if (options.assets_dir.empty()) {
        level_block = "<script type='application/json' class='replay-level' data-level='" + key +
                      "'>" + level_json(level->mesh) + "</script>";
      } else {
        write_file(std::filesystem::path(options.assets_dir) / ("replay-level-" + key + ".js"),
                   "(window.sightlineReplayLevels=window.sightlineReplayLevels||{})[\"" + key +
                       "\"]=" + level_json(level->mesh) + ";\n");
        level_block = "<script type='application/json' class='replay-level' data-level='" + key +
                      "' data-src='" +
                      html_escape(options.assets_href + "/replay-level-" + key + ".js") +
                      "'>null</script>";
      }
    }
  }
  std::ostringstream out;
  std::string run_ids;
  for (const ReplayRun& run : scene.runs) run_ids += (run_ids.empty() ? "" : " ") + run.id;
  out << "<section class='replay' data-scene='" << html_escape(scene.id) << "' data-runs='"
      << html_escape(run_ids) << "'";
  if (options.assets_dir.empty()) {
    out << ">" << level_block << "<script type='application/json' class='replay-data'>" << json
        << "</script>";
  } else {
    const std::string file = "replay-" + replay_safe_id(scene.id) + ".js";
    write_file(std::filesystem::path(options.assets_dir) / file,
               "(window.sightlineReplayData=window.sightlineReplayData||{})[" +
                   json_string(scene.id) + "]=" + json + ";\n");
    out << " data-src='" << html_escape(options.assets_href + "/" + file) << "'>" << level_block;
  }
  out << "<div class='replay-placeholder'>3D replay of " << html_escape(scene.scene->name()) << " ("
      << scene.runs.size() << " run" << (scene.runs.size() == 1 ? "" : "s")
      << "): builds when scrolled into view, or click here.</div></section>\n";
  return out.str();
}

std::string replay_page(const std::string& title, const std::vector<ReplayScene>& scenes,
                        const ReplayOptions& page_options) {
  ReplayOptions options = page_options;  // a page of its own: no level written yet
  options.levels_on_page = std::make_shared<std::set<std::string>>();
  std::string out = "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>" +
                    html_escape(title) + "</title>";
  out += "<style>body{font-family:system-ui,sans-serif;margin:24px;color:#222}</style>";
  out += replay_head(options);
  out += "</head><body><h1>" + html_escape(title) + "</h1>\n";
  for (const ReplayScene& scene : scenes) {
    out += "<h2>Scene <code>" + html_escape(scene.scene ? scene.scene->name() : scene.id) +
           "</code></h2>\n";
    out += replay_section(scene, options);
  }
  out += "</body></html>\n";
  return out;
}

}  // namespace sightline::experiments
