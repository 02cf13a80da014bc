// `sightline scene check SCENE.yaml`: reads and validates a scene file (docs/CAMERA.md) and
// prints its summary: boxes, areas, movers, actors, character, duration, frames, camera and profile. A bad
// file is an InputError ("FILE:LINE:COL: what was expected"), which main turns into a
// message and exit status 2.
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "apps/commands.h"
#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/sources/conversation_generator.h"
#include "sightline/experiments/sources/tracking_shot_generator.h"
#include "sightline/experiments/sources/shot_problems.h"

namespace sightline::apps {
namespace {

std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream out;
  out << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return out.str();
}

std::string plural(std::size_t n, const std::string& word, const std::string& words = "") {
  return std::to_string(n) + " " + (n == 1 ? word : words.empty() ? word + "s" : words);
}

void check_scene(const std::string& path) {
  const camera::Scene scene = camera::read_scene_file(path);
  // Building the camera problem once checks the profile and its extras against the scene.
  const camera::CameraProblem problem(scene);
  const camera::CameraProfile& profile = scene.profile();

  std::cout << "Scene '" << scene.name() << "' (" << path << "): OK\n";
  if (!scene.description().empty()) std::cout << "  " << scene.description() << "\n";
  std::cout << "  boxes:      " << plural(scene.solids().size(), "solid box", "solid boxes");
  if (!scene.solids().empty()) {
    const camera::Aabb b = scene.solid_tree().bounds();
    std::cout << " within " << vec(b.min) << " .. " << vec(b.max);
  }
  std::cout << "\n";
  if (const camera::Level* level = scene.level()) {
    const camera::Aabb b = scene.triangle_index().bounds();
    std::cout << "  level:      " << level->file;
    if (!level->map.empty()) std::cout << " map " << level->map;
    std::cout << " (" << level->format << ", scale " << level->transform.scale << ", up "
              << camera::to_string(level->transform.up) << "): "
              << plural(level->mesh.size(), "triangle") << " within " << vec(b.min) << " .. "
              << vec(b.max) << "; solid volumes: "
              << (level->solid ? level->solid->describe() : std::string("none (mesh)"))
              << "; loaded in " << level->load_seconds << " s\n";
  }
  std::size_t enclosed = 0;
  std::string names;
  for (const camera::Area& a : scene.areas()) {
    enclosed += a.kind == camera::AreaKind::kEnclosed;
    names += (names.empty() ? "" : ", ") + a.name + " (" + camera::to_string(a.kind) + ")";
  }
  std::cout << "  areas:      " << plural(scene.areas().size(), "area");
  if (!scene.areas().empty()) {
    std::cout << ", " << enclosed << " enclosed, " << scene.areas().size() - enclosed
              << " semi-enclosed: " << names;
  }
  std::cout << "\n";
  // Movers: how many, then one line each (name, size, time span of the path), at most 20.
  std::cout << "  movers:     " << plural(scene.movers().size(), "mover") << "\n";
  constexpr std::size_t kListed = 20;
  for (std::size_t i = 0; i < scene.movers().size() && i < kListed; ++i) {
    const camera::Mover& m = scene.movers()[i];
    const Eigen::Vector3d& s = m.size();
    std::cout << "    " << (m.name().empty() ? "mover #" + std::to_string(i + 1) : m.name())
              << " (line " << m.where().line << "): " << s.x() << " x " << s.y() << " x "
              << s.z() << " m, " << plural(m.path().size(), "keyframe");
    if (m.path().size() == 1) {
      std::cout << ", standing at " << vec(m.path().front().position);
    } else {
      std::cout << ", t = " << m.path().front().t << " .. " << m.path().back().t << " s";
    }
    std::cout << "\n";
  }
  if (scene.movers().size() > kListed) {
    std::cout << "    ... and " << scene.movers().size() - kListed << " more\n";
  }
  // Actors: how many, then one line each (they are also among the movers above).
  std::cout << "  actors:     " << plural(scene.actors().size(), "actor");
  if (!scene.actors().empty()) std::cout << " (each also a mover above)";
  std::cout << "\n";
  for (std::size_t i = 0; i < scene.actors().size() && i < kListed; ++i) {
    const camera::Actor& a = scene.actors()[i];
    std::cout << "    " << a.name << " (line " << a.where.line << "): " << a.shape.size.x()
              << " x " << a.shape.size.y() << " x " << a.shape.size.z() << " m, aim "
              << a.shape.look_at_height << " m above the feet, "
              << plural(a.trajectory.keyframes().size(), "keyframe") << ", t = "
              << a.trajectory.start_time() << " .. " << a.trajectory.end_time() << " s\n";
  }
  if (scene.actors().size() > kListed) {
    std::cout << "    ... and " << scene.actors().size() - kListed << " more\n";
  }
  const camera::CharacterShape& c = scene.character();
  std::cout << "  character:  " << c.size.x() << " x " << c.size.y() << " x " << c.size.z()
            << " m, looking at " << c.look_at_height << " m above the feet\n";
  const camera::Trajectory& t = scene.trajectory();
  std::cout << "  trajectory: " << plural(t.keyframes().size(), "keyframe") << ", t = "
            << t.start_time() << " .. " << t.end_time() << " s (" << t.duration() << " s)\n";
  std::cout << "  frames:     " << scene.frame_count() << " at " << scene.frame_rate()
            << " frames per second\n";
  std::cout << "  camera:     start " << vec(scene.start_camera_position())
            << (scene.camera_start()  ? ""
              : scene.level() ? " (the profile's ideal spot, pulled in toward the character "
                                "where a wall is in the way)"
                              : " (the profile's ideal spot)")
            << "\n";
  std::cout << "  profile:    " << profile.name << " (" << scene.profile_source() << "): height "
            << profile.height.desired << " m, distance " << profile.distance.desired
            << " m, orientation " << profile.orientation.desired << " deg";
  if (!profile.extras.empty()) std::cout << ", " << plural(profile.extras.size(), "extra constraint");
  std::cout << "\n";
  std::cout << "  problem:    " << problem.problem().num_variables() << " variables, "
            << plural(problem.problem().num_constraints(), "constraint") << "\n";
}

// A generated scene's text to `out`, or to standard output when it is empty.
void write_scene_text(const std::string& text, const std::string& out) {
  if (out.empty()) {
    std::cout << text;
    return;
  }
  std::ofstream file(out);
  file << text;
  if (!file) throw std::runtime_error("cannot write " + out);
}

}  // namespace

void add_scene_command(CLI::App& app) {
  CLI::App* scene = app.add_subcommand("scene", "work with camera scene files");
  scene->require_subcommand(1);
  CLI::App* check = scene->add_subcommand(
      "check", "validate a scene file and print its summary (boxes, areas, duration, frames, "
               "profile)");
  auto path = std::make_shared<std::string>();
  check->add_option("scene", *path, "scene file (YAML, see docs/CAMERA.md)")->required();
  check->callback([path] { check_scene(*path); });
  CLI::App* problem = scene->add_subcommand(
      "shot-problem", "write problem SEED of the benchmark of shot problems as a scene file "
                      "(experiments/sources/shot_problems.h)");
  auto seed = std::make_shared<std::uint64_t>(1);
  auto out = std::make_shared<std::string>();
  problem->add_option("seed", *seed, "the problem's seed (>= 1)")->required()->check(CLI::PositiveNumber);
  problem->add_option("--out", *out, "write it here (default: standard output)");
  problem->callback([seed, out] { write_scene_text(experiments::shot_problem_yaml(*seed), *out); });
  CLI::App* talk = scene->add_subcommand(
      "conversation", "write the generated conversation SEED (actors and a script, for the "
                      "editor: experiments/sources/conversation_generator.h) as a scene file");
  auto options = std::make_shared<experiments::ConversationOptions>();
  auto talk_out = std::make_shared<std::string>();
  talk->add_option("seed", options->seed, "the conversation's seed (>= 1)")->required()->check(CLI::PositiveNumber);
  talk->add_option("--seconds", options->seconds, "its length (default 40)")->check(CLI::Range(6.0, 3600.0));
  talk->add_option("--layout", options->layout,
                   "0 standing, 1 walking, 2 circling, 3 someone comes in (default: by seed)")
      ->check(CLI::Range(0, 3));
  talk->add_option("--out", *talk_out, "write it here (default: standard output)");
  talk->callback([options, talk_out] {
    experiments::generate_conversation(*options);  // valid by the scene reader's rules
    write_scene_text(experiments::conversation_yaml(*options), *talk_out);
  });
  CLI::App* tracking = scene->add_subcommand(
      "tracking-shot", "write the generated tracking shot SEED (people moving and a shot: "
                       "block: experiments/sources/tracking_shot_generator.h) as a scene file");
  auto shot = std::make_shared<experiments::TrackingShotOptions>();
  auto shot_out = std::make_shared<std::string>();
  tracking->add_option("seed", shot->seed, "the shot's seed (>= 1)")->required()->check(CLI::PositiveNumber);
  tracking->add_option("--seconds", shot->seconds, "its length (default 12)")->check(CLI::Range(4.0, 600.0));
  tracking->add_option("--layout", shot->layout,
                       "0 street, 1 corner chase, 2 crossing, 3 circling (default: by seed)")
      ->check(CLI::Range(0, 3));
  tracking->add_option("--out", *shot_out, "write it here (default: standard output)");
  tracking->callback([shot, shot_out] {
    experiments::generate_tracking_shot(*shot);  // valid by the scene reader's rules
    write_scene_text(experiments::tracking_shot_yaml(*shot), *shot_out);
  });
}

}  // namespace sightline::apps
