// Tests of the sliding octree: the exact candidates of table 8 (child centres, shrinking,
// sliding), 2^d children per pass, never worse than the start, feasibility first, limits,
// suitability and options.
#include "sightline/solvers/sliding_octree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "sightline/solvers/registry.h"
#include "tests/solvers/test_problems.h"

namespace sightline::solvers {
namespace {

using test_problems::add;

// A soft constraint that records every point it is evaluated at.
class Recorder : public csp::Constraint {
 public:
  Recorder(std::vector<csp::VariableId> scope, std::vector<std::vector<double>>* log,
           std::function<double(const std::vector<double>&)> f)
      : Constraint(std::move(scope)), log_(log), f_(std::move(f)) {}
  std::string_view kind() const override { return "test.recorder"; }
  double violation(std::span<const double> values) const override {
    std::vector<double> x(values.begin(), values.end());
    log_->push_back(x);
    return f_(x);
  }

 private:
  std::vector<std::vector<double>>* log_;
  std::function<double(const std::vector<double>&)> f_;
};

SlidingOctreeSolver make_octree(std::int64_t passes = 8, double scale = 0.6) {
  SlidingOctreeSolver::Options o;
  o.passes = passes;
  o.scale = scale;
  return SlidingOctreeSolver("sliding-octree", o);
}

TEST(SlidingOctreeSolver, EvaluatesTheChildCentresThenShrinksAndSlidesTowardTheBest) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::real_interval(-10, 10));
  const auto y = p.add_variable("y", csp::Domain::real_interval(-10, 10));
  std::vector<std::vector<double>> log;
  p.add_constraint(std::make_unique<Recorder>(
      std::vector<csp::VariableId>{x, y}, &log,
      [](const auto& v) { return std::abs(v[0] - 7) + std::abs(v[1] + 3); }));
  SlidingOctreeSolver octree = make_octree(2, 0.5);  // initial size 0.5 x 20 = 10 per axis
  const SolverResult r = octree.solve(p, std::vector<double>{1, 1});
  EXPECT_EQ(r.evaluations, 1u + 2 * 4);
  EXPECT_EQ(r.iterations, 2u);
  // The score() of finish_result comes after; the first 9 points are the search.
  ASSERT_GE(log.size(), 9u);
  EXPECT_EQ(log[0], (std::vector<double>{1, 1}));  // the start
  // Pass 1: centre (1, 1), size 10, children at +-2.5; bit k of the child index picks the
  // half of axis k.
  EXPECT_EQ(log[1], (std::vector<double>{-1.5, -1.5}));
  EXPECT_EQ(log[2], (std::vector<double>{3.5, -1.5}));
  EXPECT_EQ(log[3], (std::vector<double>{-1.5, 3.5}));
  EXPECT_EQ(log[4], (std::vector<double>{3.5, 3.5}));
  // Best (3.5, -1.5); size 5; centre slides all the way there: children at +-1.25.
  EXPECT_EQ(log[5], (std::vector<double>{2.25, -2.75}));
  EXPECT_EQ(log[8], (std::vector<double>{4.75, -0.25}));
  EXPECT_EQ(r.best, (csp::Assignment{4.75, -2.75}));
}

TEST(SlidingOctreeSolver, EvaluatesTwoToTheDChildrenPerPass) {
  for (int d = 1; d <= 4; ++d) {
    csp::Problem p;
    std::vector<csp::VariableId> vars;
    for (int i = 0; i < d; ++i) {
      vars.push_back(p.add_variable("x" + std::to_string(i), csp::Domain::real_interval(0, 1)));
    }
    add(p, vars, [](const auto& v) {
      double s = 0;
      for (double t : v) s += (t - 0.3) * (t - 0.3);
      return s;
    });
    SlidingOctreeSolver octree = make_octree(5);
    const SolverResult r = octree.solve(p, p.default_assignment());
    EXPECT_EQ(r.evaluations, 1u + 5u * (1u << d)) << "d = " << d;
    EXPECT_EQ(r.iterations, 5u);
    EXPECT_EQ(r.stop, StopReason::kCompleted);
  }
}

TEST(SlidingOctreeSolver, ConvergesOnABowlWithinItsReach) {
  const auto problem = test_problems::tiny_continuous_problem();
  SlidingOctreeSolver octree = make_octree(20);
  const SolverResult r = octree.solve(*problem, std::vector<double>{0, 0});
  EXPECT_NEAR(r.best[0], test_problems::kContinuousOptimum[0], 1e-3);
  EXPECT_NEAR(r.best[1], test_problems::kContinuousOptimum[1], 1e-3);
}

TEST(SlidingOctreeSolver, NeverReturnsWorseThanItsStart) {
  const auto problem = test_problems::tiny_continuous_problem();
  const std::vector<double> start(test_problems::kContinuousOptimum.begin(),
                                  test_problems::kContinuousOptimum.end());
  SlidingOctreeSolver octree = make_octree();
  const SolverResult r = octree.solve(*problem, start);
  EXPECT_EQ(r.best, start) << "every child centre is worse than the exact optimum";
}

TEST(SlidingOctreeSolver, PrefersAFeasibleCandidateToACheaperInfeasibleOne) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::real_interval(-1, 1));
  const auto y = p.add_variable("y", csp::Domain::real_interval(-1, 1));
  add(p, {x, y}, [](const auto& v) { return v[0] * v[0] + v[1] * v[1]; });  // soft: to 0
  add(
      p, {x}, [](const auto& v) { return std::max(0.0, 0.5 - v[0]); }, 1e-6, true);  // x >= 0.5
  // Every pass evaluates children left of x = 0.5, cheaper but infeasible; none may win.
  SlidingOctreeSolver octree = make_octree(12);
  const SolverResult r = octree.solve(p, std::vector<double>{0.8, 0.4});
  EXPECT_TRUE(r.feasible()) << r.brief_report("sliding-octree");
  EXPECT_GE(r.best[0], 0.5);
  EXPECT_LT(r.cost(), 0.8 * 0.8 + 0.4 * 0.4);
  EXPECT_NEAR(r.best[0], 0.5, 0.05);
}

TEST(SlidingOctreeSolver, ClampsCandidatesToTheDomains) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::real_interval(0, 1));
  std::vector<std::vector<double>> log;
  p.add_constraint(std::make_unique<Recorder>(std::vector<csp::VariableId>{x}, &log,
                                              [](const auto& v) { return -v[0]; }));
  SlidingOctreeSolver octree = make_octree();
  const SolverResult r = octree.solve(p, std::vector<double>{1});
  for (const auto& point : log) {
    EXPECT_GE(point[0], 0.0);
    EXPECT_LE(point[0], 1.0);
  }
  EXPECT_EQ(r.best[0], 1.0);
}

TEST(SlidingOctreeSolver, UsesAnAbsoluteInitialSizeWhenGiven) {
  csp::Problem p;
  const auto x = p.add_variable("x", csp::Domain::real_interval(-100, 100));
  std::vector<std::vector<double>> log;
  p.add_constraint(std::make_unique<Recorder>(std::vector<csp::VariableId>{x}, &log,
                                              [](const auto& v) { return std::abs(v[0]); }));
  SlidingOctreeSolver::Options o;
  o.initial_size_absolute = 4;  // children at centre +- 1 metre
  SlidingOctreeSolver octree("sliding-octree", o);
  octree.solve(p, std::vector<double>{10});
  ASSERT_GE(log.size(), 3u);
  EXPECT_EQ(log[1][0], 9.0);
  EXPECT_EQ(log[2][0], 11.0);
}

TEST(SlidingOctreeSolver, IsUnsuitableForDiscreteOrTooManyDimensions) {
  SlidingOctreeSolver octree = make_octree();
  EXPECT_NE(octree.unsuitable_reason(*test_problems::tiny_discrete_problem()), "");
  EXPECT_EQ(octree.unsuitable_reason(*test_problems::tiny_continuous_problem()), "");
  csp::Problem wide;
  for (std::size_t i = 0; i <= SlidingOctreeSolver::kMaxDimensions; ++i) {
    wide.add_variable("x" + std::to_string(i), csp::Domain::real_interval(0, 1));
  }
  EXPECT_NE(octree.unsuitable_reason(wide).find("2^d"), std::string::npos);
  EXPECT_THROW(octree.solve(wide, wide.default_assignment()), std::invalid_argument);
}

TEST(SlidingOctreeSolver, StopsAtTheEvaluationAndIterationLimits) {
  const auto problem = test_problems::tiny_continuous_problem();
  SlidingOctreeSolver octree = make_octree();
  SolveContext context;
  context.limits.max_evaluations = 10;
  SolverResult r = octree.solve(*problem, problem->default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kEvaluationLimit);
  EXPECT_EQ(r.evaluations, 10u);
  EXPECT_EQ(r.iterations, 2u);  // 1 + 4 + 4 evaluations = two whole passes, then one more
  context.limits = {};
  context.limits.max_iterations = 3;
  r = octree.solve(*problem, problem->default_assignment(), context);
  EXPECT_EQ(r.stop, StopReason::kIterationLimit);
  EXPECT_EQ(r.iterations, 3u);
  EXPECT_EQ(r.evaluations, 1u + 3 * 4);
}

TEST(SlidingOctreeSolver, ValidatesItsOptionsNamingTheField) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"scale", "0.4"}, {"scale", "1"},        {"slide", "0"},
      {"passes", "0"},  {"initial_size", "0"}, {"initial_size_absolute", "-1"}};
  for (const auto& [field, value] : bad) {
    try {
      SolverRegistry::global().create("sliding-octree", {{field, value}});
      ADD_FAILURE() << field << "=" << value << " accepted";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(SlidingOctreeSolver::Options{}.validate(), "");
}

}  // namespace
}  // namespace sightline::solvers
