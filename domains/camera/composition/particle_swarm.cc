#include "sightline/domains/camera/composition/particle_swarm.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sightline/domains/camera/composition/composition_problem.h"

namespace sightline::camera {
namespace {

constexpr int kDims = 7;

}  // namespace

const solvers::OptionSchema<ParticleSwarm::Options>& ParticleSwarm::Options::schema() {
  static const solvers::OptionSchema<Options> schema = [] {
    solvers::OptionSchema<Options> s;
    s.integer("particles", &Options::particles, "swarm size (>= 2)", 2);
    s.integer("iterations", &Options::iterations, "iterations without a time limit (>= 1)", 1);
    s.real("w_start", &Options::w_start, "inertia at the start (>= 0)", 0);
    s.real("w_end", &Options::w_end, "inertia at the end of the budget (>= 0)", 0);
    s.real("c1", &Options::c1, "pull toward the particle's own best (>= 0)", 0);
    s.real("c2", &Options::c2, "pull toward the swarm's best (>= 0)", 0);
    return s;
  }();
  return schema;
}

std::string ParticleSwarm::Options::validate() const { return ""; }

std::string ParticleSwarm::unsuitable_reason(const csp::Problem& problem) const {
  return composition_of(problem) ? "" : "needs a composition problem (a scene's shot: block)";
}

void ParticleSwarm::solve_into(const csp::Problem& problem, std::span<const double> /*start*/,
                               const solvers::SolveContext& context,
                               solvers::SolverResult& result) {
  const CompositionProblem* owner = composition_of(problem);
  if (!owner) throw std::invalid_argument(name_ + ": " + unsuitable_reason(problem));
  solvers::Budget budget(context.limits, 1);
  std::mt19937_64 rng(context.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto n = static_cast<std::size_t>(options_.particles);
  double lo[kDims], hi[kDims], vmax[kDims];
  for (int k = 0; k < kDims; ++k) {
    lo[k] = problem.domain(static_cast<csp::VariableId>(k)).lower();
    hi[k] = problem.domain(static_cast<csp::VariableId>(k)).upper();
    vmax[k] = (hi[k] - lo[k]) / 2;
  }
  std::vector<int> targets;
  for (const std::vector<int>& t : owner->targets()) targets.insert(targets.end(), t.begin(), t.end());
  std::vector<csp::Assignment> x(n, csp::Assignment(kDims)), v(n, csp::Assignment(kDims, 0.0)),
      own_best(n);
  std::vector<csp::Score> own_score(n);
  std::size_t swarm_best = 0;
  std::uint64_t evaluations = 0, iterations = 0;
  for (std::size_t i = 0; i < n; ++i) {
    CameraPose pose;
    for (int k = 0; k < 3; ++k) pose.position[k] = lo[k] + unit(rng) * (hi[k] - lo[k]);
    const int t = targets[static_cast<std::size_t>(unit(rng) * static_cast<double>(targets.size())) %
                          targets.size()];
    pose.look_at = owner->world().people()[static_cast<std::size_t>(t)].aim;
    if ((pose.look_at - pose.position).norm() < 1e-6) pose.look_at += Eigen::Vector3d::UnitZ();
    pose.fov = lo[5] + unit(rng) * (hi[5] - lo[5]);
    pose.roll = std::clamp(0.0, lo[6], hi[6]);
    pose.aspect = owner->shot().aspect;
    x[i] = owner->assignment(pose);
    for (int k = 0; k < kDims; ++k) v[i][k] = (unit(rng) - 0.5) * vmax[k] * 0.2;
    own_best[i] = x[i];
    own_score[i] = problem.score(x[i]);
    ++evaluations;
    if (own_score[i].better_than(own_score[swarm_best])) swarm_best = i;
  }
  budget.note_best(evaluations);
  const double limit = context.limits.time_limit_seconds;
  while (!budget.exhausted(evaluations, iterations)) {
    if (limit <= 0 && iterations >= static_cast<std::uint64_t>(options_.iterations)) break;
    const double progress = limit > 0 ? std::min(1.0, budget.elapsed_seconds() / limit)
                                      : static_cast<double>(iterations) / static_cast<double>(options_.iterations);
    const double w = options_.w_start + (options_.w_end - options_.w_start) * progress;
    ++iterations;
    const csp::Assignment global = own_best[swarm_best];
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < kDims; ++k) {
        double vk = w * v[i][k] + options_.c1 * unit(rng) * (own_best[i][k] - x[i][k]) +
                    options_.c2 * unit(rng) * (global[k] - x[i][k]);
        vk = std::clamp(vk, -vmax[k], vmax[k]);
        v[i][k] = vk;
        x[i][k] = std::clamp(x[i][k] + vk, lo[k], hi[k]);
      }
      const csp::Score s = problem.score(x[i]);
      ++evaluations;
      if (s.better_than(own_score[i])) {
        own_score[i] = s;
        own_best[i] = x[i];
        if (s.better_than(own_score[swarm_best])) {
          swarm_best = i;
          budget.note_best(evaluations);
        }
      }
      if (budget.exhausted(evaluations, iterations)) break;
    }
  }
  result.best = own_best[swarm_best];
  result.evaluations = evaluations;
  result.iterations = iterations;
  result.stop = budget.exhausted(evaluations, iterations) ? budget.reason()
                                                          : solvers::StopReason::kCompleted;
  result.message.clear();
  solvers::finish_result(problem, context, budget, result);
}

}  // namespace sightline::camera
