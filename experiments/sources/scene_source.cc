#include "sightline/experiments/sources/scene_source.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/profile_text.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/file_globs.h"
#include "sightline/experiments/sources/agile_families.h"
#include "sightline/experiments/sources/conversation_generator.h"
#include "sightline/experiments/sources/tracking_shot_generator.h"
#include "sightline/experiments/sources/scene_families.h"
#include "sightline/experiments/sources/scene_generator.h"

namespace sightline::experiments {
namespace {

std::string exact(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string exact(const Eigen::Vector3d& v) {
  return exact(v.x()) + " " + exact(v.y()) + " " + exact(v.z());
}

std::vector<SourcedScene> files_source(const csp::Spec& entry, const std::string& base_dir) {
  const csp::Spec& files = entry.is_map() ? entry.at("files") : entry;
  std::vector<SourcedScene> scenes;
  for (const std::string& path :
       expand_glob(files, base_dir, files.as_string("a scene path or glob"))) {
    SourcedScene s;
    s.path = path;  // the suite hashes the file's content; it loads only the scenes it needs
    scenes.push_back(std::move(s));
  }
  return scenes;
}

}  // namespace

SceneSourceInfo seeded_source(std::string name, std::string description,
                              std::function<camera::Scene(std::uint64_t)> generate) {
  SceneSourceInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.fields = {"seed", "seeds"};
  info.make = [generate](const csp::Spec& entry, const std::string&) {
    std::vector<SourcedScene> scenes;
    for (const std::uint64_t seed : entry_seeds(entry)) {
      SourcedScene s;
      s.scene = std::make_shared<const camera::Scene>(generate(seed));
      s.fingerprint = scene_fingerprint(*s.scene);
      scenes.push_back(std::move(s));
    }
    return scenes;
  };
  return info;
}

namespace {

// A generator taking an options struct, made a function of the seed (its other options at
// their defaults).
template <class Options, class Scene>
std::function<camera::Scene(std::uint64_t)> with_seed(Scene (*generate)(const Options&)) {
  return [generate](std::uint64_t seed) {
    Options o;
    o.seed = seed;
    return generate(o);
  };
}

void add_builtin_sources(SceneSources& sources) {
  SceneSourceInfo files;
  files.name = "files";
  files.description = "scene files (YAML, FORMATS.md): a path or glob relative to the suite file";
  files.fields = {"files"};
  files.make = files_source;
  sources.add(std::move(files));
  for (const SceneFamily family : all_scene_families()) {
    sources.add(seeded_source(to_string(family), "the seeded " + to_string(family) +
                                              " family (experiments/sources/scene_families.h)",
                       [family](std::uint64_t seed) { return generate_family(family, seed); }));
  }
  sources.add(seeded_source("pillar-forest", "pillars scattered round a winding walk",
                            with_seed<GeneratedSceneOptions>(generate_pillar_forest)));
  sources.add(seeded_source("city", "a city of blocks and streets",
                            with_seed<GeneratedSceneOptions>(generate_city)));
  sources.add(seeded_source("switchback", "a walk that doubles back between walls",
                            with_seed<SwitchbackOptions>(generate_switchback)));
  sources.add(seeded_source("crossings", "people crossing between camera and character",
                            with_seed<CrossingOptions>(generate_crossings)));
  for (const AgileFamily family : all_agile_families()) {
    sources.add(seeded_source(to_string(family), "the seeded agile family " + to_string(family) +
                                                     " (experiments/sources/agile_families.h)",
                              [family](std::uint64_t seed) { return generate_agile(family, seed); }));
  }
  sources.add(seeded_source("conversation",
                            "two or three people talking (standing, walking, circling, one "
                            "coming in), with a script: edited, not chased",
                            with_seed<ConversationOptions>(generate_conversation)));
  sources.add(seeded_source("tracking-shot",
                            "people moving through a street, round a corner, across a square or "
                            "circling, with a shot: block (a tracking shot)",
                            with_seed<TrackingShotOptions>(generate_tracking_shot)));
}

}  // namespace

SceneSources& SceneSources::global() {
  static SceneSources* sources = [] {
    auto* s = new SceneSources;
    add_builtin_sources(*s);
    return s;
  }();
  return *sources;
}

void SceneSources::add(SceneSourceInfo info) {
  if (info.name.empty() || !info.make) {
    throw std::invalid_argument("a scene source needs a name and a make function");
  }
  if (contains(info.name)) {
    throw std::invalid_argument("scene source '" + info.name + "' is registered twice");
  }
  const std::string name = info.name;
  sources_.emplace(name, std::move(info));
}

std::vector<std::string> SceneSources::names() const {
  std::vector<std::string> out;
  for (const auto& [name, info] : sources_) out.push_back(name);
  return out;
}

const SceneSourceInfo& SceneSources::info(const std::string& name) const {
  const auto it = sources_.find(name);
  if (it == sources_.end()) throw std::invalid_argument("no scene source '" + name + "'");
  return it->second;
}

std::vector<SourcedScene> SceneSources::scenes_of(const csp::Spec& entry,
                                                  const std::string& base_dir) const {
  if (entry.is_scalar()) return info("files").make(entry, base_dir);
  if (!entry.is_map()) {
    entry.fail("expected a scene file or glob, or a source {source: NAME, ...}, got " +
               entry.preview());
  }
  const csp::Spec& source = entry.at("source");
  const std::string& name = source.as_string("a scene source name");
  const auto it = sources_.find(name);
  if (it == sources_.end()) {
    std::string known;
    for (const std::string& n : names()) known += (known.empty() ? "" : ", ") + n;
    source.fail("unknown scene source '" + name + "'; the sources are: " + known);
  }
  std::vector<std::string> keys = it->second.fields;
  keys.push_back("source");
  entry.check_keys(keys);
  return it->second.make(entry, base_dir);
}

std::vector<std::uint64_t> entry_seeds(const csp::Spec& entry) {
  const csp::Spec* one = entry.find("seed");
  const csp::Spec* many = entry.find("seeds");
  if (one && many) entry.fail("expected seed: N or seeds: [N, ...], not both");
  std::vector<csp::Spec> values;
  if (one) values.push_back(*one);
  if (many) values = many->items("a list of seeds (integers >= 0)");
  if (values.empty()) return {1};
  std::vector<std::uint64_t> seeds;
  for (const csp::Spec& v : values) {
    const long long seed = v.as_integer("a seed (an integer >= 0)");
    if (seed < 0) v.fail("expected a seed >= 0, got " + std::to_string(seed));
    seeds.push_back(static_cast<std::uint64_t>(seed));
  }
  return seeds;
}

std::string scene_fingerprint(const camera::Scene& scene) {
  std::ostringstream out;
  out << "scene " << scene.name() << "\nframe_rate " << exact(scene.frame_rate())
      << "\ncharacter " << exact(scene.character().size) << " "
      << exact(scene.character().look_at_height) << "\n";
  for (const camera::SolidBox& b : scene.solids()) {
    out << "box " << exact(b.box.min) << " " << exact(b.box.max) << "\n";
  }
  for (const camera::Area& a : scene.areas()) {
    out << "area " << static_cast<int>(a.kind) << " " << exact(a.box.min) << " "
        << exact(a.box.max) << "\n";
  }
  for (const camera::Mover& m : scene.movers()) {
    out << "mover " << exact(m.size());
    for (const camera::MoverKeyframe& k : m.path()) out << " | " << exact(k.t) << " " << exact(k.position);
    out << "\n";
  }
  for (const camera::Keyframe& k : scene.trajectory().keyframes()) {
    out << "key " << exact(k.t) << " " << exact(k.position) << " " << exact(k.yaw) << "\n";
  }
  if (const camera::Level* level = scene.level()) {
    out << "level " << level->file << " " << level->map << " " << level->mesh.size() << "\n";
  }
  if (scene.camera_start()) out << "start " << exact(*scene.camera_start()) << "\n";
  // People's facing and the script (an editor's scene); nothing for scenes without them.
  for (const camera::Actor& a : scene.actors()) {
    out << "actor " << a.name << " " << exact(a.shape.look_at_height);
    for (const camera::Keyframe& k : a.trajectory.keyframes()) out << " | " << exact(k.t) << " " << exact(k.yaw);
    out << "\n";
  }
  if (const auto* script = scene.script()) {
    for (const camera::ScriptEntry& e : *script) {
      out << "line " << exact(e.t0) << " " << exact(e.t1) << " " << e.speaker << " " << e.to << " "
          << e.action << "\n";
    }
  }
  out << "profile " << camera::profile_text(scene.profile());
  return out.str();
}

}  // namespace sightline::experiments
