// How close each solver gets to the optimum of the camera problem, and at what cost in time.
//
// Camera frames are sampled from the thesis scenes as the occlusion-octree chase camera
// actually meets them (character state, last camera position, frame interval, the area's
// desired values). For each frame the reference optimum comes from a fine `grid` lattice
// over the frame's search cube, refined by `ceres-refine` (the pipeline "grid>ceres-refine"
// with grid.points = 64, i.e. 262,144 candidates). Every solver then solves the same frame
// from the last camera position. Printed as a Markdown table: mean cost relative to the
// reference (1.00 = as good; as a ratio of mean costs, and as the mean of per-frame
// ratios, which near-zero optima make harsh), frames within 1% of it, frames feasible (look-at
// visible, clear of geometry), and the mean and p99 time per frame.
//
//   build/bench/solver_quality [--frames-per-scene N] [--grid-points K] [--misses]
//                              [--pipeline-option key=value]...
// --misses lists the frames where the pipeline is not within 1% of the reference and why
// (see print_miss); --pipeline-option passes an option to the pipeline ("ceres-refine.
// alternatives=0" measures it without the octree's alternatives).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/metrics.h"
#include "sightline/experiments/sources/scene_files.h"

namespace {

using namespace sightline;

struct SampledFrame {
  const camera::Scene* scene;
  std::size_t index;  // frame number in the scene's run
  camera::CharacterState character;
  Eigen::Vector3d last_camera;
  double dt;
};

struct SolverStats {
  std::string name;
  std::vector<double> ratio, seconds;
  double cost_sum = 0, reference_sum = 0;  // over frames where both are feasible
  int within_1pct = 0, feasible = 0, frames = 0;
};

std::string point_text(std::span<const double> a) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", a[0], a[1], a[2]);
  return text;
}

// One frame the pipeline missed (not within 1% of the reference): where the octree, the
// pipeline and the reference ended, the pipeline's message, the Score along the straight
// segment pipeline -> reference (X = infeasible: another basin behind a wall; a feasible,
// falling profile: a stall), and the per-constraint costs of both points.
void print_miss(const csp::Problem& problem, const SampledFrame& frame, const double* start,
                const csp::Assignment& octree_point, const solvers::SolverResult& refined,
                const solvers::SolverResult& reference) {
  const csp::Score octree_score = problem.score(octree_point);
  std::printf(
      "miss %s frame %zu: octree %s %.4f%s | refined %s %.4f%s | reference %s %.4f | "
      "start %s\n",
      frame.scene->name().c_str(), frame.index, point_text(octree_point).c_str(), octree_score.soft,
      octree_score.feasible() ? "" : " INFEASIBLE", point_text(refined.best).c_str(),
      refined.cost(), refined.feasible() ? "" : " INFEASIBLE", point_text(reference.best).c_str(),
      reference.cost(), point_text(std::span<const double>(start, 3)).c_str());
  std::printf("    message: %s\n    segment refined->reference:", refined.message.c_str());
  csp::Assignment x(3);
  for (int k = 0; k <= 20; ++k) {
    for (int v = 0; v < 3; ++v) {
      x[v] = refined.best[v] + k / 20.0 * (reference.best[v] - refined.best[v]);
    }
    const csp::Score score = problem.score(x);
    std::printf(" %s%.3f", score.feasible() ? "" : "X", score.soft);
  }
  std::printf("\n");
  const auto mine = problem.breakdown(refined.best), theirs = problem.breakdown(reference.best);
  for (std::size_t c = 0; c < mine.size(); ++c) {
    std::printf("    %-28s %9.4f %9.4f\n",
                std::string(problem.constraint(mine[c].id).kind()).c_str(), mine[c].cost,
                theirs[c].cost);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"camera solvers' cost against a fine grid optimum on sampled frames"};
  int per_scene = 30;
  int grid_points = 64;
  bool list_misses = false;
  std::vector<std::string> pipeline_option_texts;
  app.add_option("--frames-per-scene", per_scene, "frames sampled along each scene's run")
      ->check(CLI::Range(1, 100000));
  app.add_option("--grid-points", grid_points, "reference lattice points per axis")
      ->check(CLI::Range(2, 256));
  app.add_flag("--misses", list_misses, "list the frames the pipeline misses by over 1%");
  app.add_option("--pipeline-option", pipeline_option_texts,
                 "key=value for the pipeline (stage-prefixed, e.g. ceres-refine.alternatives=0)");
  CLI11_PARSE(app, argc, argv);
  solvers::OptionValues pipeline_options;  // for the last solver, the pipeline
  for (const std::string& text : pipeline_option_texts) {
    try {
      pipeline_options.insert(solvers::split_option(text));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "--pipeline-option: %s\n", e.what());
      return 2;
    }
  }
  camera::solver_registry();
  const std::vector<std::string> paths =
      experiments::scene_files(SIGHTLINE_SOURCE_DIR "/experiments/scenes");
  std::vector<camera::Scene> scenes;
  scenes.reserve(paths.size());
  for (const auto& p : paths) scenes.push_back(camera::read_scene_file(p));

  // Sample frames along the occlusion-octree camera's own run.
  std::vector<SampledFrame> frames;
  for (const camera::Scene& scene : scenes) {
    camera::ChaseCamera chase(scene, scene.profile(), {});
    const std::size_t n = scene.frame_count();
    const std::size_t stride = std::max<std::size_t>(1, n / static_cast<std::size_t>(per_scene));
    double previous = scene.frame_time(0) - 1.0 / scene.frame_rate();
    for (std::size_t i = 0; i < n; ++i) {
      const double t = scene.frame_time(i);
      const camera::CharacterState c = scene.character_at(t);
      const double dt = std::max(t - previous, 1e-3);
      previous = t;
      if (i % stride == stride / 2) frames.push_back({&scene, i, c, chase.frame().position, dt});
      chase.update(c, dt);
    }
  }

  const std::vector<std::string> names = {"grid", "sls", "sliding-octree", "occlusion-octree",
                                          "occlusion-octree>ceres-refine"};
  std::vector<SolverStats> stats;
  for (const auto& n : names) stats.push_back({n, {}, {}, 0, 0, 0});
  auto& registry = solvers::SolverRegistry::global();
  auto reference =
      registry.create("grid>ceres-refine", {{"grid.points", std::to_string(grid_points)}});
  std::vector<std::unique_ptr<solvers::Solver>> solvers;
  try {
    for (const auto& n : names) {
      solvers.push_back(
          registry.create(n, n == names.back() ? pipeline_options : solvers::OptionValues{}));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  double reference_seconds = 0;
  solvers::SolveContext context;
  context.want_breakdown = false;
  std::uint64_t seed = 1;
  for (const SampledFrame& f : frames) {
    camera::CameraProblem problem(*f.scene);
    problem.set_frame(f.character, f.last_camera, f.dt);
    const double start[3] = {f.last_camera.x(), f.last_camera.y(), f.last_camera.z()};
    context.seed = seed++;
    const auto t0 = std::chrono::steady_clock::now();
    const solvers::SolverResult best = reference->solve(problem.problem(), start, context);
    reference_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    csp::Assignment octree_point;
    for (std::size_t s = 0; s < solvers.size(); ++s) {
      const auto t1 = std::chrono::steady_clock::now();
      const solvers::SolverResult r = solvers[s]->solve(problem.problem(), start, context);
      const double secs =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      SolverStats& st = stats[s];
      ++st.frames;
      st.seconds.push_back(secs);
      if (r.feasible()) ++st.feasible;
      if (r.feasible() && best.feasible()) {
        // Relative cost; a tiny floor keeps frames whose optimum is ~0 from dividing by 0.
        const double ratio = (r.cost() + 1e-3) / (best.cost() + 1e-3);
        st.ratio.push_back(ratio);
        st.cost_sum += r.cost();
        st.reference_sum += best.cost();
        if (r.cost() <= best.cost() * 1.01 + 1e-6) ++st.within_1pct;
      }
      if (names[s] == "occlusion-octree") octree_point = r.best;
      if (list_misses && s + 1 == solvers.size() &&
          !(r.feasible() && r.cost() <= best.cost() * 1.01 + 1e-6)) {
        print_miss(problem.problem(), f, start, octree_point, r, best);
      }
    }
  }
  std::printf(
      "%zu frames from %zu thesis scenes; reference: grid %d^3 > ceres-refine, %.1f ms "
      "per frame\n\n",
      frames.size(), scenes.size(), grid_points, 1e3 * reference_seconds / frames.size());
  std::printf(
      "| solver | mean cost / mean reference cost | mean per-frame ratio | frames within "
      "1%% | feasible | mean time (us) | p99 time (us) | time / reference time |\n"
      "|---|---|---|---|---|---|---|---|\n");
  for (SolverStats& st : stats) {
    double mean_ratio = 0;
    for (double r : st.ratio) mean_ratio += r;
    mean_ratio /= std::max<std::size_t>(1, st.ratio.size());
    double mean_time = 0;
    for (double s : st.seconds) mean_time += s;
    mean_time /= std::max<std::size_t>(1, st.seconds.size());
    std::printf("| %s | %.4f | %.4f | %d / %d | %d / %d | %.0f | %.0f | 1/%.0f |\n",
                st.name.c_str(), st.cost_sum / std::max(st.reference_sum, 1e-12), mean_ratio,
                st.within_1pct, static_cast<int>(st.ratio.size()), st.feasible, st.frames,
                mean_time * 1e6, experiments::percentile(st.seconds, 99) * 1e6,
                (reference_seconds / frames.size()) / mean_time);
  }
  return 0;
}
