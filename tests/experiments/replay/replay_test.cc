// The replay page (experiments/replay/replay.h): its structure, that the base64 buffers decode
// (here, with a decoder of the test's own) to exactly the trace's and scene's numbers, that
// three.js is inlined or its absence reported, that sizes grow linearly with frames, and the
// assets-beside mode. What the page does in a browser is checked by the view's browser script.
#include "sightline/experiments/replay/replay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace sightline::experiments {
namespace {

using camera::Aabb;
using Eigen::Vector3d;

std::vector<unsigned char> decode_base64(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<unsigned char> out;
  unsigned bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=') break;
    const int v = value(c);
    if (v < 0) throw std::runtime_error(std::string("not base64: ") + c);
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>((bits >> count) & 0xff));
    }
  }
  return out;
}

template <typename T>
std::vector<T> decode(const std::string& text) {
  const std::vector<unsigned char> bytes = decode_base64(text);
  if (bytes.size() % sizeof(T) != 0) throw std::runtime_error("ragged buffer");
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), bytes.size());  // little-endian, as the page reads it
  return out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The JSON inside the first <script class='replay-data'> of a page or section.
nlohmann::json inline_data(const std::string& html) {
  const std::string open = "<script type='application/json' class='replay-data'>";
  const std::size_t a = html.find(open);
  if (a == std::string::npos) throw std::runtime_error("no replay-data block");
  const std::size_t b = html.find("</script>", a);
  return nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
}

std::shared_ptr<camera::Scene> make_scene(bool with_level_and_mover) {
  std::vector<camera::SolidBox> boxes{{"wall", Aabb{Vector3d(-2, 0, 3), Vector3d(2, 2.5, 3.4)}, {}},
                                      {"pillar", Aabb{Vector3d(1.25, 0, -1.5), Vector3d(1.75, 3, -1)}, {}}};
  std::vector<camera::Area> areas{
      {"room", camera::AreaKind::kEnclosed, Aabb{Vector3d(-5, 0, -5), Vector3d(5, 3, 5)}, {}}};
  camera::Trajectory path({{0, Vector3d(0, 0, 0), 0}, {2, Vector3d(4, 0, 1), 90}});
  auto scene = std::make_shared<camera::Scene>("test", boxes, areas, camera::CharacterShape{}, path, 10);
  if (with_level_and_mover) {
    auto level = std::make_shared<camera::Level>();
    level->file = "triangles";
    level->mesh.vertices = {Eigen::Vector3f(-10, 0, -10), Eigen::Vector3f(10, 0, -10),
                            Eigen::Vector3f(10, 0, 10), Eigen::Vector3f(-10, 0.125f, 10.3f)};
    level->mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    scene->set_level(level);
    scene->set_movers({camera::Mover("bus", Vector3d(2, 3, 5),
                                     {{0.5, Vector3d(-3, 0, 2)}, {1.5, Vector3d(3, 0, 2.5)}})});
  }
  return scene;
}

// A trace of `frames` rows with awkward numbers, cuts every 7th frame.
std::vector<TraceRow> make_trace(int frames, double phase) {
  std::vector<TraceRow> rows;
  for (int i = 0; i < frames; ++i) {
    TraceRow r;
    r.frame = i;
    r.t = i * 0.1;
    r.character = Vector3d(0.1 * i, 0.0, 0.05 * i);
    r.character_yaw = 3.7 * i;
    r.camera = Vector3d(std::sin(i + phase) * 3.3, 1.7 + 0.01 * i, std::cos(i) * 2.9 - 1 / 3.0);
    r.target = r.character + Vector3d(0, 1.5, 0.001 * i);
    r.cut = i % 7 == 3;
    rows.push_back(r);
  }
  return rows;
}

ReplayRun make_run(const std::string& id, int frames, double phase) {
  ReplayRun run{id, id + " / scene / seed 1", make_trace(frames, phase), {}};
  for (int i = 0; i < frames; ++i) run.hidden.push_back(i % 5 == 1 ? 1 : 0);
  return run;
}

TEST(Replay, PageHasOneHeadAndOneSectionPerSceneWithItsRuns) {
  auto a = make_scene(false), b = make_scene(true);
  std::vector<ReplayScene> scenes{{"scene-a", a.get(), {make_run("a1", 20, 0), make_run("a2", 20, 1)}},
                                  {"scene-b", b.get(), {make_run("b1", 12, 0)}}};
  const std::string page = replay_page("replay test", scenes, {});
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(count(page, "class='replay-head'"), 1u);
  EXPECT_EQ(count(page, "<section class='replay'"), 2u);
  EXPECT_EQ(count(page, "</section>"), 2u);
  EXPECT_NE(page.find("data-scene='scene-a' data-runs='a1 a2'"), std::string::npos);
  EXPECT_NE(page.find("data-scene='scene-b' data-runs='b1'"), std::string::npos);
  EXPECT_EQ(count(page, "class='replay-data'"), 2u);
  EXPECT_NE(page.rfind("</body></html>"), std::string::npos);
}

TEST(Replay, SceneAndRunBuffersDecodeToExactlyTheTraceAndSceneNumbers) {
  auto scene = make_scene(true);
  ReplayScene rs{"s", scene.get(), {make_run("r1", 30, 0.5), make_run("r2", 30, 2)}};
  rs.runs[1].trace[4].character.x() += 0.25;  // r2's character differs: its own track
  const nlohmann::json d = inline_data(replay_section(rs, {}));

  const std::vector<float> boxes = decode<float>(d["boxes"]);
  ASSERT_EQ(boxes.size(), 12u);
  for (std::size_t i = 0; i < 2; ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(boxes[i * 6 + k], static_cast<float>(scene->solids()[i].box.min[k]));
      EXPECT_EQ(boxes[i * 6 + 3 + k], static_cast<float>(scene->solids()[i].box.max[k]));
    }
  }
  EXPECT_EQ(decode<float>(d["areas"]).size(), 6u);
  EXPECT_EQ(d["area_kinds"], "e");
  EXPECT_EQ(d["fov"], 60);

  const auto& mesh = scene->level()->mesh;
  const std::string section = replay_section(rs, {});
  ASSERT_EQ(d["level"]["triangles"], 2);
  const std::string open = "<script type='application/json' class='replay-level' data-level='" +
                           d["level"]["key"].get<std::string>() + "'>";
  const std::size_t at = section.find(open);
  ASSERT_NE(at, std::string::npos);
  const nlohmann::json level = nlohmann::json::parse(
      section.substr(at + open.size(), section.find("</script>", at) - at - open.size()));
  const std::vector<float> positions = decode<float>(level["positions"]);
  ASSERT_EQ(positions.size(), mesh.vertices.size() * 3);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(positions[v * 3 + k], mesh.vertices[v][k]);
  }
  ASSERT_EQ(level["index_type"], "u16");
  const std::vector<std::uint16_t> indices = decode<std::uint16_t>(level["indices"]);
  ASSERT_EQ(indices.size(), 6u);
  for (std::size_t t = 0; t < 2; ++t) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(indices[t * 3 + k], mesh.triangles[t][k]);
  }
  ASSERT_EQ(d["movers"].size(), 1u);
  EXPECT_EQ(d["movers"][0]["size"][2], 5.0);
  EXPECT_EQ(d["movers"][0]["keys"][1][0], 1.5);
  EXPECT_EQ(d["movers"][0]["keys"][1][3], 2.5);

  // The quantisation grid spans the scene and the runs in 65535 steps, no coarser.
  const double step = d["grid"]["step"];
  const double origin[3] = {d["grid"]["origin"][0], d["grid"]["origin"][1], d["grid"]["origin"][2]};
  EXPECT_LE(origin[0], -10.0);  // the level's corner
  EXPECT_LE(step, 20.3 / 65535 * 1.0001);  // the level's z extent, the largest
  EXPECT_GT(step, 20.3 / 65535 * 0.9999);

  ASSERT_EQ(d["runs"].size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    const ReplayRun& run = rs.runs[r];
    const nlohmann::json& j = d["runs"][r];
    EXPECT_EQ(j["id"], run.id);
    EXPECT_EQ(j["frames"], run.trace.size());
    ASSERT_TRUE(j.contains("track")) << "run " << r << " has its own character";
    const std::vector<float> track = decode<float>(j["track"]);
    const std::vector<std::uint16_t> camera = decode<std::uint16_t>(j["camera_q"]);
    const std::vector<std::uint16_t> target = decode<std::uint16_t>(j["target_q"]);
    const std::vector<std::uint8_t> flags = decode<std::uint8_t>(j["flags"]);
    ASSERT_EQ(track.size(), run.trace.size() * 5);
    ASSERT_EQ(camera.size(), run.trace.size() * 3);
    ASSERT_EQ(target.size(), run.trace.size() * 3);
    ASSERT_EQ(flags.size(), run.trace.size());
    for (std::size_t i = 0; i < run.trace.size(); ++i) {
      const TraceRow& row = run.trace[i];
      EXPECT_EQ(track[i * 5], static_cast<float>(row.t));
      EXPECT_EQ(track[i * 5 + 4], static_cast<float>(row.character_yaw));
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(track[i * 5 + 1 + k], static_cast<float>(row.character[k]));
        // Quantised: within half a step of the trace, as the page computes it (in doubles
        // here, Float32 there: a float's rounding is far below the step).
        EXPECT_NEAR(origin[k] + camera[i * 3 + k] * step, row.camera[k], step * 0.5 + 1e-9);
        EXPECT_NEAR(origin[k] + target[i * 3 + k] * step, row.target[k], step * 0.5 + 1e-9);
      }
      EXPECT_EQ(flags[i], (row.cut ? 1 : 0) | (run.hidden[i] ? 2 : 0)) << "frame " << i;
    }
  }
}

TEST(Replay, ACharacterTrackSharedByRunsIsWrittenOnce) {
  auto scene = make_scene(false);
  ReplayScene rs{"s", scene.get(), {make_run("r1", 40, 0), make_run("r2", 40, 1), make_run("r3", 40, 2)}};
  const std::string section = replay_section(rs, {});
  const nlohmann::json d = inline_data(section);
  EXPECT_TRUE(d["runs"][0].contains("track"));
  EXPECT_EQ(d["runs"][1]["track_of"], 0);
  EXPECT_EQ(d["runs"][2]["track_of"], 0);
  EXPECT_EQ(count(section, "\"track\":"), 1u);
}

TEST(Replay, ALevelSharedByScenesIsWrittenOncePerPage) {
  auto a = make_scene(true);
  auto b = std::make_shared<camera::Scene>(*a);  // another scene on the same level
  ReplayOptions options;
  std::string sections = replay_section({"a", a.get(), {make_run("a1", 5, 0)}}, options) +
                         replay_section({"b", b.get(), {make_run("b1", 5, 0)}}, options);
  EXPECT_EQ(count(sections, "class='replay-level'"), 1u);
  EXPECT_EQ(inline_data(sections)["level"]["key"],
            inline_data(sections.substr(sections.find("data-scene='b'")))["level"]["key"]);
  // A page of its own writes it again; so does a caller with no record of the page.
  const std::string page = replay_page("p", {{"a", a.get(), {make_run("a1", 5, 0)}},
                                             {"b", b.get(), {make_run("b1", 5, 0)}}}, options);
  EXPECT_EQ(count(page, "class='replay-level'"), 1u);
  options.levels_on_page = nullptr;
  EXPECT_EQ(count(replay_section({"a", a.get(), {make_run("a1", 5, 0)}}, options), "class='replay-level'"), 1u);
}

TEST(Replay, HeadInlinesThreeJsWithItsOrbitControlsAndTheReplayCode) {
  const std::string head = replay_head({});
  EXPECT_NE(head.find("REVISION=\"111\""), std::string::npos) << "Debian's libjs-three r111";
  EXPECT_NE(head.find("OrbitControls"), std::string::npos);
  EXPECT_NE(head.find("dataset.replay = 'ready'"), std::string::npos);
  EXPECT_NE(head.find(".replay-solo-target"), std::string::npos);  // the CSS
  EXPECT_EQ(count(head, "<script class="), 2u);
  EXPECT_EQ(count(head, "</script"), 2u);  // nothing inlined ends a block early
}

TEST(Replay, MissingThreeJsIsAnErrorNamingThePackage) {
  ReplayOptions options;
  options.three_dir = "/nonexistent/three";
  try {
    replay_head(options);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("libjs-three"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("/nonexistent/three/three.min.js"), std::string::npos) << e.what();
  }
}

TEST(Replay, SectionSizeGrowsLinearlyWithFrames) {
  auto scene = make_scene(false);
  auto size = [&](int frames) {
    ReplayScene rs{"s", scene.get(), {make_run("r1", frames, 0), make_run("r2", frames, 1)}};
    return static_cast<double>(replay_section(rs, {}).size());
  };
  const double s1 = size(500), s2 = size(1000), s4 = size(2000);
  EXPECT_NEAR((s4 - s2) / (s2 - s1), 2.0, 0.02);
  // Per frame: one shared character track (5 floats) and per run camera and target (6
  // Uint16) and a flag byte, base64: (20 + 2 * 13) * 4 / 3 = 61.3 bytes.
  EXPECT_NEAR((s2 - s1) / 500, 61.3, 1.0);
}

TEST(Replay, TextIsEscapedSoALabelCannotEndTheDataBlock) {
  auto scene = make_scene(false);
  ReplayRun run = make_run("r'1", 5, 0);
  run.label = "</script><b>\"x\"";
  ReplayScene rs{"s<1>", scene.get(), {run}};
  const std::string section = replay_section(rs, {});
  EXPECT_EQ(count(section, "</script>"), 1u);
  EXPECT_NE(section.find("data-scene='s&lt;1&gt;' data-runs='r&#39;1'"), std::string::npos);
  EXPECT_EQ(inline_data(section)["runs"][0]["label"], "</script><b>\"x\"");
}

TEST(Replay, BadRunsAreRefused) {
  auto scene = make_scene(false);
  ReplayScene rs{"s", scene.get(), {make_run("r1", 5, 0)}};
  rs.runs[0].hidden.pop_back();
  EXPECT_THROW(replay_section(rs, {}), std::invalid_argument);
  rs.runs[0] = ReplayRun{"empty", "empty", {}, {}};
  EXPECT_THROW(replay_section(rs, {}), std::invalid_argument);
}

TEST(Replay, AssetsBesideWritesThreeJsAndSceneDataAsScriptsThePageReferences) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("replay_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  auto scene = make_scene(true);
  ReplayOptions options;
  options.assets_dir = (dir / "report-assets").string();
  options.assets_href = "report-assets";
  const std::string page =
      replay_page("beside", {{"my scene", scene.get(), {make_run("r1", 50, 0)}}}, options);
  EXPECT_NE(page.find("src='report-assets/three.js'"), std::string::npos);
  EXPECT_NE(page.find("data-src='report-assets/replay-my_scene.js'"), std::string::npos);
  EXPECT_EQ(page.find("class='replay-data'"), std::string::npos);
  EXPECT_EQ(page.find("REVISION"), std::string::npos);

  std::ifstream three(dir / "report-assets/three.js");
  std::stringstream three_text;
  three_text << three.rdbuf();
  EXPECT_NE(three_text.str().find("REVISION=\"111\""), std::string::npos);
  std::ifstream data(dir / "report-assets/replay-my_scene.js");
  std::stringstream data_text;
  data_text << data.rdbuf();
  const std::string prefix = "(window.sightlineReplayData=window.sightlineReplayData||{})[\"my scene\"]=";
  ASSERT_EQ(data_text.str().rfind(prefix, 0), 0u) << data_text.str().substr(0, 100);
  std::string json = data_text.str().substr(prefix.size());
  json = json.substr(0, json.rfind(';'));
  const nlohmann::json d = nlohmann::json::parse(json);
  EXPECT_EQ(d["runs"][0]["id"], "r1");
  EXPECT_EQ(decode<std::uint16_t>(d["runs"][0]["camera_q"]).size(), 150u);
  const std::string key = d["level"]["key"];
  EXPECT_NE(page.find("data-level='" + key + "' data-src='report-assets/replay-level-" + key + ".js'"),
            std::string::npos);
  std::ifstream level(dir / ("report-assets/replay-level-" + key + ".js"));
  std::stringstream level_text;
  level_text << level.rdbuf();
  EXPECT_EQ(level_text.str().rfind("(window.sightlineReplayLevels=window.sightlineReplayLevels||{})[\"" + key + "\"]={\"positions\":", 0), 0u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sightline::experiments
