// ParticleSwarm (`particle-swarm`): the composition literature's baseline solver, particle
// swarm optimisation over the pose as Burelli et al. (2008) and Ranon & Urli (2014) use it,
// so comparisons with the published results run in the same harness.
//
// Particles: the seven pose variables (position in the region, yaw, pitch, fov, roll).
// Initialised with positions uniform in the region, each looking at the aim point of a
// target drawn at random (the view at the subjects, as their initialisation does), the fov
// uniform in its range, roll 0 where allowed. Velocity update
//   v = w v + c1 r1 (personal best - x) + c2 r2 (swarm best - x),
// each component clamped to half its variable's range, positions clamped into the domains;
// the inertia w falls linearly from w_start to w_end over the budget (its time limit, else
// `iterations`). Fitness is the problem's score (hard violations first, then the cost).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::camera {

class ParticleSwarm : public solvers::Solver {
 public:
  struct Options {
    std::int64_t particles = 30;
    std::int64_t iterations = 100;  // without a time limit
    double w_start = 0.9, w_end = 0.4;
    double c1 = 2.0, c2 = 2.0;

    static const solvers::OptionSchema<Options>& schema();
    std::string validate() const;
  };

  ParticleSwarm(std::string name, Options options) : name_(std::move(name)), options_(options) {}
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const solvers::SolveContext& context, solvers::SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
};

}  // namespace sightline::camera
