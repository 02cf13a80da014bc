#include "sightline/experiments/execution/run_order.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>

namespace sightline::experiments {
namespace {

// Guessed controller time per frame, in seconds, of one camera solver or baseline: from the
// per-frame p99 times measured on the levels suite (docs/EXPERIMENTS.md), rounded up.
double solver_seconds_per_frame(std::string_view name) {
  struct Guess {
    std::string_view name;
    double seconds;
  };
  static constexpr Guess kGuesses[] = {
      {"ceres-refine", 5e-3},
      {"grid", 2e-3},
      {"sls", 5e-4},
      {"sliding-octree", 3e-4},
      {"occlusion-octree", 1.5e-4},
      {"bourne-octree", 5e-5},
      {"spring-arm", 3e-5},
      {"pull-forward", 3e-5},
  };
  for (const Guess& g : kGuesses) {
    if (name == g.name) return g.seconds;
  }
  return 5e-4;  // an unknown solver: as slow as sls
}

// A pipeline "a>b>c" runs every stage each frame.
double pipeline_seconds_per_frame(const std::string& pipeline) {
  double total = 0;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = pipeline.find('>', start);
    total += solver_seconds_per_frame(std::string_view(pipeline).substr(
        start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) return total;
    start = end + 1;
  }
}

// Per frame besides the solver: the trace row, the metrics and the independent checks.
constexpr double kFrameOverheadSeconds = 5e-5;
constexpr double kLevelFactor = 4;
// A toy solver's time per unit of problem size; exhaustive ones are slower.
double toy_seconds_per_unit(const std::string& solver) {
  if (solver == "grid" || solver == "bnb" || solver == "toulbar2") return 1e-5;
  return 1e-6;
}

double file_bytes(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return ec ? 1000.0 : static_cast<double>(size);
}

}  // namespace

double expected_run_seconds(const Suite& suite, const SuiteRun& run) {
  if (run.kind == SuiteRun::Kind::kCamera) {
    const SuiteScene& scene = suite.scenes[run.subject];
    const double frames = std::max<double>(1, static_cast<double>(scene.scene->frame_count()));
    double per_frame = kFrameOverheadSeconds +
                       pipeline_seconds_per_frame(suite.camera_solvers[run.solver].options.solver);
    if (scene.scene->level() != nullptr) per_frame *= kLevelFactor;
    return frames * per_frame;
  }
  const SuiteProblem& problem = suite.problems[run.subject];
  double size = 1;
  switch (problem.kind) {
    case SuiteProblem::Kind::kNQueens:
      size = static_cast<double>(problem.queens) * static_cast<double>(problem.queens);
      break;
    case SuiteProblem::Kind::kProblemFile:
      size = file_bytes(problem.path);
      break;
    case SuiteProblem::Kind::kGraph:
      size = file_bytes(problem.path) * std::max(1, problem.colours);
      break;
  }
  double seconds = std::max(1.0, size) * toy_seconds_per_unit(suite.toy_solvers[run.solver].name);
  if (suite.toy_limits.time_limit_seconds > 0)
    seconds = std::min(seconds, suite.toy_limits.time_limit_seconds);
  return seconds;
}

std::vector<std::size_t> longest_first(const Suite& suite, const std::vector<SuiteRun>& runs,
                                       std::vector<std::size_t> pending) {
  std::vector<double> expected(runs.size(), 0.0);
  for (std::size_t i : pending) expected[i] = expected_run_seconds(suite, runs[i]);
  std::stable_sort(pending.begin(), pending.end(),
                   [&](std::size_t a, std::size_t b) { return expected[a] > expected[b]; });
  return pending;
}

}  // namespace sightline::experiments
