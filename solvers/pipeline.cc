#include "sightline/solvers/pipeline.h"

namespace sightline::solvers {

Pipeline::Pipeline(std::string name, std::vector<std::unique_ptr<Solver>> stages)
    : name_(std::move(name)), stages_(std::move(stages)) {}

std::string Pipeline::unsuitable_reason(const csp::Problem& problem) const {
  for (const auto& stage : stages_) {
    if (std::string why = stage->unsuitable_reason(problem); !why.empty()) {
      return stage->name() + ": " + why;
    }
  }
  return "";
}

std::size_t Pipeline::alternatives_wanted() const {
  return stages_.empty() ? 0 : stages_.front()->alternatives_wanted();
}

void Pipeline::solve_into(const csp::Problem& problem, std::span<const double> start,
                          const SolveContext& context, SolverResult& result) {
  Budget budget(context, 1);
  result.best.assign(start.begin(), start.end());
  result.score = problem.score(result.best);
  result.evaluations = 1;
  result.iterations = 0;
  result.stop = StopReason::kCompleted;
  result.message.clear();
  result.alternatives.clear();
  budget.note_best(result.evaluations, 0, &result.score);
  SolveContext stage_context = context;
  stage_context.want_breakdown = false;
  handed_over_.clear();
  for (std::size_t i = 0; i < stages_.size(); ++i) {
    // Each stage gets what is left of the pipeline's limits.
    SolveLimits& left = stage_context.limits;
    const SolveLimits& all = context.limits;
    if (all.max_evaluations) left.max_evaluations = all.max_evaluations - result.evaluations;
    if (all.max_iterations) left.max_iterations = all.max_iterations - result.iterations;
    if (all.time_limit_seconds > 0) {
      left.time_limit_seconds = all.time_limit_seconds - budget.elapsed_seconds();
      if (left.time_limit_seconds <= 0) {
        result.stop = StopReason::kTimeLimit;
        break;
      }
    }
    stage_context.seed = context.seed + i;
    const bool last = i + 1 == stages_.size();
    // An anytime stage before the last would take the whole budget (SolveContext::anytime).
    stage_context.anytime = context.anytime && last;
    const double stage_began = budget.elapsed_seconds();
    const std::uint64_t evaluations_before = result.evaluations;
    stage_context.alternatives_wanted =
        last ? context.alternatives_wanted : stages_[i + 1]->alternatives_wanted();
    if (i > 0) stage_context.alternative_starts = handed_over_;
    stage_result_.alternatives.clear();  // solvers that do not explore leave it as it is
    stages_[i]->solve_into(problem, result.best, stage_context, stage_result_);
    if (stage_result_.alternatives.size() > stage_context.alternatives_wanted) {
      stage_result_.alternatives.resize(stage_context.alternatives_wanted);
    }
    handed_over_.swap(stage_result_.alternatives);
    if (last) result.alternatives = handed_over_;
    result.evaluations += stage_result_.evaluations;
    result.iterations += stage_result_.iterations;
    // The stage's improvements on the pipeline's best, on the pipeline's clock.
    csp::Score so_far = result.score;
    for (const AnytimePoint& p : stage_result_.trajectory) {
      if (!p.score.better_than(so_far)) continue;
      so_far = p.score;
      budget.record_best(evaluations_before + p.evaluations, stage_began + p.seconds, &p.score);
    }
    if (stage_result_.score.better_than(result.score)) {
      result.best = stage_result_.best;
      result.score = stage_result_.score;
      if (stage_result_.best_found_seconds >= 0) {
        budget.record_best(evaluations_before + stage_result_.evaluations_at_best,
                           stage_began + stage_result_.best_found_seconds);
      } else {
        budget.record_best(evaluations_before + stage_result_.evaluations,
                           stage_began + stage_result_.wall_seconds);
      }
    }
    result.stop = stage_result_.stop;
    if (!stage_result_.message.empty()) {
      result.message += (result.message.empty() ? "" : "; ") + stages_[i]->name() + ": " +
                        stage_result_.message;
    }
    if (budget.exhausted(result.evaluations, result.iterations)) {
      result.stop = budget.reason();
      break;
    }
  }
  finish_result(problem, context, budget, result);
}

}  // namespace sightline::solvers
