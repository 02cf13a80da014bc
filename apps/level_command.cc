// `sightline level walk LEVEL [--map NAME] [--scale S] [--up y|z] --walks N --seed S --out DIR`:
// loads a level (a Quake III map or any mesh assimp reads, domains/camera/level/level.h),
// makes N walks on it as a person walks them (experiments/sources/level_walk.h: Recast/Detour, every
// person and walk setting an option) and writes one scene file per walk to DIR, named
// <map or file stem>-walk<k>.yaml. Prints the navigation mesh and, per walk, the file, its
// seconds, metres and keyframes. Bad input (no level, unknown map, N < 1, a DIR that cannot
// be written, a level with no walkable region) is an exception: main prints it, exit 2.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "apps/commands.h"
#include "sightline/domains/camera/level/level.h"
#include "sightline/experiments/sources/level_walk.h"
#include "sightline/experiments/sources/spawn_points.h"

namespace sightline::apps {
namespace {

namespace fs = std::filesystem;

struct LevelWalkArgs {
  std::string file, map, out, up;
  double scale = 0;
  bool scale_given = false;
  experiments::WalkOptions options;
};

std::string fixed(double v, int decimals) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << v;
  return out.str();
}

void walk_level(const LevelWalkArgs& args) {
  if (std::string bad = args.options.validate(); !bad.empty()) {
    // The field's name as the option is spelled.
    static const std::pair<const char*, const char*> kOptions[] = {
        {"agent_radius", "--agent-radius"},
        {"agent_height", "--agent-height"},
        {"agent_step", "--agent-step"},
        {"max_slope_degrees", "--max-slope"},
        {"cell_size", "--cell-size"},
        {"cell_height", "--cell-height"},
        {"min_speed", "--min-speed"},
        {"max_speed", "--max-speed"},
        {"min_seconds", "--min-seconds"},
        {"max_seconds", "--max-seconds"},
        {"stop_probability", "--stop-probability"},
        {"turn_rate_degrees", "--turn-rate"},
        {"walks", "--walks"}};
    for (const auto& [field, option] : kOptions) {
      const std::string prefix = std::string(field) + ":";
      if (bad.rfind(prefix, 0) == 0) bad = option + bad.substr(std::string(field).size());
    }
    throw std::invalid_argument(bad);
  }
  camera::LevelSpec spec;
  spec.file = args.file;
  spec.map = args.map;
  if (args.scale_given) spec.scale = args.scale;
  if (!args.up.empty()) spec.up = camera::up_axis_from_string(args.up);
  const camera::Level level = camera::load_level(spec);
  std::cout << "Level " << args.file << (level.map.empty() ? "" : " (map " + level.map + ")")
            << ": " << level.format << ", " << level.mesh.size() << " triangles, loaded in "
            << fixed(level.load_seconds, 2) << " s\n";

  // The folder first: a run of minutes must not end in "cannot write".
  std::error_code error;
  fs::create_directories(args.out, error);
  if (error || !fs::is_directory(args.out)) {
    throw std::runtime_error("cannot create the output folder " + args.out +
                             (error ? ": " + error.message() : ""));
  }

  const std::vector<Eigen::Vector3d> spawns =
      experiments::quake3_spawn_points(spec, level.transform);
  const experiments::LevelWalks result =
      experiments::generate_walks(level.mesh, args.options, spawns, level.solid.get());
  const experiments::NavigationMeshStats& nav = result.navigation;
  std::cout << "Navigation mesh: " << nav.polygons << " polygons, " << nav.region_polygons
            << " in the connected region walked (" << fixed(nav.region_area, 1) << " of "
            << fixed(nav.walkable_area, 1) << " m^2 walkable), " << nav.grid_width << " x "
            << nav.grid_depth << " cells of " << nav.cell_size << " x " << nav.cell_height
            << " m, built in " << fixed(nav.build_seconds, 2) << " s\n";
  if (nav.anchors > 0) {
    std::cout << "  the region walked holds " << nav.region_anchors << " of the map's "
              << nav.anchors << " spawn points\n";
    // Maps of islands (delta, czest2ctf, cbctf1, oa_ctf2, oa_koth2 ...): say why the walks
    // see so little of them, rather than leave the user to guess at a bug.
    if (2 * nav.region_anchors < nav.anchors) {
      std::cout << "  note: the other " << nav.anchors - nav.region_anchors
                << " spawn points are off it, on floors not reachable on foot from it (jump pads, "
                   "teleporters, lifts, jumps: walks take none of them), so every walk "
                   "keeps to this part of the map\n";
    }
  }
  if (!nav.note.empty()) std::cout << "  note: " << nav.note << "\n";

  // The level as the scene files name it: as given when absolute (installed maps), else
  // relative to the folder the scenes are written to.
  const fs::path level_path = fs::path(args.file).is_absolute()
                                  ? fs::path(args.file)
                                  : fs::relative(fs::absolute(args.file), fs::absolute(args.out));
  const std::string base = !level.map.empty() ? fs::path(level.map).stem().string()
                                              : fs::path(args.file).stem().string();
  std::optional<camera::UpAxis> up;
  if (!args.up.empty()) up = camera::up_axis_from_string(args.up);
  const std::size_t n = result.walks.size();
  for (std::size_t k = 0; k < n; ++k) {
    const experiments::LevelWalk& walk = result.walks[k];
    const std::string name = base + "-walk" + std::to_string(k + 1);
    const double seconds = walk.keyframes.back().t;
    const std::string description =
        "walk " + std::to_string(k + 1) + " of " + std::to_string(n) + " on " + base + ", seed " +
        std::to_string(args.options.seed) + ": " + fixed(walk.length_metres, 1) + " m in " +
        fixed(seconds, 1) + " s, " + std::to_string(walk.stops) + " stops (sightline level walk)";
    const fs::path file = fs::path(args.out) / (name + ".yaml");
    std::ofstream stream(file, std::ios::binary);
    stream << experiments::walk_scene_yaml(
        name, description, level_path.generic_string(), level.map.empty() ? "" : base, walk,
        args.scale_given ? std::optional<double>(args.scale) : std::nullopt, up);
    stream.close();
    if (!stream) throw std::runtime_error("cannot write " + file.string());
    std::cout << "  " << file.string() << ": " << fixed(seconds, 1) << " s, "
              << fixed(walk.length_metres, 1) << " m, " << walk.keyframes.size() << " keyframes, "
              << walk.stops << " stops\n";
  }
  std::cout << n << (n == 1 ? " walk" : " walks") << " in " << fixed(result.seconds, 2) << " s\n";
}

}  // namespace

void add_level_command(CLI::App& app) {
  CLI::App* level =
      app.add_subcommand("level", "work with level geometry (Quake III maps, meshes)");
  level->require_subcommand(1);
  CLI::App* walk = level->add_subcommand(
      "walk",
      "make walks on a level as a person walks them (Recast/Detour) and write them as "
      "scene files");
  auto args = std::make_shared<LevelWalkArgs>();
  experiments::WalkOptions& o = args->options;
  walk->add_option("level", args->file, "level file: .pk3, .bsp, or a mesh (glTF, OBJ, ...)")
      ->required();
  walk->add_option("--map", args->map, "the map inside a .pk3 (e.g. oa_thor)");
  CLI::Option* scale =
      walk->add_option("--scale", args->scale, "metres per file unit (default: the format's)");
  walk->add_option("--up", args->up, "the file's up axis (default: the format's)")
      ->check(CLI::IsMember({"y", "z"}));
  walk->add_option("--walks", o.walks, "how many walks")->required();
  walk->add_option("--seed", o.seed, "random seed: the same seed writes the same files")
      ->required();
  walk->add_option("--out", args->out, "folder for the scene files")->required();
  walk->add_option("--agent-radius", o.agent_radius, "the person's radius, m")
      ->capture_default_str();
  walk->add_option("--agent-height", o.agent_height, "the person's height, m")
      ->capture_default_str();
  walk->add_option("--agent-step", o.agent_step, "the highest step walked up, m")
      ->capture_default_str();
  walk->add_option("--max-slope", o.max_slope_degrees, "the steepest floor walked, degrees")
      ->capture_default_str();
  walk->add_option("--cell-size", o.cell_size, "Recast's cell size across, m")
      ->capture_default_str();
  walk->add_option("--cell-height", o.cell_height, "Recast's cell height, m")
      ->capture_default_str();
  walk->add_option("--min-speed", o.min_speed, "slowest walking speed, m/s")->capture_default_str();
  walk->add_option("--max-speed", o.max_speed, "fastest walking speed, m/s")->capture_default_str();
  walk->add_option("--min-seconds", o.min_seconds, "shortest walk, s")->capture_default_str();
  walk->add_option("--max-seconds", o.max_seconds, "longest walk, s")->capture_default_str();
  walk->add_option("--stop-probability", o.stop_probability,
                   "chance of a stop and a turn on the spot at each corner")
      ->capture_default_str();
  walk->add_option("--turn-rate", o.turn_rate_degrees, "turning speed, degrees/s")
      ->capture_default_str();
  walk->callback([args, scale] {
    args->scale_given = scale->count() > 0;
    walk_level(*args);
  });
}

}  // namespace sightline::apps
