// Pipeline: solvers run one after another, each starting from the best of the one before.
//
// "sliding-octree>ceres-refine" is coarse global search followed by local refinement. The
// pipeline's result is the best over all stages (a later stage can never make it worse),
// with evaluations, iterations and time summed; limits apply to the whole pipeline.
// Alternatives: before each stage the pipeline asks the next stage how many alternative
// starts it would use (Solver::alternatives_wanted), requests that many from the stage
// (SolveContext::alternatives_wanted), and hands what it got to the next stage as
// SolveContext::alternative_starts, so "occlusion-octree>ceres-refine" refines from the
// octree's best and from its best points in other regions. The pipeline's own
// alternatives are its last stage's. Only the last stage runs anytime (SolveContext::anytime):
// the ones before it run their default course within the limits, so they leave the rest of
// the budget to the last. The time to best is that of the stage that found the best.
#pragma once

#include <memory>
#include <vector>

#include "sightline/solvers/solver.h"

namespace sightline::solvers {

class Pipeline : public Solver {
 public:
  Pipeline(std::string name, std::vector<std::unique_ptr<Solver>> stages);
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  // The first stage's: a pipeline that follows another starts where its first stage does.
  std::size_t alternatives_wanted() const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override;
  const std::vector<std::unique_ptr<Solver>>& stages() const { return stages_; }

 private:
  std::string name_;
  std::vector<std::unique_ptr<Solver>> stages_;
  SolverResult stage_result_;
  std::vector<csp::Assignment> handed_over_;  // the previous stage's alternatives
};

}  // namespace sightline::solvers
