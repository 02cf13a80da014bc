// Tests of what ceres-refine does beyond Ceres' line search: the poll that follows edges
// without a gradient (0/1 hard constraints, piecewise-constant soft terms), and the
// alternatives a global stage hands over through a pipeline (other basins, refined too).
#include <gtest/gtest.h>

#include <random>

#include "sightline/solvers/ceres_refine.h"
#include "sightline/solvers/ceres_refine_poll.h"
#include "sightline/solvers/pipeline.h"
#include "tests/solvers/ceres_refine_test_problems.h"

namespace sightline::solvers {
namespace {

using namespace ceres_refine_testing;

// Outside the half-plane y <= slope x: violation 1 (a step, like a blocked sight line or a
// hidden body sample), else 0. Its gradient is 0 wherever it exists, and it says so.
class AboveLine : public csp::Constraint {
 public:
  AboveLine(VariableId x, VariableId y, double slope, double weight, bool hard)
      : Constraint({x, y}, weight, hard), slope_(slope) {}
  std::string_view kind() const override { return "test.above_line"; }
  double violation(std::span<const double> v) const override {
    return v[scope()[1]] > slope_ * v[scope()[0]] ? 1.0 : 0.0;
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> v,
                                std::span<double> gradient) const override {
    std::fill(gradient.begin(), gradient.end(), 0.0);
    return violation(v);
  }

 private:
  double slope_;
};

// Inside the band lo < x < hi: violation 1 (a wall between two basins), else 0.
class InsideBand : public csp::Constraint {
 public:
  InsideBand(VariableId x, double lo, double hi) : Constraint({x}, 1.0, true), lo_(lo), hi_(hi) {}
  std::string_view kind() const override { return "test.inside_band"; }
  double violation(std::span<const double> v) const override {
    const double x = v[scope()[0]];
    return x > lo_ && x < hi_ ? 1.0 : 0.0;
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> v,
                                std::span<double> gradient) const override {
    gradient[0] = 0;
    return violation(v);
  }

 private:
  double lo_, hi_;
};

// The bowl (x - 1)^2 + (y - 2)^2 over [-3, 3]^2 with y <= 0.3 x enforced by a step term:
// hard (0/1), or soft with a weight no gain can pay for. The constrained optimum is the
// bowl's centre projected on the line: t (1, 0.3) with t = (1 + 0.6) / 1.09, at squared
// distance (2 - 0.3)^2 / 1.09.
std::unique_ptr<Problem> edge_problem(bool hard) {
  auto p = std::make_unique<Problem>("edge");
  p->add_variable("x", Domain::real_interval(-3, 3));
  p->add_variable("y", Domain::real_interval(-3, 3));
  add_jet<Bowl<2>, 2>(*p, {0, 1}, Bowl<2>{{1.0, 2.0}, {1.0, 1.0}});
  p->add_constraint(std::make_unique<AboveLine>(0, 1, 0.3, hard ? 1.0 : 100.0, hard));
  return p;
}
constexpr double kEdgeT = 1.6 / 1.09;
constexpr double kEdgeCost = 1.7 * 1.7 / 1.09;

// x in [-10, 10], cost 0.01 (x - 9)^2, a hard 0/1 wall on (-8, 8): two basins, the left
// one's best is x = -8 (cost 2.89), the right one's x = 9 (cost 0). The wall is far wider
// than any step Ceres' line search or the poll takes from the left basin, so a local method
// started there stays there.
std::unique_ptr<Problem> two_basins() {
  auto p = std::make_unique<Problem>("two-basins");
  p->add_variable("x", Domain::real_interval(-10, 10));
  add_jet<Bowl<1>, 1>(*p, {0}, Bowl<1>{{9.0}, {0.01}});
  p->add_constraint(std::make_unique<InsideBand>(0, -8.0, 8.0));
  return p;
}

// ---------------------------------------------------------------------------------------
// The poll.

TEST(CeresRefine, FollowsAnEdgeWithoutAGradientToTheConstrainedOptimum) {
  for (const bool hard : {true, false}) {
    auto problem = edge_problem(hard);
    for (const csp::Assignment& start :
         {csp::Assignment{2.5, -1.0}, csp::Assignment{-0.5, -2.5}, csp::Assignment{2.9, 0.0}}) {
      const SolverResult r = make_refiner()->solve(*problem, start);
      SCOPED_TRACE(std::string(hard ? "hard" : "soft") + " step: " +
                   r.brief_report("ceres-refine"));
      EXPECT_TRUE(r.feasible());
      EXPECT_EQ(problem->constraint(1).violation(r.best), 0.0);
      // The cost is flat along the edge near the optimum (quadratic in the distance), so
      // 2e-3 in cost is about 0.045 in position.
      EXPECT_NEAR(r.cost(), kEdgeCost, 2e-3);
      EXPECT_NEAR(r.best[0], kEdgeT, 0.05);
      EXPECT_NEAR(r.best[1], 0.3 * kEdgeT, 0.05);
      // Ceres alone stalls where its line search first meets the edge (why the poll exists).
      const SolverResult stalled =
          make_refiner({{"poll_evaluations", "0"}})->solve(*problem, start);
      EXPECT_GT(stalled.cost(), kEdgeCost + 0.05) << stalled.brief_report("no poll");
    }
  }
}

TEST(CeresRefine, SkipsThePollAtASmoothOptimum) {
  auto problem = bowl_problem<3>({1.0, -2.0, 0.5}, {1.0, 4.0, 0.5});
  const csp::Assignment start = {-4.0, 4.0, 4.0};
  const SolverResult r = make_refiner()->solve(*problem, start);
  const SolverResult without = make_refiner({{"poll_evaluations", "0"}})->solve(*problem, start);
  EXPECT_EQ(r.message.find("poll:"), std::string::npos) << r.message;
  EXPECT_EQ(r.best, without.best);
  EXPECT_EQ(r.evaluations, without.evaluations + 1);  // the one gradient that found it stationary
}

// Counts the Scores the poll asks for; the gradient is the problem's smooth part by finite
// differences (only the order of the directions depends on it).
class CountingTarget : public detail::BoundaryPoll::Target {
 public:
  CountingTarget(const Problem& problem, std::uint64_t limit) : problem_(problem), limit_(limit) {}
  bool judge(std::span<const double> values, csp::Score& score) override {
    if (limit_ && judged >= limit_) return false;
    ++judged;
    score = problem_.score(values);
    return true;
  }
  bool gradient(std::span<const double> values, std::span<double> g) override {
    csp::Assignment x(values.begin(), values.end());
    for (std::size_t i = 0; i < g.size(); ++i) {
      const double h = 1e-6, keep = x[i];
      x[i] = keep + h;
      const double up = problem_.score(x).soft;
      x[i] = keep - h;
      const double down = problem_.score(x).soft;
      x[i] = keep;
      g[i] = (up - down) / (2 * h);
    }
    return true;
  }
  std::uint64_t judged = 0;

 private:
  const Problem& problem_;
  std::uint64_t limit_;
};

TEST(BoundaryPoll, NeverMovesToAWorseOrLessFeasiblePointAndHonoursItsBudgets) {
  auto problem = guarded_problem();
  const std::vector<VariableId> free = {0, 1};
  const std::vector<double> half = {4.0, 4.0};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-4, 4);
  detail::BoundaryPoll poll;
  int moved = 0;
  for (int trial = 0; trial < 100; ++trial) {
    detail::BoundaryPoll::Settings settings;
    settings.seed = static_cast<std::uint64_t>(trial);
    settings.max_evaluations = trial % 2 ? 300 : 25;
    CountingTarget target(*problem, trial % 3 == 0 ? 10 : 0);  // some with a caller limit
    csp::Assignment anchor = {coordinate(rng), coordinate(rng)};
    const csp::Score before = problem->score(anchor);
    csp::Score score = before;
    const bool changed = poll.run(*problem, free, half, settings, target, anchor, score);
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_TRUE(inside_domains(*problem, anchor));
    EXPECT_EQ(score.soft, problem->score(anchor).soft);
    EXPECT_EQ(score.hard, problem->score(anchor).hard);
    EXPECT_FALSE(before.better_than(score));
    if (before.feasible()) {
      EXPECT_TRUE(score.feasible());
    }
    EXPECT_EQ(changed, score.better_than(before));
    EXPECT_LE(target.judged, settings.max_evaluations);
    if (trial % 3 == 0) {
      EXPECT_LE(target.judged, 10u);
    }
    moved += changed;
  }
  EXPECT_GT(moved, 50);  // it does move: the checks above are not vacuous
}

// ---------------------------------------------------------------------------------------
// Alternatives.

TEST(CeresRefineOptions, AsksForAsManyAlternativesAsItsOptionSaysAndValidatesThePollOptions) {
  EXPECT_EQ(make_refiner()->alternatives_wanted(), 2u);
  EXPECT_EQ(make_refiner({{"alternatives", "5"}})->alternatives_wanted(), 5u);
  EXPECT_EQ(make_refiner({{"alternatives", "0"}})->alternatives_wanted(), 0u);
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"alternatives", "-1"}, {"poll_evaluations", "-1"}, {"poll_step", "0"},
           {"poll_step", "2"}, {"poll_min_step", "0"}}) {
    EXPECT_THROW(make_refiner({{key, value}}), OptionError) << key << "=" << value;
  }
  EXPECT_THROW(make_refiner({{"poll_step", "0.01"}, {"poll_min_step", "0.1"}}), OptionError);
}

TEST(CeresRefine, FindsTheBetterBasinFromAnAlternativeStart) {
  auto problem = two_basins();
  const csp::Assignment start = {-9.5};
  const std::vector<csp::Assignment> alternatives = {{9.8}};
  SolveContext context;
  // From the start alone it cannot cross the wall: the left basin's best, x = -8.
  const SolverResult alone = make_refiner()->solve(*problem, start, context);
  EXPECT_TRUE(alone.feasible());
  EXPECT_NEAR(alone.best[0], -8.0, 1e-2) << alone.brief_report("alone");
  // Handed the alternative, it refines from there too and keeps the better basin's optimum.
  context.alternative_starts = alternatives;
  const SolverResult both = make_refiner()->solve(*problem, start, context);
  EXPECT_TRUE(both.feasible());
  EXPECT_NEAR(both.best[0], 9.0, 1e-3) << both.brief_report("with the alternative");
  EXPECT_NE(both.message.find("from alternative 1:"), std::string::npos) << both.message;
  // With `alternatives` = 0 the hand-over is ignored.
  const SolverResult ignored = make_refiner({{"alternatives", "0"}})->solve(*problem, start, context);
  EXPECT_EQ(ignored.best, alone.best);
}

TEST(CeresRefine, RefiningFromAlternativesIsNeverWorseThanFromTheStartAlone) {
  auto problem = guarded_problem();
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> coordinate(-4, 4);
  auto refiner = make_refiner({{"alternatives", "3"}});
  int better = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const csp::Assignment start = {coordinate(rng), coordinate(rng)};
    std::vector<csp::Assignment> alternatives;
    for (int k = 0; k < 3; ++k) alternatives.push_back({coordinate(rng), coordinate(rng)});
    SolveContext context;
    const SolverResult alone = refiner->solve(*problem, start, context);
    context.alternative_starts = alternatives;
    const SolverResult with = refiner->solve(*problem, start, context);
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + with.brief_report("with"));
    EXPECT_FALSE(alone.score.better_than(with.score));
    EXPECT_FALSE(problem->score(start).better_than(with.score));
    if (problem->score(start).feasible()) {
      EXPECT_TRUE(with.feasible());
    }
    better += with.score.better_than(alone.score);
  }
  // The guarded problem has basins (the disc splits the bowl's floor): some starts gain.
  EXPECT_GT(better, 0);
}

// A stage that hands over fixed alternatives (more than asked, to see the pipeline trim
// them), and records what it was asked for.
class Explorer : public Solver {
 public:
  Explorer(csp::Assignment best, std::vector<csp::Assignment> alternatives)
      : best_(std::move(best)), alternatives_(std::move(alternatives)) {}
  std::string name() const override { return "explorer"; }
  void solve_into(const csp::Problem& problem, std::span<const double>,
                  const SolveContext& context, SolverResult& result) override {
    asked = context.alternatives_wanted;
    result.best = best_;
    result.score = problem.score(best_);
    result.evaluations = 1;
    result.iterations = 0;
    result.stop = StopReason::kCompleted;
    result.message.clear();
    if (context.alternatives_wanted > 0) result.alternatives = alternatives_;
  }
  std::size_t asked = 99;

 private:
  csp::Assignment best_;
  std::vector<csp::Assignment> alternatives_;
};

// A stage that wants `wanted` alternative starts and records those it got.
class Follower : public Solver {
 public:
  explicit Follower(std::size_t wanted) : wanted_(wanted) {}
  std::string name() const override { return "follower"; }
  std::size_t alternatives_wanted() const override { return wanted_; }
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const SolveContext& context, SolverResult& result) override {
    asked = context.alternatives_wanted;
    got.assign(context.alternative_starts.begin(), context.alternative_starts.end());
    result.best.assign(start.begin(), start.end());
    result.score = problem.score(result.best);
    result.evaluations = 1;
    result.iterations = 0;
    result.stop = StopReason::kCompleted;
    result.message.clear();
  }
  std::size_t asked = 99;
  std::vector<csp::Assignment> got;

 private:
  std::size_t wanted_;
};

TEST(Pipeline, AsksEachStageForWhatTheNextWantsAndHandsOverItsAlternatives) {
  auto problem = two_basins();
  const std::vector<csp::Assignment> offered = {{9.0}, {-9.0}, {8.5}};
  auto explorer = std::make_unique<Explorer>(csp::Assignment{-9.5}, offered);
  auto follower = std::make_unique<Follower>(2);
  Explorer* first = explorer.get();
  Follower* second = follower.get();
  std::vector<std::unique_ptr<Solver>> stages;
  stages.push_back(std::move(explorer));
  stages.push_back(std::move(follower));
  Pipeline pipeline("explorer>follower", std::move(stages));
  EXPECT_EQ(pipeline.alternatives_wanted(), 0u);  // the first stage's
  const SolverResult r = pipeline.solve(*problem, csp::Assignment{0.0});
  EXPECT_EQ(first->asked, 2u);
  EXPECT_EQ(second->asked, 0u);  // the pipeline's own caller asked for none
  EXPECT_EQ(second->got, (std::vector<csp::Assignment>{{9.0}, {-9.0}}));
  EXPECT_TRUE(r.alternatives.empty());
  EXPECT_EQ(r.best, (csp::Assignment{-9.5}));
}

TEST(Pipeline, RefinesFromTheCoarseStagesAlternativeToTheBetterBasin) {
  // A coarse stage that lands in the worse basin but has seen the better one: the pipeline
  // hands it to ceres-refine, which crosses no wall but starts there too.
  auto problem = two_basins();
  for (const bool hand_over : {false, true}) {
    std::vector<std::unique_ptr<Solver>> stages;
    stages.push_back(std::make_unique<Explorer>(
        csp::Assignment{-9.5}, std::vector<csp::Assignment>{{-9.0}, {9.8}}));
    stages.push_back(make_refiner({{"alternatives", hand_over ? "2" : "0"}}));
    Pipeline pipeline("explorer>ceres-refine", std::move(stages));
    const SolverResult r = pipeline.solve(*problem, csp::Assignment{-9.5});
    SCOPED_TRACE(r.brief_report(pipeline.name()));
    EXPECT_TRUE(r.feasible());
    EXPECT_NEAR(r.best[0], hand_over ? 9.0 : -8.0, 1e-2);
  }
}

}  // namespace
}  // namespace sightline::solvers
