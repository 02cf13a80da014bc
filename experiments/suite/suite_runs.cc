#include "sightline/experiments/suite/suite.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sightline/domains/camera/profile_text.h"
#include "sightline/experiments/runs/stable_hash.h"

// How a suite becomes runs: every scene x solver x profile x seed (and problem x solver x
// seed), each with a definition and an id that hashes it (suite.h). Reading the suite file
// is suite.cc's.
namespace sightline::experiments {
namespace {

// Letters, digits, '.', '-' and '_' kept; anything else (">", "/", spaces) becomes '_'.
std::string file_safe(const std::string& text) {
  std::string out = text;
  for (char& c : out) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '-' || c == '_';
    if (!ok) c = '_';
  }
  return out;
}

// A file's content hash, 8 hex digits: a run's definition includes its scene's, so an
// edited scene file makes new runs.
std::string file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return StableHash().add(text.str()).short_hex();
}

// What a camera run's profile says, as 16 hex digits of its canonical text
// (profile_text.h): the profile entry's source ("inline", "file PATH", "preset NAME",
// "scene") alone would let an edited inline mapping, profile file, preset or a scene's
// profile file reuse stale results. A "scene" entry takes the subject scene's own profile,
// which may come from a file or preset the scene file's hash does not cover. The subject's
// scene is loaded whenever its runs are made (also in a run-one child, suite.h).
std::string profile_content(const Suite& suite, std::size_t subject, std::size_t profile) {
  const SuiteProfile& entry = suite.profiles[profile];
  const camera::Scene* scene = suite.scenes[subject].scene.get();
  if (!entry.profile && scene == nullptr) return "unloaded";  // never matches a real id
  return StableHash()
      .add(camera::profile_text(entry.profile ? *entry.profile : scene->profile()))
      .hex();
}

// The run's definition and id. `subject_hash` is the hash of its scene or problem file.
SuiteRun combination(const Suite& suite, SuiteRun::Kind kind, std::size_t subject,
                     std::size_t solver, std::size_t profile, std::uint64_t seed,
                     const std::string& subject_hash) {
  SuiteRun run;
  run.kind = kind;
  run.subject = subject;
  run.solver = solver;
  run.seed = seed;
  const RunLimits* limits = nullptr;
  if (kind == SuiteRun::Kind::kCamera) {
    run.profile = profile;
    run.definition = "camera;scene=" + suite.scenes[subject].label + "#" + subject_hash + ";" +
                     suite.camera_solvers[solver].definition +
                     ";profile=" + suite.profiles[profile].definition +
                     ",content=" + profile_content(suite, subject, profile) +
                     ";seed=" + std::to_string(seed);
    limits = &suite.camera_solvers[solver].limits;
    run.id = file_safe(suite.scenes[subject].label + "__" + suite.camera_solvers[solver].label +
                       "__" + suite.profiles[profile].label + "__s" + std::to_string(seed));
  } else {
    const SuiteProblem& p = suite.problems[subject];
    std::ostringstream toy_limits;
    toy_limits << "limits=" << suite.toy_limits.time_limit_seconds << ","
               << suite.toy_limits.max_evaluations << "," << suite.toy_limits.max_iterations;
    const std::string problem_text =
        p.kind == SuiteProblem::Kind::kNQueens
            ? "nqueens=" + std::to_string(p.queens)
            : "file=" + p.label + "#" + subject_hash + ",colours=" + std::to_string(p.colours);
    run.definition = "toy;" + problem_text + ";" + suite.toy_solvers[solver].definition + ";" +
                     toy_limits.str() + ";seed=" + std::to_string(seed);
    limits = &suite.toy_solvers[solver].limits;
    run.id =
        file_safe(p.label + "__" + suite.toy_solvers[solver].label + "__s" + std::to_string(seed));
  }
  // Run limits change what a run may report (a timeout at 60 s may finish in 120 s), so
  // they are part of the definition; only when set, so the ids of suites without limits
  // stay as they were.
  if (limits->any()) run.definition += ";run_limits=" + limits->text();
  run.id += "__" + StableHash().add(run.definition).short_hex();
  return run;
}

std::string subject_hash(const Suite& suite, SuiteRun::Kind kind, std::size_t subject) {
  if (kind == SuiteRun::Kind::kCamera) {
    // A file's content, or a generated scene's fingerprint (sources/scene_source.h).
    const SuiteScene& scene = suite.scenes[subject];
    return scene.path.empty() ? StableHash().add(scene.fingerprint).short_hex()
                              : file_hash(scene.path);
  }
  const SuiteProblem& p = suite.problems[subject];
  return p.kind == SuiteProblem::Kind::kNQueens ? std::string() : file_hash(p.path);
}

}  // namespace

std::vector<SuiteRun> expand_runs(const Suite& suite) {
  std::vector<SuiteRun> runs;
  constexpr auto kCamera = SuiteRun::Kind::kCamera;
  for (std::size_t sc = 0; sc < suite.scenes.size(); ++sc) {
    const std::string hash = subject_hash(suite, kCamera, sc);
    for (std::size_t so = 0; so < suite.camera_solvers.size(); ++so) {
      for (std::size_t pr = 0; pr < suite.profiles.size(); ++pr) {
        for (std::uint64_t seed : suite.camera_seeds) {
          runs.push_back(combination(suite, kCamera, sc, so, pr, seed, hash));
        }
      }
    }
  }
  constexpr auto kToy = SuiteRun::Kind::kToy;
  for (std::size_t pb = 0; pb < suite.problems.size(); ++pb) {
    const std::string hash = subject_hash(suite, kToy, pb);
    for (std::size_t so = 0; so < suite.toy_solvers.size(); ++so) {
      for (std::uint64_t seed : suite.toy_seeds) {
        runs.push_back(combination(suite, kToy, pb, so, 0, seed, hash));
      }
    }
  }
  return runs;
}

SuiteRun make_run(const Suite& suite, SuiteRun::Kind kind, std::size_t subject, std::size_t solver,
                  std::size_t profile, std::uint64_t seed) {
  return combination(suite, kind, subject, solver, profile, seed,
                     subject_hash(suite, kind, subject));
}

const RunLimits& run_limits(const Suite& suite, const SuiteRun& run) {
  return run.kind == SuiteRun::Kind::kCamera ? suite.camera_solvers[run.solver].limits
                                             : suite.toy_solvers[run.solver].limits;
}

camera::CameraProfile run_profile(const Suite& suite, const SuiteRun& run) {
  const SuiteProfile& entry = suite.profiles[run.profile];
  camera::CameraProfile profile =
      entry.profile ? *entry.profile : suite.scenes[run.subject].scene->profile();
  if (!entry.area_adaptation || !suite.camera_solvers[run.solver].area_adaptation) {
    profile.enclosed = {};
    profile.semi_enclosed = {};
    profile.sensing.enabled = false;  // on levels, the sensed room adapts like an area
  }
  return profile;
}

}  // namespace sightline::experiments
