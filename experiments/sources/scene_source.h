// SceneSource: one way of getting the scenes a suite films, with a registry, so suite files,
// the command line and research code name every source the same way.
//
// A source turns one entry of a suite's `scenes:` list into scenes. A plain string is a file
// path or glob (the `files` source); a mapping names its source:
//
//   scenes:
//     - ../scenes/*.yaml                        # files
//     - {source: corridor, seeds: [1, 2, 3]}    # a generated family, one scene per seed
//     - {source: pillar-forest, seed: 7}
//
// Built in: `files`, the six seeded families of scene_families.h (corridor, junction, rooms,
// colonnade, traffic, stairs) and the four generators of scene_generator.h (pillar-forest,
// city, switchback, crossings), each at its defaults but the seed. A new source is one
// function and one SceneSources::add call, from anywhere (a test registers its own).
//
// Every scene a source makes carries a fingerprint: for a file, the file's content; for a
// generated scene, its geometry and paths (scene_fingerprint), so a suite re-run after a
// generator changed redoes exactly the runs of the scenes that changed.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/spec.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::experiments {

struct SourcedScene {
  // Null for files (the caller reads the file, and only when it needs the scene).
  std::shared_ptr<const camera::Scene> scene;
  std::string path;         // the file, for the files source; empty for generated scenes
  std::string fingerprint;  // for generated scenes: scene_fingerprint (a file's content is
                            // its fingerprint, hashed by the suite)
};

struct SceneSourceInfo {
  std::string name;         // what `source:` says
  std::string description;  // one line, for listings
  // The entry's fields besides `source` (checked: others are refused with the entry's line).
  std::vector<std::string> fields;
  // The scenes of one entry, in a stable order. `base_dir` resolves relative paths.
  // csp::InputError with the entry's file and line for bad fields.
  std::function<std::vector<SourcedScene>(const csp::Spec& entry, const std::string& base_dir)>
      make;
};

class SceneSources {
 public:
  // The process-wide registry, with the built-in sources.
  static SceneSources& global();
  // Throws std::invalid_argument when the name is taken.
  void add(SceneSourceInfo info);
  bool contains(const std::string& name) const { return sources_.count(name) != 0; }
  std::vector<std::string> names() const;
  const SceneSourceInfo& info(const std::string& name) const;

  // The scenes of one `scenes:` entry: a string is a path or glob (`files`), a mapping names
  // its source. csp::InputError naming the entry's line for an unknown source (listing the
  // known ones), unknown fields, or what the source refuses.
  std::vector<SourcedScene> scenes_of(const csp::Spec& entry, const std::string& base_dir) const;

 private:
  std::map<std::string, SceneSourceInfo> sources_;
};

// A source of one generated scene per seed (`seed: N` or `seeds: [...]`, default 1), each
// fingerprinted: the whole of a new seeded source is its generator and this.
SceneSourceInfo seeded_source(std::string name, std::string description,
                              std::function<camera::Scene(std::uint64_t)> generate);

// Text that changes exactly when what a camera run of the scene sees changes: its name,
// frame rate, character, boxes, areas, movers (actors included), trajectory, level file and
// camera start and profile, every number written round-trippable.
std::string scene_fingerprint(const camera::Scene& scene);

// The seeds an entry asks for: `seed: N` or `seeds: [N, ...]` (default: [1]); integers >= 0.
std::vector<std::uint64_t> entry_seeds(const csp::Spec& entry);

}  // namespace sightline::experiments
