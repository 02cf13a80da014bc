// Every registered solver, on the same tiny problems: each must find the grid's optimum
// (exactly on the discrete problem, within the lattice's own error on the continuous one)
// from several starts, be deterministic for a seed, honour the limits and a stop request,
// and answer bad
// options with messages that name the culprit. Solvers that declare a problem unsuitable
// are skipped on it. Pipelines must never end worse than their first stage.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "sightline/solvers/registry.h"
#include "tests/solvers/stop_request.h"
#include "tests/solvers/test_problems.h"

namespace sightline::solvers {
namespace {

using test_problems::continuous_lattice_tolerance;
using test_problems::continuous_starts;
using test_problems::discrete_starts;
using test_problems::tiny_continuous_problem;
using test_problems::tiny_discrete_problem;

constexpr int kLatticePoints = 41;

SolverResult grid_optimum(const csp::Problem& problem) {
  auto grid = SolverRegistry::global().create("grid", {{"points", std::to_string(kLatticePoints)}});
  return grid->solve(problem, problem.default_assignment());
}

bool natural_end(StopReason r) {
  return r == StopReason::kCompleted || r == StopReason::kProvenOptimal ||
         r == StopReason::kTargetReached;
}

class EverySolver : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Solver> make(const OptionValues& options = {}) {
    return SolverRegistry::global().create(GetParam(), options);
  }
};

TEST_P(EverySolver, FindsTheGridOptimumOfATinyDiscreteProblemExactly) {
  const auto problem = tiny_discrete_problem();
  auto solver = make();
  if (!solver->unsuitable_reason(*problem).empty()) GTEST_SKIP() << "unsuitable";
  const SolverResult reference = grid_optimum(*problem);
  ASSERT_EQ(reference.stop, StopReason::kProvenOptimal);
  for (const auto& start : discrete_starts()) {
    for (std::uint64_t seed : {1u, 7u}) {
      SolveContext context;
      context.seed = seed;
      const SolverResult r = solver->solve(*problem, start, context);
      EXPECT_TRUE(r.feasible()) << r.brief_report(GetParam());
      EXPECT_NEAR(r.cost(), reference.cost(), 1e-12) << r.brief_report(GetParam());
      EXPECT_DOUBLE_EQ(problem->cost(r.best), r.cost());
    }
  }
}

TEST_P(EverySolver, FindsTheGridOptimumOfATinyContinuousProblemWithinTheLatticeError) {
  const auto problem = tiny_continuous_problem();
  auto solver = make();
  if (!solver->unsuitable_reason(*problem).empty()) GTEST_SKIP() << "unsuitable";
  const SolverResult reference = grid_optimum(*problem);
  // A lattice solver (grid, with its own default `points`) is held to its own lattice.
  int points = kLatticePoints;
  for (const OptionInfo& o : SolverRegistry::global().info(GetParam()).options) {
    if (o.name == "points") points = std::min(points, std::stoi(o.default_value));
  }
  const double tolerance = continuous_lattice_tolerance(points);
  for (const auto& start : continuous_starts()) {
    const SolverResult r = solver->solve(*problem, start);
    EXPECT_LE(r.cost(), reference.cost() + tolerance) << r.brief_report(GetParam());
    // Nobody beats the true minimum, which is at most `tolerance` below the lattice's best.
    EXPECT_GE(r.cost(), reference.cost() - tolerance) << r.brief_report(GetParam());
    EXPECT_DOUBLE_EQ(problem->cost(r.best), r.cost());
  }
}

TEST_P(EverySolver, GivesIdenticalResultsForTheSameSeed) {
  for (const auto& problem : {tiny_discrete_problem(), tiny_continuous_problem()}) {
    auto solver = make();
    if (!solver->unsuitable_reason(*problem).empty()) continue;
    const auto start = problem->default_assignment();
    SolveContext context;
    context.seed = 42;
    const SolverResult a = solver->solve(*problem, start, context);
    const SolverResult b = make()->solve(*problem, start, context);
    EXPECT_EQ(a.best, b.best);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.stop, b.stop);
    // Reusing the same solver object does not change the answer either.
    const SolverResult c = solver->solve(*problem, start, context);
    EXPECT_EQ(a.best, c.best);
    EXPECT_EQ(a.evaluations, c.evaluations);
  }
}

TEST_P(EverySolver, KeepsWithinAnEvaluationLimitAndSaysSo) {
  for (const auto& problem : {tiny_discrete_problem(), tiny_continuous_problem()}) {
    auto solver = make();
    if (!solver->unsuitable_reason(*problem).empty()) continue;
    SolveContext context;
    context.limits.max_evaluations = 5;
    const SolverResult r = solver->solve(*problem, problem->default_assignment(), context);
    EXPECT_LE(r.evaluations, 5u) << r.brief_report(GetParam());
    EXPECT_TRUE(r.stop == StopReason::kEvaluationLimit || natural_end(r.stop))
        << r.brief_report(GetParam());
    EXPECT_NO_THROW(problem->check_assignment(r.best));
  }
}

TEST_P(EverySolver, KeepsWithinAnIterationLimitAndSaysSo) {
  for (const auto& problem : {tiny_discrete_problem(), tiny_continuous_problem()}) {
    auto solver = make();
    if (!solver->unsuitable_reason(*problem).empty()) continue;
    SolveContext context;
    context.limits.max_iterations = 2;
    const SolverResult r = solver->solve(*problem, problem->default_assignment(), context);
    EXPECT_LE(r.iterations, 2u) << r.brief_report(GetParam());
    EXPECT_TRUE(r.stop == StopReason::kIterationLimit || natural_end(r.stop))
        << r.brief_report(GetParam());
  }
}

TEST_P(EverySolver, StopsSoonAfterATimeLimit) {
  // Only the bound is checked here (a slow machine may legitimately finish first); the
  // solver-specific tests force the time limit on problems that cannot finish in time.
  for (const auto& problem : {tiny_discrete_problem(), tiny_continuous_problem()}) {
    auto solver = make();
    if (!solver->unsuitable_reason(*problem).empty()) continue;
    SolveContext context;
    context.limits.time_limit_seconds = 0.01;
    const SolverResult r = solver->solve(*problem, problem->default_assignment(), context);
    EXPECT_TRUE(r.stop == StopReason::kTimeLimit || natural_end(r.stop));
    EXPECT_LT(r.wall_seconds, 5.0);
  }
}

// A stop request (SolveLimits::stop: Ctrl-C in the Python module), set from another thread
// during a solve with no limit at all: the solver ends soon with its best so far, saying it
// was interrupted (or its own end, when it finished first).
TEST_P(EverySolver, StopsSoonWhenAskedToFromAnotherThread) {
  using std::chrono::milliseconds;
  for (const auto& problem : {tiny_discrete_problem(), tiny_continuous_problem(),
                              test_problems::unfinishable_problem()}) {
    auto solver = make();
    if (!solver->unsuitable_reason(*problem).empty()) continue;
    // The tiny ones may end first; on the other no solver ends (bnb would search for hours).
    const SolverResult r = testing::solve_asked_to_stop(*solver, *problem, milliseconds(50));
    EXPECT_TRUE(r.stop == StopReason::kInterrupted || natural_end(r.stop)) << r.brief_report(GetParam());
    EXPECT_LT(r.wall_seconds, 5.0) << r.brief_report(GetParam());
    EXPECT_NO_THROW(problem->check_assignment(r.best));
  }
}

TEST_P(EverySolver, AcceptsItsDefaultOptionsWrittenAsText) {
  const SolverInfo& info = SolverRegistry::global().info(GetParam());
  EXPECT_NO_THROW(make());
  OptionValues defaults;
  for (const OptionInfo& o : info.options) defaults[o.name] = o.default_value;
  EXPECT_NO_THROW(make(defaults)) << "the defaults, written back as text, must validate";
}

TEST_P(EverySolver, NamesTheOptionWhoseValueIsBad) {
  const SolverInfo& info = SolverRegistry::global().info(GetParam());
  for (const OptionInfo& o : info.options) {
    if (o.type == "text") continue;  // any text parses; its meaning is the solver's business
    try {
      make({{o.name, "not-a-value"}});
      ADD_FAILURE() << GetParam() << " accepted " << o.name << "=not-a-value";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find(o.name), std::string::npos) << e.what();
    }
  }
}

TEST_P(EverySolver, ListsTheValidOptionsWhenAnOptionIsUnknown) {
  const SolverInfo& info = SolverRegistry::global().info(GetParam());
  try {
    make({{"no_such_option", "1"}});
    FAIL() << "an unknown option was accepted";
  } catch (const OptionError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no_such_option"), std::string::npos) << message;
    for (const OptionInfo& o : info.options) {
      EXPECT_NE(message.find(o.name), std::string::npos) << o.name << " not in: " << message;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Registered, EverySolver,
                         ::testing::ValuesIn(SolverRegistry::global().names()),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(SolverRegistry, ListsTheKnownSolversWhenTheNameIsUnknown) {
  try {
    SolverRegistry::global().create("no-such-solver");
    FAIL() << "an unknown solver was created";
  } catch (const OptionError& e) {
    const std::string message = e.what();
    for (const std::string& name : SolverRegistry::global().names()) {
      EXPECT_NE(message.find(name), std::string::npos) << name << " not in: " << message;
    }
  }
}

TEST(SolverRegistry, HasTheGenericSolvers) {
  for (const char* name : {"grid", "sls", "sliding-octree"}) {
    EXPECT_TRUE(SolverRegistry::global().contains(name)) << name;
  }
}

TEST(Pipeline, NeverEndsWorseThanItsFirstStage) {
  const auto names = SolverRegistry::global().names();
  for (const auto& problem : {tiny_discrete_problem(), tiny_continuous_problem()}) {
    const auto starts = problem->all_discrete() ? discrete_starts() : continuous_starts();
    for (const std::string& first : names) {
      for (const std::string& second : names) {
        auto pipeline = SolverRegistry::global().create(first + ">" + second);
        if (!pipeline->unsuitable_reason(*problem).empty()) continue;
        auto alone = SolverRegistry::global().create(first);
        for (const auto& start : starts) {
          SolveContext context;
          context.seed = 3;  // the pipeline's first stage runs with the pipeline's seed
          const SolverResult p = pipeline->solve(*problem, start, context);
          const SolverResult a = alone->solve(*problem, start, context);
          EXPECT_FALSE(a.score.better_than(p.score))
              << first << ">" << second << ": " << p.brief_report(pipeline->name()) << " vs "
              << a.brief_report(first);
        }
      }
    }
  }
}

}  // namespace
}  // namespace sightline::solvers
