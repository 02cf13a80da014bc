// Suite: an experiment plan read from YAML: which scenes and problems, which solvers (with
// options), which profiles and seeds; and its expansion into independent runs.
//
// Researchers compare solvers by writing one of these and running `sightline run`. Two
// families of runs share the same runner, results table and report:
//   camera runs: scene x camera solver (a solver, pipeline or baseline controller, with
//                solver and controller options) x profile x seed, judged by RunMetrics;
//   toy runs:    problem (N-queens size, problem file, graph + colours) x solver x seed,
//                judged by cost, feasibility, time and evaluations.
// Everything a run needs is checked when the file is read (scenes load, profiles resolve,
// every solver name and option is accepted by the registry or by make_controller), so a
// typo fails in a second with "suite.yaml:12:7: ..." instead of after an hour of runs.
//
// Run ids are derived from the combination (labels, plus a hash of everything that defines
// the run), so they are the same in every invocation, which is what lets an interrupted
// suite resume, and a run whose definition was edited is not mistaken for a finished one.
// The file format is in docs/EXPERIMENTS.md.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sightline/csp/input_error.h"
#include "sightline/csp/spec.h"
#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/domains/camera/profile.h"
#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/suite/run_limits.h"
#include "sightline/solvers/solver.h"

namespace sightline::experiments {

struct SuiteScene {
  std::string label;  // the scene's name, unique in the suite
  std::string path;   // as resolved from the suite file; empty for a generated scene
  std::string fingerprint;  // a generated scene's (sources/scene_source.h); "" for files
  std::shared_ptr<const camera::Scene> scene;
};

struct SuiteCameraSolver {
  std::string label;  // the "solver" column; unique in the suite
  // What make_controller is given: options.solver is the solver, pipeline or baseline name,
  // options.solver_options its settings, the other fields the controller's; seed is set per run.
  camera::ChaseCameraOptions options;
  bool area_adaptation = true;  // false drops the profile's enclosed/semi-enclosed adaptation
  std::string definition;       // canonical text of all of the above, hashed into run ids
  RunLimits limits;             // the suite's `limits:`, overridden by the entry's own
  csp::SourceLocation where;
};

struct SuiteProfile {
  std::string label;                           // the "profile" column
  std::optional<camera::CameraProfile> profile;  // empty: each scene's own profile
  bool area_adaptation = true;
  std::string definition;
  csp::SourceLocation where;
};

struct SuiteProblem {
  enum class Kind { kNQueens, kProblemFile, kGraph };
  Kind kind = Kind::kNQueens;
  std::string label;  // "8-queens", the file's problem name, "myciel5 (6 colours)"
  std::size_t queens = 0;
  std::string path;   // problem file (.yaml, .wcsp, .wcsp.gz) or graph (.col, .yaml)
  int colours = 0;
  csp::SourceLocation where;
};

struct SuiteToySolver {
  std::string label;
  std::string name;  // registered solver or pipeline
  solvers::OptionValues options;
  std::string definition;
  RunLimits limits;  // the suite's `limits:`, overridden by the entry's own
  csp::SourceLocation where;
};

// A pair of solvers (labels of one family, camera or problems) to compare with the Wilcoxon
// signed-rank test in the summary (`statistics: {compare: [a, b]}` or `run --compare a,b`).
struct SuiteComparison {
  std::string a, b;
  csp::SourceLocation where;
};

struct Suite {
  std::string name;
  std::string description;
  std::string path;  // the suite file

  std::vector<SuiteScene> scenes;
  std::vector<SuiteCameraSolver> camera_solvers;
  std::vector<SuiteProfile> profiles;
  std::vector<std::uint64_t> camera_seeds;

  std::vector<SuiteProblem> problems;
  std::vector<SuiteToySolver> toy_solvers;
  std::vector<std::uint64_t> toy_seeds;
  solvers::SolveLimits toy_limits;
  // Reference values of the problems (`problems: references:`), for judging optimisation
  // runs: a run counts as solved when it reaches its problem's reference within
  // `reference_tolerance`, at its time to best. By problem label; `reference_from` names a
  // solver whose proven optima in the same suite serve where no value is given.
  std::map<std::string, double> references;
  std::string reference_from;
  double reference_tolerance = 1e-9;

  // `report: replay_assets: beside`: the 3D replay's three.js and scene data go to
  // OUT/report-assets/ beside report.html instead of inside it (`inline`, the default).
  bool replay_assets_beside = false;
  // Every run in a child process of its own (run_isolation.h; `isolation:`, default true),
  // with these limits unless a solver entry sets its own (`limits:`; 0 = none).
  bool isolated = true;
  RunLimits limits;
  csp::SourceLocation isolation_where;

  // Report settings: how many frames of each scene are shown from the main camera.
  int camera_view_frames = 3;

  // Statistics settings: the pairs to compare (suite_comparisons.h).
  std::vector<SuiteComparison> comparisons;
};

// One combination. Indices point into the Suite's lists.
struct SuiteRun {
  enum class Kind { kCamera, kToy };
  Kind kind = Kind::kCamera;
  std::string id;  // stable: labels + seed + hash of the definition; a file-name-safe text
  std::size_t subject = 0;  // scene (camera) or problem (toy)
  std::size_t solver = 0;
  std::size_t profile = 0;  // camera runs only
  std::uint64_t seed = 1;
  std::string definition;   // the canonical text the id's hash is taken of
};

// For a run-one child (isolated_run.h): load only this run's scene or problem (the others
// keep their path but have no label or data) and skip the checks the runner already made
// when it read the whole file, so a run of a 50-level suite does not load 50 levels.
struct SuiteLoadOnly {
  SuiteRun::Kind kind = SuiteRun::Kind::kCamera;
  std::size_t subject = 0;
};

// Reads a suite file. Throws csp::InputError naming the file, line and what was expected:
// unknown fields, globs matching no file, unreadable scenes, unknown solvers (the message
// lists the valid names), bad options, duplicate labels, an empty suite.
Suite read_suite_file(const std::string& path, std::optional<SuiteLoadOnly> only = {});
// Reads a suite from a parsed document; relative paths resolve against `base_dir`.
Suite parse_suite(const csp::Spec& document, const std::string& base_dir,
                  std::optional<SuiteLoadOnly> only = {});

// Every combination, camera runs first (scene-major, then solver, profile, seed), then toy
// runs (problem, solver, seed): the order of results.csv.
std::vector<SuiteRun> expand_runs(const Suite& suite);
// One combination, as expand_runs makes it (profile is ignored for toy runs).
SuiteRun make_run(const Suite& suite, SuiteRun::Kind kind, std::size_t subject, std::size_t solver,
                  std::size_t profile, std::uint64_t seed);

// The limits a run is held to: its solver entry's.
const RunLimits& run_limits(const Suite& suite, const SuiteRun& run);

// The profile a camera run uses: the entry's (or the scene's own), without area adaptation
// when the profile entry or the solver entry asks for that.
camera::CameraProfile run_profile(const Suite& suite, const SuiteRun& run);

}  // namespace sightline::experiments
