#include "sightline/domains/camera/scene_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/spec_reading.h"

namespace sightline::camera {
namespace {

using csp::Spec;
using detail::format_number;
using detail::read_positive;
using detail::read_vector3;

std::string describe_box(const Aabb& b) {
  auto v = [](const Eigen::Vector3d& p) {
    return "[" + format_number(p.x()) + ", " + format_number(p.y()) + ", " +
           format_number(p.z()) + "]";
  };
  return "min " + v(b.min) + " max " + v(b.max);
}

// min/max of a box entry, with min < max on every axis.
Aabb read_box(const Spec& entry, const std::string& what) {
  Aabb box{read_vector3(entry.at("min"), "the min corner of " + what),
           read_vector3(entry.at("max"), "the max corner of " + what)};
  static const char* kAxis[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (!(box.min[i] < box.max[i])) {
      entry.fail("expected min < max on every axis for " + what + ", but on " + kAxis[i] +
                 " min is " + format_number(box.min[i]) + " and max is " +
                 format_number(box.max[i]) + " (boxes must have a positive size)");
    }
  }
  return box;
}

// The list under `key`, empty when the key is absent or written with nothing after it.
const std::vector<Spec>& optional_list(const Spec& spec, const std::string& key,
                                       const std::string& what) {
  static const std::vector<Spec> kNone;
  const Spec* field = spec.find(key);
  if (field == nullptr || field->is_null()) return kNone;
  return field->items(what);
}

std::vector<SolidBox> read_solids(const Spec& spec) {
  // Names are labels (FORMATS.md): two boxes may share one, as the two halves of a wall
  // split by a door often do.
  std::vector<SolidBox> solids;
  for (const Spec& entry : optional_list(spec, "boxes", "a list of boxes")) {
    if (!entry.is_map()) entry.fail("expected a box {name: ..., min: [x, y, z], max: [x, y, z]}");
    entry.check_keys({"name", "min", "max"});
    SolidBox box;
    if (const Spec* n = entry.find("name")) box.name = n->as_string("a box name");
    const std::string what = box.name.empty()
                                 ? "box #" + std::to_string(solids.size() + 1)
                                 : "box '" + box.name + "'";
    box.box = read_box(entry, what);
    box.where = entry.where();
    solids.push_back(std::move(box));
  }
  return solids;
}

std::vector<Area> read_areas(const Spec& spec) {
  std::vector<Area> areas;  // names are labels here too, not keys
  for (const Spec& entry : optional_list(spec, "areas", "a list of areas")) {
    if (!entry.is_map()) {
      entry.fail("expected an area {name: ..., kind: enclosed, min: [x, y, z], max: [x, y, z]}");
    }
    entry.check_keys({"name", "kind", "min", "max"});
    Area area;
    area.name = entry.find("name") ? entry.at("name").as_string("an area name")
                                   : "area #" + std::to_string(areas.size() + 1);
    const Spec& kind = entry.at("kind");
    const auto parsed = area_kind_from_string(kind.as_string("an area kind"));
    if (!parsed) kind.fail("expected an area kind: enclosed or semi-enclosed, got " + kind.preview());
    area.kind = *parsed;
    area.box = read_box(entry, "area '" + area.name + "'");
    area.where = entry.where();
    areas.push_back(std::move(area));
  }
  return areas;
}

// The `movers:` block (FORMATS.md): boxes of a fixed size moving on their own keyframes.
// Names are labels as for boxes (optional, may repeat); unknown fields are refused as for
// boxes. One keyframe is a mover that stands still.
std::vector<Mover> read_movers(const Spec& spec) {
  std::vector<Mover> movers;
  for (const Spec& entry : optional_list(spec, "movers", "a list of movers")) {
    if (!entry.is_map()) {
      entry.fail("expected a mover {name: ..., size: [sx, sy, sz], path: [{t: s, position: "
                 "[x, y, z]}, ...]}, got " + entry.preview());
    }
    entry.check_keys({"name", "size", "path"});
    std::string name;
    if (const Spec* n = entry.find("name")) name = n->as_string("a mover name");
    const std::string what = name.empty() ? "mover #" + std::to_string(movers.size() + 1)
                                          : "mover '" + name + "'";
    const Spec& size_field = entry.at("size");
    const Eigen::Vector3d size = read_vector3(size_field, "the size of " + what);
    static const char* kAxis[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      if (!(size[i] > 0)) {
        size_field.fail("expected the size of " + what + " as 3 numbers > 0, but on " +
                        kAxis[i] + " it is " + format_number(size[i]));
      }
    }
    const Spec& path_field = entry.at("path");
    // "path:" with nothing after it: a null placed where the next token starts, often on a
    // later line, so the mover's own line is the better place to name.
    if (path_field.is_null()) entry.fail("expected at least one keyframe in the path of " + what);
    std::vector<MoverKeyframe> path;
    std::vector<int> lines;  // of each keyframe, to name both when times do not increase
    for (const Spec& key : path_field.items("the path of " + what +
                                            " as a list of keyframes {t: s, position: [x, y, z]}")) {
      const std::string key_what =
          "keyframe #" + std::to_string(path.size() + 1) + " of " + what;
      if (!key.is_map()) {
        key.fail("expected " + key_what + " as {t: s, position: [x, y, z]}, got " + key.preview());
      }
      key.check_keys({"t", "position"});
      MoverKeyframe k;
      const Spec& t = key.at("t");
      k.t = t.as_number("the time of " + key_what + " (seconds)");
      if (!path.empty() && !(k.t > path.back().t)) {
        t.fail("expected the keyframe times of " + what + " to increase strictly: keyframe #" +
               std::to_string(path.size() + 1) + " (line " + std::to_string(key.where().line) +
               ") has t = " + format_number(k.t) + " but keyframe #" +
               std::to_string(path.size()) + " (line " + std::to_string(lines.back()) +
               ") has t = " + format_number(path.back().t));
      }
      k.position = read_vector3(key.at("position"), "the position of " + key_what);
      path.push_back(k);
      lines.push_back(key.where().line);
    }
    if (path.empty()) path_field.fail("expected at least one keyframe in the path of " + what);
    try {
      movers.emplace_back(std::move(name), size, std::move(path), entry.where());
    } catch (const std::invalid_argument& e) {
      entry.fail(std::string("a bad ") + what + ": " + e.what());  // checked above; defence
    }
  }
  return movers;
}

// The `level:` block (FORMATS.md): the file relative to the scene's folder, an optional
// map, scale and up; the level is loaded here, so a bad level file is reported with the
// block's line.
std::shared_ptr<const Level> read_level(const Spec& spec, const std::string& base_dir) {
  const Spec* block = spec.find("level");
  if (block == nullptr || block->is_null()) return nullptr;
  if (!block->is_map()) {
    block->fail("expected a level {file: PATH, map: NAME, scale: metres per unit, up: y|z}");
  }
  block->check_keys({"file", "map", "scale", "up"});
  LevelSpec level;
  const Spec& file = block->at("file");
  const std::string path = file.as_string("the level's file path");
  if (path.empty()) file.fail("expected the level's file path, got an empty string");
  const std::filesystem::path given(path);
  level.file = given.is_absolute() || base_dir.empty() ? path
                                                       : (std::filesystem::path(base_dir) / given).string();
  if (const Spec* map = block->find("map")) level.map = map->as_string("a map name");
  if (const Spec* scale = block->find("scale")) {
    level.scale = read_positive(*scale, "the level's scale (metres per file unit)");
  }
  if (const Spec* up = block->find("up")) {
    const auto axis = up_axis_from_string(up->as_string("the level's up axis"));
    if (!axis) up->fail("expected the level's up axis: y or z, got " + up->preview());
    level.up = *axis;
  }
  level.where = block->where();
  return std::make_shared<const Level>(load_level(level));
}

// A person's size and look-at height from the fields of `block` (the `character:` block or
// an actor's entry), defaults where absent.
CharacterShape read_shape(const Spec& block, const std::string& whose) {
  CharacterShape shape;
  if (const Spec* size = block.find("size")) {
    shape.size = read_vector3(*size, whose + " size");
    if (!(shape.size.minCoeff() > 0)) {
      size->fail("expected " + whose + " size as 3 numbers > 0, got " + size->preview());
    }
  }
  if (const Spec* h = block.find("look_at_height")) {
    shape.look_at_height = read_positive(*h, whose + " look-at height (metres above the feet)");
    if (shape.look_at_height > shape.size.y()) {
      h->fail("expected the look-at height to be at most " + whose + " height " +
              format_number(shape.size.y()) + ", got " + h->preview());
    }
  } else if (shape.look_at_height > shape.size.y()) {
    block.fail("the default look-at height 1.5 is above " + whose + " height " +
               format_number(shape.size.y()) + "; give look_at_height");
  }
  return shape;
}

CharacterShape read_character(const Spec& spec) {
  const Spec* block = spec.find("character");
  if (block == nullptr || block->is_null()) return CharacterShape{};
  if (!block->is_map()) block->fail("expected the character {size: [x, y, z], look_at_height: h}");
  block->check_keys({"size", "look_at_height"});
  return read_shape(*block, "the character's");
}

// Keyframes {t, position, yaw} of `list` (the scene's trajectory or an actor's); `whose` is
// empty for the character, "of actor 'bob'" for an actor.
std::vector<Keyframe> read_keyframes(const Spec& list, const std::string& whose,
                                     std::vector<csp::SourceLocation>& where) {
  const std::string of = whose.empty() ? "" : " " + whose;
  std::vector<Keyframe> keyframes;
  for (const Spec& entry : list.items("a list of keyframes {t, position, yaw}")) {
    if (!entry.is_map()) entry.fail("expected a keyframe {t: s, position: [x, y, z], yaw: deg}");
    entry.check_keys({"t", "position", "yaw"});
    const std::string what = "keyframe #" + std::to_string(keyframes.size() + 1) + of;
    Keyframe k;
    k.t = entry.at("t").as_number("the time of " + what + " (seconds)");
    if (!keyframes.empty() && !(k.t > keyframes.back().t)) {
      entry.at("t").fail("expected keyframe times to increase: " + what + " has t = " +
                         format_number(k.t) + " but the keyframe before has t = " +
                         format_number(keyframes.back().t));
    }
    k.position = read_vector3(entry.at("position"), "the position of " + what);
    k.yaw = entry.at("yaw").as_number("the yaw of " + what + " (degrees)");
    keyframes.push_back(k);
    where.push_back(entry.where());
  }
  if (keyframes.empty()) list.fail("expected at least one keyframe in the trajectory" + of);
  return keyframes;
}

// The `actors:` block (FORMATS.md "Actors"): each a unique name, an optional size and
// look-at height, and a trajectory. "character" names the followed character, which only a
// scene without `trajectory:` may give this way.
std::vector<Actor> read_actors(const Spec& spec, bool has_trajectory) {
  std::vector<Actor> actors;
  std::map<std::string, int> lines;  // name -> line, for repeated names
  for (const Spec& entry : optional_list(spec, "actors", "a list of actors")) {
    if (!entry.is_map()) {
      entry.fail("expected an actor {name: ..., size: [sx, sy, sz], look_at_height: h, "
                 "trajectory: [{t: s, position: [x, y, z], yaw: deg}, ...]}, got " +
                 entry.preview());
    }
    entry.check_keys({"name", "size", "look_at_height", "trajectory"});
    Actor a;
    a.name = entry.at("name").as_string("an actor's name");
    if (a.name.empty()) entry.at("name").fail("expected a non-empty actor name");
    if (const auto it = lines.find(a.name); it != lines.end()) {
      entry.at("name").fail("actor name '" + a.name + "' is taken by the actor on line " +
                            std::to_string(it->second) + ": names are unique among the actors");
    }
    if (a.name == "character" && has_trajectory) {
      entry.at("name").fail("the scene has a trajectory:, which is the character's, so no actor "
                            "may be named 'character'");
    }
    lines[a.name] = entry.where().line;
    const std::string whose = "actor '" + a.name + "'";
    a.shape = read_shape(entry, whose + "'s");
    const Spec& path = entry.at("trajectory");
    if (path.is_null()) entry.fail("expected at least one keyframe in the trajectory of " + whose);
    a.trajectory = Trajectory(read_keyframes(path, "of " + whose, a.keyframe_where));
    a.where = entry.where();
    actors.push_back(std::move(a));
  }
  return actors;
}

std::string solid_name(const Scene& scene, std::size_t i) {
  const SolidBox& b = scene.solids()[i];
  std::string name = b.name.empty() ? "box #" + std::to_string(i + 1) : "'" + b.name + "'";
  return "solid box " + name + " (line " + std::to_string(b.where.line) + ")";
}

// The character's body must never be inside a solid box: at the keyframes (reported naming
// the keyframe) and at every simulated frame in between.
void check_trajectory(const Scene& scene, const std::vector<csp::SourceLocation>& where) {
  const auto& keys = scene.trajectory().keyframes();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const Aabb body = scene.character().body_at(keys[k].position);
    if (auto hit = scene.solid_overlapping(body)) {
      throw csp::InputError(where[k], "keyframe #" + std::to_string(k + 1) + " (t = " +
                                          format_number(keys[k].t) +
                                          ") puts the character's box (" + describe_box(body) +
                                          ") inside " + solid_name(scene, *hit));
    }
  }
  for (std::size_t f = 0; f < scene.frame_count(); ++f) {
    const double t = scene.frame_time(f);
    const CharacterState s = scene.character_at(t);
    const Aabb body = scene.character().body_at(s.position);
    if (auto hit = scene.solid_overlapping(body)) {
      const std::size_t k = scene.trajectory().segment_at(t);
      throw csp::InputError(
          where[k], "between keyframe #" + std::to_string(k + 1) + " and keyframe #" +
                        std::to_string(k + 2) + " the character's box passes through " +
                        solid_name(scene, *hit) + " (first at frame " + std::to_string(f) +
                        ", t = " + format_number(t) + ")");
    }
  }
}

// The people a shot or a script may name: the followed character (when someone is chased)
// and the actors.
std::vector<std::string> people_of(const Scene& scene) {
  std::vector<std::string> names;
  if (scene.has_character()) names.push_back(scene.character_name());
  for (const Actor& a : scene.actors()) names.push_back(a.name);
  return names;
}

// shot:, shots: and script: (FORMATS.md "Shots", "Script and named shots").
void read_direction(const Spec& spec, Scene& scene) {
  const std::vector<std::string> people = people_of(scene);
  if (const Spec* shot = spec.find("shot")) {
    scene.set_shot(std::make_shared<const Shot>(read_shot(*shot, people)));
  }
  std::vector<std::shared_ptr<const Shot>> named;
  std::map<std::string, int> lines;
  for (const Spec& entry : optional_list(spec, "shots", "a list of named shots")) {
    if (!entry.is_map()) entry.fail("expected a named shot {name: ..., region: ..., properties: [...]}");
    auto shot = std::make_shared<const Shot>(read_shot(entry, people, true));
    if (const auto it = lines.find(shot->name); it != lines.end()) {
      entry.at("name").fail("shot name '" + shot->name + "' is taken by the shot on line " +
                            std::to_string(it->second));
    }
    lines[shot->name] = entry.where().line;
    named.push_back(std::move(shot));
  }
  std::shared_ptr<const std::vector<ScriptEntry>> script;
  if (const Spec* s = spec.find("script"); s != nullptr && !s->is_null()) {
    script = std::make_shared<const std::vector<ScriptEntry>>(read_script(*s, people));
  }
  scene.set_direction(std::move(named), std::move(script));
}

}  // namespace

Scene parse_scene(const csp::Spec& spec, const std::string& base_dir) {
  if (!spec.is_map()) spec.fail("expected a scene (a mapping with name, boxes, trajectory ...)");
  spec.check_keys({"name", "description", "frame_rate", "character", "level", "boxes", "areas",
                   "movers", "actors", "trajectory", "camera", "shot", "shots", "script"});
  const std::string name = spec.at("name").as_string("the scene's name");
  if (name.empty()) spec.at("name").fail("expected a non-empty scene name");
  double frame_rate = 60;
  if (const Spec* fr = spec.find("frame_rate")) {
    frame_rate = read_positive(*fr, "the frame rate (frames per second)");
  }
  CharacterShape character = read_character(spec);
  std::vector<SolidBox> solids = read_solids(spec);
  std::vector<Area> areas = read_areas(spec);
  std::vector<Mover> movers = read_movers(spec);
  const Spec* trajectory_field = spec.find("trajectory");
  std::vector<Actor> actors = read_actors(spec, trajectory_field != nullptr);
  std::vector<csp::SourceLocation> keyframe_where;
  Trajectory trajectory;
  bool nobody_chased = false;
  if (trajectory_field != nullptr) {
    trajectory = Trajectory(read_keyframes(*trajectory_field, "", keyframe_where));
  } else {
    // The followed character may be the actor named "character" (FORMATS.md "Actors").
    const auto followed = std::find_if(actors.begin(), actors.end(),
                                       [](const Actor& a) { return a.name == "character"; });
    if (actors.empty()) spec.at("trajectory");  // missing required field 'trajectory'
    if (spec.find("character")) {
      spec.at("character").fail("the character is the actor named 'character' here: give its "
                                "size and look_at_height there, not in a character: block");
    }
    if (followed != actors.end()) {
      character = followed->shape;
      trajectory = followed->trajectory;
      keyframe_where = followed->keyframe_where;
      actors.erase(followed);
    } else if (const Spec* shot = spec.find("shot")) {
      // Nobody is chased: the frames follow the shot's first target (FORMATS.md "Actors").
      std::vector<std::string> names;
      for (const Actor& a : actors) names.push_back(a.name);
      const std::string first = read_shot(*shot, names).targets().front();
      const auto target = std::find_if(actors.begin(), actors.end(),
                                       [&](const Actor& a) { return a.name == first; });
      character = target->shape;
      trajectory = target->trajectory;
      keyframe_where = target->keyframe_where;
      nobody_chased = true;
    } else if (spec.find("shots") || spec.find("script")) {
      // Nobody is chased and an editor films them: the frames follow the first actor.
      character = actors.front().shape;
      trajectory = actors.front().trajectory;
      keyframe_where = actors.front().keyframe_where;
      nobody_chased = true;
    } else {
      spec.fail("expected a trajectory: (the character's), an actor named 'character' to "
                "follow, a shot: block framing the actors, or a script: or shots: for an "
                "editor (FORMATS.md \"Actors\")");
    }
  }
  if (trajectory.duration() * frame_rate > kMaxSceneFrames) {
    (trajectory_field ? *trajectory_field : spec).fail("the trajectory lasts " + format_number(trajectory.duration()) +
                               " s, which at " + format_number(frame_rate) +
                               " frames per second is more than " +
                               format_number(kMaxSceneFrames) + " frames");
  }

  std::shared_ptr<const Level> level = read_level(spec, base_dir);
  Scene scene(name, std::move(solids), std::move(areas), character, std::move(trajectory),
              frame_rate);
  scene.set_level(std::move(level));
  scene.set_movers(std::move(movers));
  scene.set_actors(std::move(actors));
  if (nobody_chased) scene.set_no_character();
  if (const Spec* d = spec.find("description")) scene.set_description(d->as_string("a description"));
  read_direction(spec, scene);

  // Without camera.profile the scene gets the project's default camera, its best.
  scene.set_profile(preset_profile(kDefaultPreset), std::string("preset ") + kDefaultPreset);
  const Spec* camera = spec.find("camera");
  if (camera != nullptr && !camera->is_null()) {
    if (!camera->is_map()) camera->fail("expected camera settings {start: [x, y, z], profile: ...}");
    camera->check_keys({"start", "profile"});
    if (const Spec* p = camera->find("profile")) {
      std::string source;
      CameraProfile profile = resolve_profile(*p, base_dir, source);
      scene.set_profile(std::move(profile), source);
    }
    if (const Spec* start = camera->find("start")) {
      const Eigen::Vector3d p = read_vector3(*start, "the camera's start position");
      if (auto nearest = scene.solid_tree().nearest(p, 0.0)) {
        start->fail("the camera's start position is inside " + solid_name(scene, nearest->box));
      }
      if (!scene.open_at(p)) {
        start->fail("the camera's start position is inside the level's solid matter or "
                    "outside its world");
      }
      scene.set_camera_start(p);
    }
  }
  check_trajectory(scene, keyframe_where);
  // Builds the camera problem once: a bad extra is reported now, with its line.
  try {
    CameraProblem check(scene);
  } catch (const std::invalid_argument& e) {
    spec.fail(e.what());
  }
  return scene;
}

Scene read_scene_file(const std::string& path) {
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return parse_scene(csp::read_yaml_file(path), dir);
}

}  // namespace sightline::camera
