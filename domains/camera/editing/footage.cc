#include "sightline/domains/camera/editing/footage.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/solvers/registry.h"

namespace sightline::camera {

std::pair<double, double> people_time_span(const Scene& scene) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto add = [&](const Trajectory& path) {
    lo = std::min(lo, path.start_time());
    hi = std::max(hi, path.end_time());
  };
  if (scene.has_character()) add(scene.trajectory());
  for (const Actor& a : scene.actors()) add(a.trajectory);
  if (!std::isfinite(lo)) add(scene.trajectory());
  return {lo, hi};
}

PersonInTake person_in_view(const ShotWorld& world, int who, const CameraPose& pose) {
  PersonInTake out;
  const auto view = View::of(pose);
  if (!view) return out;
  const PersonAtTime& person = world.people()[who];
  const Aabb& body = person.body;
  const Eigen::Vector3d head = body.min + Eigen::Vector3d(0.5, 0.9, 0.5).cwiseProduct(body.max - body.min);
  auto seen = [&](const Eigen::Vector3d& q) {
    const auto s = view->project(q);
    return s && s->x() >= 0 && s->x() <= 1 && s->y() >= 0 && s->y() <= 1 &&
           world.clear(pose.position, q, who);
  };
  int count = 0;
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  bool all_in_front = true;
  for (const Eigen::Vector3d& q : person_samples(body)) {
    if (seen(q)) ++count;
    if (const auto s = view->project(q)) {
      top = std::max(top, s->y());
      bottom = std::min(bottom, s->y());
    } else {
      all_in_front = false;
    }
  }
  out.shown = count >= 9 && seen(head);
  const Eigen::Vector3d away = pose.position - person.aim;
  const double bearing = std::atan2(away.x(), away.z()) * 180 / std::numbers::pi;
  out.front = std::abs(signed_degrees(bearing - person.yaw)) <= 90;
  out.size = all_in_front ? top - bottom : 0;
  return out;
}

Footage film_footage(const Scene& scene, std::vector<CandidateShot> candidates,
                     const FootageOptions& options) {
  if (!(options.slot_seconds > 0)) throw std::invalid_argument("the slot must last more than 0 s");
  const auto began = std::chrono::steady_clock::now();
  Footage footage;
  footage.candidates = std::move(candidates);
  footage.slot_seconds = options.slot_seconds;
  std::tie(footage.start, footage.end) = people_time_span(scene);
  // Slot i covers [start + i slot, start + (i + 1) slot); the last one holds the end.
  const auto slots = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::ceil((footage.end - footage.start) / options.slot_seconds - 1e-9)));
  for (std::size_t i = 0; i < slots; ++i) {
    footage.slot_times.push_back(footage.start + static_cast<double>(i) * options.slot_seconds);
  }
  const std::size_t k_count = footage.candidates.size();
  if (k_count == 0) throw std::invalid_argument("no shot to cut between: the scene names nobody");

  solvers::SolverRegistry& registry = solvers::SolverRegistry::global();
  register_composition_solvers(registry);
  auto local = registry.create("shot-search", {{"global", "false"}});
  auto global = registry.create("shot-search");
  solvers::SolveContext local_context, global_context;
  local_context.limits.max_evaluations = options.refine_evaluations;
  local_context.want_breakdown = false;
  local_context.anytime = false;
  local_context.seed = options.seed;
  global_context.want_breakdown = false;
  global_context.seed = options.seed;
  solvers::SolverResult result;

  std::vector<std::unique_ptr<CompositionProblem>> problems;
  for (const CandidateShot& c : footage.candidates) {
    problems.push_back(std::make_unique<CompositionProblem>(scene, *c.shot, footage.start));
  }
  for (const PersonAtTime& p : problems.front()->world().people()) footage.people.push_back(p.name);
  std::vector<std::optional<CameraPose>> last_start(k_count);
  std::vector<double> global_satisfaction(k_count, 0);
  footage.takes.assign(slots, std::vector<Take>(k_count));
  for (std::size_t i = 0; i < slots; ++i) {
    for (std::size_t k = 0; k < k_count; ++k) {
      CompositionProblem& problem = *problems[k];
      const CandidateShot& c = footage.candidates[k];
      problem.set_time(footage.slot_times[i]);
      const ShotWorld& world = problem.world();
      const Take* previous = i > 0 ? &footage.takes[i - 1][k] : nullptr;
      CameraPose pose;
      if (c.idiom != Idiom::kNamed) {
        const std::optional<CameraPose> seed = idiom_start(c, scene, world);
        CameraPose start = seed ? *seed : (previous ? previous->pose : CameraPose{});
        // Carry the last take along as the idiom's placement moved, unless it jumped (a new
        // partner): the film then moves smoothly from slot to slot.
        if (seed && previous && last_start[k] &&
            (seed->position - last_start[k]->position).norm() < 1.0) {
          const Eigen::Vector3d moved = seed->position - last_start[k]->position;
          start = previous->pose;
          start.position += moved;
          start.look_at += moved;
        }
        last_start[k] = seed;
        local->solve_into(problem.problem(), problem.assignment(start), local_context, result);
        footage.evaluations += result.evaluations;
        pose = problem.pose(result.best);
        if (!keeps_screen_direction(c, scene, world, pose)) pose = start;
        if (!keeps_screen_direction(c, scene, world, pose) && seed) pose = *seed;
      } else if (previous == nullptr) {
        global_context.limits.max_evaluations = options.global_evaluations;
        CameraPose from;
        global->solve_into(problem.problem(), problem.assignment(from), global_context, result);
        footage.evaluations += result.evaluations;
        pose = problem.pose(result.best);
        global_satisfaction[k] = problem.evaluate(pose).satisfaction;
      } else {
        local->solve_into(problem.problem(), problem.assignment(previous->pose), local_context, result);
        footage.evaluations += result.evaluations;
        pose = problem.pose(result.best);
        const ShotEvaluation e = problem.evaluate(pose);
        if (!e.feasible || e.satisfaction < global_satisfaction[k] - 0.15) {
          global_context.limits.max_evaluations = options.global_evaluations / 3;
          global->solve_into(problem.problem(), result.best, global_context, result);
          footage.evaluations += result.evaluations;
          const CameraPose again = problem.pose(result.best);
          const ShotEvaluation f = problem.evaluate(again);
          if (f.feasible && (!e.feasible || f.satisfaction > e.satisfaction)) {
            pose = again;
            global_satisfaction[k] = f.satisfaction;
          }
        } else {
          global_satisfaction[k] = std::max(global_satisfaction[k] * 0.98, e.satisfaction);
        }
      }
      Take& take = footage.takes[i][k];
      const ShotEvaluation e = problem.evaluate(pose);
      take.pose = pose;
      take.feasible = e.feasible;
      take.satisfaction = e.satisfaction;
      take.people.resize(world.people().size());
      take.subject_size = 0;
      for (std::size_t p = 0; p < world.people().size(); ++p) {
        take.people[p] = person_in_view(world, static_cast<int>(p), pose);
        if (take.people[p].shown) take.subject_size = std::max(take.subject_size, take.people[p].size);
      }
    }
  }
  footage.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return footage;
}

}  // namespace sightline::camera
