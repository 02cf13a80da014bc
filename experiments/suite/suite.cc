#include "sightline/experiments/suite/suite.h"

#include <glob.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <set>
#include <sstream>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/experiments/runs/controllers.h"
#include "sightline/experiments/runs/edit_run.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/file_globs.h"
#include "sightline/experiments/sources/scene_source.h"
#include "sightline/experiments/suite/suite_problem.h"
#include "sightline/experiments/suite/suite_comparisons.h"
#include "sightline/solvers/registry.h"

namespace sightline::experiments {
namespace {

using csp::Spec;

// A scalar or a list of scalars, as a list.
std::vector<Spec> one_or_many(const Spec& value) {
  if (value.is_list()) return value.items();
  return {value};
}

std::vector<std::uint64_t> read_seeds(const Spec* value) {
  if (!value) return {1};
  std::vector<std::uint64_t> seeds;
  for (const Spec& s : one_or_many(*value)) {
    const long long seed = s.as_integer("a seed: an integer >= 0");
    if (seed < 0) s.fail("expected a seed: an integer >= 0, got " + s.preview());
    seeds.push_back(static_cast<std::uint64_t>(seed));
  }
  if (seeds.empty()) value->fail("expected at least one seed");
  return seeds;
}

solvers::OptionValues read_options(const Spec* value) {
  solvers::OptionValues options;
  if (!value) return options;
  if (!value->is_map()) value->fail("expected a mapping of solver options (key: value)");
  for (const auto& [key, v] : value->fields()) {
    options[key] = v.as_string("a scalar option value");
  }
  return options;
}

std::string options_text(const solvers::OptionValues& options) {
  std::string text;
  for (const auto& [k, v] : options) text += (text.empty() ? "" : ",") + k + "=" + v;
  return text;
}

void require_unique(std::set<std::string>& seen, const std::string& label, const Spec& where,
                    const std::string& what) {
  if (!seen.insert(label).second) {
    where.fail("duplicate " + what + " label '" + label + "': give one of them a `label:`");
  }
}

void read_controller(const Spec& spec, camera::ChaseCameraOptions& o) {
  spec.check_keys({"visibility_guard", "max_speed", "max_acceleration", "escape_speed",
                   "response_time", "target_smoothing", "target_smoothing_stages",
                   "min_shot_seconds", "stuck_seconds", "backing_speed"});
  o.visibility_guard = spec.bool_or("visibility_guard", o.visibility_guard);
  o.max_speed = spec.number_or("max_speed", o.max_speed);
  o.max_acceleration = spec.number_or("max_acceleration", o.max_acceleration);
  o.escape_speed = spec.number_or("escape_speed", o.escape_speed);
  o.response_time = spec.number_or("response_time", o.response_time);
  o.target_smoothing = spec.number_or("target_smoothing", o.target_smoothing);
  if (const Spec* stages = spec.find("target_smoothing_stages")) {
    constexpr int kMax = camera::ChaseCameraOptions::kMaxSmoothingStages;
    const long long k =
        stages->as_integer("a number of low-pass stages, 1 to " + std::to_string(kMax));
    if (k < 1 || k > kMax) {
      stages->fail("target_smoothing_stages must be 1 to " + std::to_string(kMax) + ", got " +
                   std::to_string(k));
    }
    o.target_smoothing_stages = static_cast<int>(k);
  }
  o.min_shot_seconds = spec.number_or("min_shot_seconds", o.min_shot_seconds);
  o.stuck_seconds = spec.number_or("stuck_seconds", o.stuck_seconds);
  o.backing_speed = spec.number_or("backing_speed", o.backing_speed);
  if (const std::string why = o.validate(); !why.empty()) spec.fail(why);
}

std::string controller_text(const camera::ChaseCameraOptions& o) {
  std::ostringstream out;
  out.precision(17);
  out << "guard=" << o.visibility_guard << ",speed=" << o.max_speed
      << ",accel=" << o.max_acceleration << ",response=" << o.response_time
      << ",smoothing=" << o.target_smoothing << ",shot=" << o.min_shot_seconds
      << ",stuck=" << o.stuck_seconds << ",backing=" << o.backing_speed;
  // Fields added later appear only when they differ from their default, so the run ids of
  // existing suites (which hash this text) stay the same.
  if (o.target_smoothing_stages != 1) out << ",stages=" << o.target_smoothing_stages;
  if (o.escape_speed != camera::ChaseCameraOptions{}.escape_speed) {
    out << ",escape=" << o.escape_speed;
  }
  return out.str();
}

// `limits: {wall_seconds: S, cpu_seconds: S, memory_mb: M}`, each optional, over `limits`.
RunLimits read_limits(const Spec& spec, RunLimits limits) {
  if (!spec.is_map()) {
    spec.fail("expected limits: a mapping {wall_seconds: S, cpu_seconds: S, memory_mb: MB}");
  }
  spec.check_keys({"wall_seconds", "cpu_seconds", "memory_mb"});
  for (const char* key : {"wall_seconds", "cpu_seconds"}) {
    if (const Spec* v = spec.find(key)) {
      const std::string what =
          std::string("a ") + (key[0] == 'w' ? "wall" : "CPU") + " time limit in seconds > 0";
      const double seconds = v->as_number(what);
      if (!(seconds > 0)) v->fail("expected " + what + ", got " + v->preview());
      (key[0] == 'w' ? limits.wall_seconds : limits.cpu_seconds) = seconds;
    }
  }
  if (const Spec* v = spec.find("memory_mb")) {
    const std::string what =
        "a memory limit in MB, an integer >= " + std::to_string(kMinimumMemoryMb) +
        " (the program needs that much to start)";
    const long long mb = v->as_integer(what);
    if (mb < static_cast<long long>(kMinimumMemoryMb)) {
      v->fail("expected " + what + ", got " + v->preview());
    }
    limits.memory_mb = static_cast<std::uint64_t>(mb);
  }
  return limits;
}

void read_camera(const Spec& camera_spec, const std::string& base_dir,
                 const std::optional<SuiteLoadOnly>& only, Suite& suite) {
  camera_spec.check_keys({"scenes", "solvers", "profiles", "seeds"});
  // Scenes.
  std::set<std::string> labels;
  std::set<std::string> paths;
  // Each entry names a scene source (sources/scene_source.h): a file or glob, or a
  // generator {source: NAME, seeds: [...]}.
  const Spec& scenes = camera_spec.at("scenes");
  for (const Spec& entry : one_or_many(scenes)) {
    for (SourcedScene& sourced : SceneSources::global().scenes_of(entry, base_dir)) {
      const std::string& path = sourced.path;
      if (!path.empty() && !paths.insert(path).second) continue;  // a file named twice: once
      SuiteScene s;
      s.path = path;
      s.fingerprint = std::move(sourced.fingerprint);
      if (only &&
          !(only->kind == SuiteRun::Kind::kCamera && only->subject == suite.scenes.size())) {
        suite.scenes.push_back(std::move(s));  // not this child's scene: not loaded
        continue;
      }
      s.scene = sourced.scene ? sourced.scene
                              : std::make_shared<const camera::Scene>(camera::read_scene_file(path));
      s.label = s.scene->name();
      if (!only) require_unique(labels, s.label, entry, "scene");
      suite.scenes.push_back(std::move(s));
    }
  }
  if (suite.scenes.empty()) scenes.fail("expected at least one scene");

  // Profiles.
  labels.clear();
  if (const Spec* profiles = camera_spec.find("profiles")) {
    for (const Spec& entry : one_or_many(*profiles)) {
      SuiteProfile p;
      p.where = entry.where();
      const Spec* value = &entry;
      if (entry.is_map() && entry.find("profile")) {
        entry.check_keys({"profile", "label", "area_adaptation"});
        value = &entry.at("profile");
        p.area_adaptation = entry.bool_or("area_adaptation", true);
      }
      std::string source;
      if (value->is_scalar() && value->as_string() == "scene") {
        p.label = "scene";
        source = "scene";
      } else {
        p.profile = camera::resolve_profile(*value, base_dir, source);
        p.label = p.profile->name;
      }
      if (!p.area_adaptation) p.label += "-no-areas";
      if (entry.is_map() && entry.find("label")) p.label = entry.at("label").as_string();
      p.definition = source + ",areas=" + std::to_string(p.area_adaptation);
      require_unique(labels, p.label, entry, "profile");
      suite.profiles.push_back(std::move(p));
    }
  }
  if (suite.profiles.empty())
    suite.profiles.push_back({"scene", std::nullopt, true, "scene,areas=1", {}});

  // Solvers: checked by building each on the first scene, as a run will.
  labels.clear();
  const Spec& solver_list = camera_spec.at("solvers");
  for (const Spec& entry : one_or_many(solver_list)) {
    SuiteCameraSolver s;
    s.where = entry.where();
    if (entry.is_map()) {
      entry.check_keys({"solver", "label", "options", "controller", "area_adaptation", "limits"});
      s.options.solver = entry.at("solver").as_string("a solver, pipeline or controller name");
      s.options.solver_options = read_options(entry.find("options"));
      if (const Spec* c = entry.find("controller")) read_controller(*c, s.options);
      s.area_adaptation = entry.bool_or("area_adaptation", true);
      s.label = entry.string_or("label", s.options.solver);
    } else {
      s.options.solver = entry.as_string("a solver name or a mapping {solver: ..., options: ...}");
      s.label = s.options.solver;
    }
    s.limits = suite.limits;
    if (entry.is_map() && entry.find("limits"))
      s.limits = read_limits(entry.at("limits"), s.limits);
    if (!only) {
      try {
        // Checked against the first scene a camera films, and as the editing model's solver
        // when some scene is edited (experiments/runs/edit_run.h).
        bool edits = false;
        const SuiteScene* filmed = nullptr;
        for (const SuiteScene& scene : suite.scenes) {
          if (is_edit_scene(*scene.scene)) {
            edits = true;
          } else if (filmed == nullptr) {
            filmed = &scene;
          }
        }
        if (filmed) {
          camera::make_controller(s.options.solver, *filmed->scene, filmed->scene->profile(), s.options);
        }
        if (edits && s.options.solver != camera::kGreedyEditor) {
          solvers::SolverRegistry::global().create(s.options.solver, s.options.solver_options);
        }
      } catch (const csp::InputError&) {
        throw;
      } catch (const std::exception& e) {
        entry.fail(std::string("camera solver '") + s.options.solver + "': " + e.what());
      }
    }
    s.definition = "solver=" + s.options.solver + ",options{" +
                   options_text(s.options.solver_options) + "}," + controller_text(s.options) +
                   ",areas=" + std::to_string(s.area_adaptation);
    require_unique(labels, s.label, entry, "camera solver");
    suite.camera_solvers.push_back(std::move(s));
  }
  if (suite.camera_solvers.empty()) solver_list.fail("expected at least one camera solver");
  suite.camera_seeds = read_seeds(camera_spec.find("seeds"));
}

// problems: references: {values: {LABEL: v, ...}, file: refs.csv, from: SOLVER, tolerance: t}
// A reference names a problem of the suite by its label (the file's lines "label,value",
// '#' comments and blank lines allowed); `from` a solver label of the suite.
void read_references(const Spec& spec, const std::string& base_dir, Suite& suite) {
  if (!spec.is_map()) {
    spec.fail("expected references: {values: {problem: value}, file: refs.csv, from: solver, "
              "tolerance: t}");
  }
  spec.check_keys({"values", "file", "from", "tolerance"});
  auto known = [&](const std::string& label) {
    for (const SuiteProblem& p : suite.problems) {
      if (p.label == label) return true;
    }
    return false;
  };
  auto known_labels = [&] {
    std::string out;
    for (const SuiteProblem& p : suite.problems) out += (out.empty() ? "" : ", ") + p.label;
    return out;
  };
  if (const Spec* values = spec.find("values")) {
    if (!values->is_map()) values->fail("expected values: {problem label: reference value, ...}");
    for (const auto& [label, value] : values->fields()) {
      if (!known(label)) {
        value.fail("no problem of the suite is labelled '" + label + "' (its problems: " +
                   known_labels() + ")");
      }
      suite.references[label] = value.as_number("a reference value (a cost)");
    }
  }
  if (const Spec* file = spec.find("file")) {
    const std::string path =
        (std::filesystem::path(base_dir) / file->as_string("a file of references")).string();
    std::ifstream in(path);
    if (!in) file->fail("cannot read the references file " + path);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty() || line[0] == '#') continue;
      const std::size_t comma = line.rfind(',');
      const csp::SourceLocation where{path, number, 1};
      if (comma == std::string::npos) {
        throw csp::InputError(where, "expected 'problem label,reference value', got '" + line + "'");
      }
      const std::string label = line.substr(0, comma);
      if (!known(label)) {
        throw csp::InputError(where, "no problem of the suite is labelled '" + label +
                                         "' (its problems: " + known_labels() + ")");
      }
      try {
        std::size_t used = 0;
        const double v = std::stod(line.substr(comma + 1), &used);
        if (used != line.size() - comma - 1 || !std::isfinite(v)) throw std::invalid_argument("");
        suite.references[label] = v;
      } catch (const std::exception&) {
        throw csp::InputError(where, "expected a finite reference value after the comma, got '" +
                                         line.substr(comma + 1) + "'");
      }
    }
  }
  if (const Spec* from = spec.find("from")) {
    suite.reference_from = from->as_string("a solver label of the suite");
    bool found = false;
    for (const SuiteToySolver& s : suite.toy_solvers) found = found || s.label == suite.reference_from;
    if (!found) from->fail("no solver of the suite is labelled '" + suite.reference_from + "'");
  }
  if (const Spec* t = spec.find("tolerance")) {
    suite.reference_tolerance = t->as_number("a tolerance >= 0 (absolute, in cost)");
    if (suite.reference_tolerance < 0) t->fail("expected a tolerance >= 0");
  }
}

void read_problems(const Spec& spec, const std::string& base_dir,
                   const std::optional<SuiteLoadOnly>& only, Suite& suite) {
  spec.check_keys({"instances", "solvers", "seeds", "limits", "references"});
  std::set<std::string> labels;
  const Spec& instances = spec.at("instances");
  for (const Spec& entry : instances.items("a list of instances")) {
    if (!entry.is_map()) {
      entry.fail(
          "expected an instance: {nqueens: N}, {problem: PATH} or {graph: PATH, colours: K}");
    }
    entry.check_keys({"nqueens", "problem", "graph", "colours"});
    std::vector<SuiteProblem> made;
    if (const Spec* n = entry.find("nqueens")) {
      for (const Spec& size : one_or_many(*n)) {
        const long long queens = size.as_integer("a board size >= 1");
        if (queens < 1) size.fail("expected a board size >= 1, got " + size.preview());
        SuiteProblem p;
        p.kind = SuiteProblem::Kind::kNQueens;
        p.queens = static_cast<std::size_t>(queens);
        p.label = std::to_string(queens) + "-queens";
        made.push_back(p);
      }
    } else if (const Spec* file = entry.find("problem")) {
      for (const std::string& path :
           expand_glob(*file, base_dir, file->as_string("a path or glob"))) {
        SuiteProblem p;
        p.kind = SuiteProblem::Kind::kProblemFile;
        p.path = path;
        made.push_back(p);
      }
    } else if (const Spec* graph = entry.find("graph")) {
      const Spec& colours = entry.at("colours");
      for (const std::string& path :
           expand_glob(*graph, base_dir, graph->as_string("a path or glob"))) {
        for (const Spec& k : one_or_many(colours)) {
          const long long c = k.as_integer("a number of colours >= 1");
          if (c < 1) k.fail("expected a number of colours >= 1, got " + k.preview());
          SuiteProblem p;
          p.kind = SuiteProblem::Kind::kGraph;
          p.path = path;
          p.colours = static_cast<int>(c);
          made.push_back(p);
        }
      }
    } else {
      entry.fail("expected one of nqueens, problem or graph");
    }
    for (SuiteProblem& p : made) {
      p.where = entry.where();
      if (only && !(only->kind == SuiteRun::Kind::kToy && only->subject == suite.problems.size())) {
        suite.problems.push_back(std::move(p));  // not this child's problem: not loaded
        continue;
      }
      // Loading once here reports a bad file now, and gives the problem its name.
      try {
        const LoadedSuiteProblem loaded = load_suite_problem(p);
        if (p.label.empty()) p.label = loaded.label;
      } catch (const csp::InputError&) {
        throw;
      } catch (const std::exception& e) {
        entry.fail(e.what());
      }
      if (!only) require_unique(labels, p.label, entry, "problem");
      suite.problems.push_back(std::move(p));
    }
  }
  if (suite.problems.empty()) instances.fail("expected at least one instance");

  labels.clear();
  const Spec& solver_list = spec.at("solvers");
  const solvers::SolverRegistry& registry = camera::solver_registry();
  for (const Spec& entry : one_or_many(solver_list)) {
    std::vector<SuiteToySolver> made;
    if (entry.is_scalar() && entry.as_string() == "all") {
      for (const std::string& name : registry.names()) made.push_back({name, name, {}, "", {}, {}});
    } else if (entry.is_map()) {
      entry.check_keys({"solver", "label", "options", "limits"});
      SuiteToySolver s;
      s.name = entry.at("solver").as_string("a solver or pipeline name");
      s.options = read_options(entry.find("options"));
      s.label = entry.string_or("label", s.name);
      made.push_back(std::move(s));
    } else {
      const std::string& name =
          entry.as_string("a solver name, `all`, or {solver: ..., options: ...}");
      made.push_back({name, name, {}, "", {}, {}});
    }
    for (SuiteToySolver& s : made) {
      s.where = entry.where();
      s.limits = suite.limits;
      if (entry.is_map() && entry.find("limits")) {
        s.limits = read_limits(entry.at("limits"), s.limits);
      }
      try {
        (void)registry.create(s.name, s.options);
      } catch (const std::exception& e) {
        entry.fail(std::string("solver '") + s.name + "': " + e.what());
      }
      s.definition = "solver=" + s.name + ",options{" + options_text(s.options) + "}";
      require_unique(labels, s.label, entry, "solver");
      suite.toy_solvers.push_back(std::move(s));
    }
  }
  if (suite.toy_solvers.empty()) solver_list.fail("expected at least one solver");
  suite.toy_seeds = read_seeds(spec.find("seeds"));
  // A run's child process loads only its own problem; references only matter to reports.
  if (const Spec* references = spec.find("references"); references && !only) {
    read_references(*references, base_dir, suite);
  }
  if (const Spec* limits = spec.find("limits")) {
    limits->check_keys({"time_seconds", "max_evaluations", "max_iterations"});
    const double time = limits->number_or("time_seconds", 0);
    if (time < 0) limits->at("time_seconds").fail("expected a time limit >= 0 seconds");
    suite.toy_limits.time_limit_seconds = time;
    for (const char* key : {"max_evaluations", "max_iterations"}) {
      if (const Spec* v = limits->find(key)) {
        const long long n = v->as_integer("an integer >= 0 (0: no limit)");
        if (n < 0) v->fail("expected an integer >= 0 (0: no limit)");
        (std::string(key) == "max_evaluations" ? suite.toy_limits.max_evaluations
                                               : suite.toy_limits.max_iterations) =
            static_cast<std::uint64_t>(n);
      }
    }
  }
}

}  // namespace

Suite parse_suite(const csp::Spec& document, const std::string& base_dir,
                  std::optional<SuiteLoadOnly> only) {
  if (!document.is_map()) document.fail("expected a suite: a mapping with name, camera, problems");
  document.check_keys({"name", "description", "camera", "problems", "report", "statistics",
                       "isolation", "limits"});
  camera::solver_registry();  // the camera's solvers join the registry before any lookup
  Suite suite;
  suite.name = document.at("name").as_string("a suite name");
  suite.description = document.string_or("description", "");
  // Isolation and limits first: solver entries start from the suite's limits.
  if (const Spec* i = document.find("isolation")) {
    suite.isolated = i->as_bool("isolation: true (each run in a child process) or false");
    suite.isolation_where = i->where();
  }
  if (const Spec* l = document.find("limits")) suite.limits = read_limits(*l, {});
  if (const Spec* c = document.find("camera")) read_camera(*c, base_dir, only, suite);
  if (const Spec* p = document.find("problems")) read_problems(*p, base_dir, only, suite);
  if (!suite.isolated) {
    // Limits are enforced on a child process; in-process runs cannot honour them.
    bool limited = suite.limits.any();
    for (const auto& s : suite.camera_solvers) limited = limited || s.limits.any();
    for (const auto& s : suite.toy_solvers) limited = limited || s.limits.any();
    if (limited) {
      csp::SourceLocation where = suite.isolation_where;
      throw csp::InputError(where,
                            "limits need isolated runs: drop `isolation: false` or the limits");
    }
  }
  if (const Spec* r = document.find("report")) {
    r->check_keys({"camera_view_frames", "replay_assets"});
    if (const Spec* a = r->find("replay_assets")) {
      const std::string v = a->as_string("inline or beside");
      if (v != "inline" && v != "beside") a->fail("expected inline or beside, got " + a->preview());
      suite.replay_assets_beside = v == "beside";
    }
    if (const Spec* f = r->find("camera_view_frames")) {
      const long long n = f->as_integer("a number of frames in 0..8");
      if (n < 0 || n > 8) f->fail("expected a number of frames in 0..8, got " + f->preview());
      suite.camera_view_frames = static_cast<int>(n);
    }
  }
  if (suite.scenes.empty() && suite.problems.empty()) {
    document.fail("a suite needs a `camera:` section, a `problems:` section, or both");
  }
  if (const Spec* s = document.find("statistics")) read_statistics_settings(*s, suite);
  return suite;
}

Suite read_suite_file(const std::string& path, std::optional<SuiteLoadOnly> only) {
  const csp::Spec document = csp::read_yaml_file(path);
  Suite suite = parse_suite(document, std::filesystem::path(path).parent_path().string(), only);
  suite.path = path;
  return suite;
}

}  // namespace sightline::experiments
