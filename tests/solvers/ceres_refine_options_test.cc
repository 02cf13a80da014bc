// Tests of ceres-refine's parts and limits: options and registration, the smooth forms of
// the kinks, the objective Ceres sees (its gradient against finite differences, the map of
// unbounded parameters into the box, the guard), and the evaluation and iteration limits.
#include <gtest/gtest.h>

#include <random>

#include "sightline/solvers/ceres_refine.h"
#include "tests/solvers/ceres_refine_test_problems.h"

namespace sightline::solvers {
namespace {

using namespace ceres_refine_testing;

// ---------------------------------------------------------------------------------------
// Options and registration.

TEST(CeresRefineOptions, DefaultsAreValid) {
  EXPECT_EQ(CeresRefineSolver::Options{}.validate(), "");
}

TEST(CeresRefineOptions, RejectsBadValuesNamingTheField) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"smoothing", "-1"},          {"line_search_direction", "newton"},
      {"function_tolerance", "0"},  {"gradient_tolerance", "-1e-9"},
      {"parameter_tolerance", "0"}, {"max_iterations", "0"},
      {"backoff_steps", "61"},      {"guard_hard", "maybe"},
  };
  for (const auto& [key, value] : bad) {
    try {
      make_refiner({{key, value}});
      ADD_FAILURE() << key << "=" << value << " was accepted";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(make_refiner({{"smoothness", "1"}}), OptionError);
  EXPECT_NO_THROW(make_refiner({{"line_search_direction", "bfgs"}, {"smoothing", "0"}}));
}

TEST(CeresRefine, IsRegisteredAndListsItsOptions) {
  const SolverInfo& info = SolverRegistry::global().info("ceres-refine");
  for (const char* key : {"max_iterations", "function_tolerance", "gradient_tolerance", "smoothing",
                          "line_search_direction", "backoff_steps"}) {
    EXPECT_TRUE(info.has_option(key)) << key;
  }
}

TEST(CeresRefine, IsUnsuitableWithoutContinuousVariables) {
  Problem discrete;
  discrete.add_variable("a", Domain::integer_range(0, 3));
  discrete.add_variable("fixed", Domain::real_interval(1, 1));
  EXPECT_NE(make_refiner()->unsuitable_reason(discrete), "");
  Problem mixed;
  mixed.add_variable("a", Domain::integer_range(0, 3));
  mixed.add_variable("x", Domain::real_interval(0, 1));
  EXPECT_EQ(make_refiner()->unsuitable_reason(mixed), "");
}

// ---------------------------------------------------------------------------------------
// The smooth forms of |r| and max(0, r).

TEST(SmoothForms, AreZeroExactlyWhereTheKinkIsSatisfiedAndWithinTheWidthOfIt) {
  const double s = 0.1;
  EXPECT_EQ(csp::smooth_abs(0.0, s), 0.0);
  EXPECT_EQ(csp::smooth_hinge(0.0, s), 0.0);
  EXPECT_EQ(csp::smooth_hinge(-3.0, s), 0.0);
  for (double r = -2; r <= 2; r += 0.01) {
    const double a = csp::smooth_abs(r, s);
    EXPECT_LE(a, std::abs(r) + 1e-15);
    EXPECT_GE(a, std::abs(r) - s);
    if (r != 0) {
      EXPECT_GT(a, 0.0);
    }
    const double h = csp::smooth_hinge(r, s);
    EXPECT_LE(h, std::max(0.0, r) + 1e-15);
    EXPECT_GE(h, std::max(0.0, r) - s / 2 - 1e-15);
  }
}

TEST(SmoothForms, SlopesMatchFiniteDifferencesAndJets) {
  const double s = 0.1, h = 1e-7;
  for (double r = -1.003; r <= 1; r += 0.0137) {  // avoids landing exactly on 0 and s
    const double fd_abs = (csp::smooth_abs(r + h, s) - csp::smooth_abs(r - h, s)) / (2 * h);
    const double fd_hinge = (csp::smooth_hinge(r + h, s) - csp::smooth_hinge(r - h, s)) / (2 * h);
    EXPECT_NEAR(csp::smooth_abs_slope(r, s), fd_abs, 1e-6) << r;
    EXPECT_NEAR(csp::smooth_hinge_slope(r, s), fd_hinge, 1e-6) << r;
    using J = ceres::Jet<double, 1>;
    EXPECT_NEAR(csp::smooth_abs(J(r, 0), s).v[0], fd_abs, 1e-6);
    EXPECT_NEAR(csp::smooth_hinge(J(r, 0), s).v[0], fd_hinge, 1e-6);
  }
  // C1 at the hinge's joints: the slope is continuous at 0 and at s.
  EXPECT_NEAR(csp::smooth_hinge_slope(1e-12, s), 0.0, 1e-9);
  EXPECT_NEAR(csp::smooth_hinge_slope(s - 1e-12, s), 1.0, 1e-9);
}

// ---------------------------------------------------------------------------------------
// The objective Ceres sees.

TEST(RefinementObjective, GradientMatchesFiniteDifferences) {
  auto problem = mixed_problem();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  detail::RefinementObjective objective;
  for (double smoothing : {0.0, 0.05}) {
    for (int trial = 0; trial < 50; ++trial) {
      csp::Assignment start = {-2 + 5 * unit(rng), 2.0, -1 + 2.5 * unit(rng), 10 * unit(rng)};
      objective.reset(*problem, start, Terms::kSoft, smoothing, /*guard_hard=*/false);
      ASSERT_EQ(objective.num_parameters(), 3u);  // k is discrete: fixed
      std::vector<double> u(3), gradient(3), probe(3);
      objective.to_parameters(start, u);
      double f = 0;
      ASSERT_TRUE(objective.evaluate(u, f, gradient));
      for (int i = 0; i < 3; ++i) {
        const double h = 1e-6 * std::max(1.0, std::abs(u[i]));
        double up = 0, down = 0;
        probe = u;
        probe[i] = u[i] + h;
        ASSERT_TRUE(objective.evaluate(probe, up, {}));
        probe[i] = u[i] - h;
        ASSERT_TRUE(objective.evaluate(probe, down, {}));
        const double fd = (up - down) / (2 * h);
        // Exact violations have a kink where the L1 term is 0; the smoothed ones do not.
        EXPECT_NEAR(gradient[i], fd, 1e-5 * std::max(1.0, std::abs(fd)))
            << "smoothing " << smoothing << " trial " << trial << " u" << i;
      }
    }
  }
}

TEST(RefinementObjective, MapsEveryParameterIntoTheBoxAndBackInside) {
  auto problem = mixed_problem();
  detail::RefinementObjective objective;
  const csp::Assignment start = {0.5, 1.0, 0.25, 5.0};
  objective.reset(*problem, start, Terms::kSoft, 0.0, true);
  csp::Assignment values(4);
  std::vector<double> u(3), back(3);
  for (double a = -100; a <= 100; a += 0.37) {
    u = {a, -2 * a, a * a};
    objective.to_assignment(u, values);
    EXPECT_TRUE(inside_domains(*problem, values)) << a;
    EXPECT_EQ(values[1], 1.0);  // the discrete variable keeps its start value
  }
  // Round trip for interior points; points on a bound come back nudged inside.
  objective.to_parameters(start, u);
  objective.to_assignment(u, values);
  for (VariableId v : {0u, 2u, 3u}) EXPECT_NEAR(values[v], start[v], 1e-12);
  objective.to_parameters(csp::Assignment{3.0, 1.0, -1.0, 0.0}, u);
  objective.to_assignment(u, values);
  EXPECT_LT(values[0], 3.0);
  EXPECT_GT(values[0], 3.0 - 0.01);
  EXPECT_GT(values[2], -1.0);
  EXPECT_LT(values[2], -1.0 + 0.01);
}

TEST(RefinementObjective, RefusesPointsThatBreakTheHardConstraintsMoreThanTheStart) {
  auto problem = mixed_problem();  // hard: x + y <= 4
  detail::RefinementObjective objective;
  objective.reset(*problem, csp::Assignment{2.0, 0.0, 1.0, 1.0}, Terms::kSoft, 0.0, true);
  std::vector<double> u(3);
  double f = 0;
  objective.to_parameters(csp::Assignment{2.9, 0.0, 1.4, 1.0}, u);  // x + y = 4.3
  EXPECT_FALSE(objective.evaluate(u, f, {}));
  objective.to_parameters(csp::Assignment{2.5, 0.0, 1.4, 1.0}, u);  // 3.9
  EXPECT_TRUE(objective.evaluate(u, f, {}));
  // From an infeasible start (x + y = 4.4) only points at least as feasible are accepted.
  objective.reset(*problem, csp::Assignment{3.0, 0.0, 1.4, 1.0}, Terms::kSoft, 0.0, true);
  objective.to_parameters(csp::Assignment{2.9, 0.0, 1.45, 1.0}, u);  // 4.35
  EXPECT_TRUE(objective.evaluate(u, f, {}));
  objective.to_parameters(csp::Assignment{2.95, 0.0, 1.49, 1.0}, u);  // 4.44
  EXPECT_FALSE(objective.evaluate(u, f, {}));
  objective.set_evaluation_cap(objective.evaluations());
  EXPECT_FALSE(objective.evaluate(u, f, {}));
  EXPECT_TRUE(objective.cap_reached());
}

// ---------------------------------------------------------------------------------------
// Limits.

TEST(CeresRefine, HonoursTheEvaluationLimit) {
  Problem p("rosenbrock");
  p.add_variable("x", Domain::real_interval(-2, 2));
  p.add_variable("y", Domain::real_interval(-2, 2));
  add_jet<Rosenbrock, 2>(p, {0, 1}, Rosenbrock{});
  const csp::Assignment start = {-1.2, 1.0};
  // Unlimited, it converges in 47 evaluations; below that the limit stops it, but what it
  // found before is kept.
  for (std::uint64_t cap : {5u, 20u, 40u}) {
    SolveContext context;
    context.limits.max_evaluations = cap;
    const SolverResult r = make_refiner()->solve(p, start, context);
    EXPECT_LE(r.evaluations, cap) << r.brief_report("ceres-refine");
    EXPECT_EQ(r.stop, StopReason::kEvaluationLimit) << r.brief_report("ceres-refine");
    EXPECT_FALSE(p.score(start).better_than(r.score));
    if (cap >= 20) {
      EXPECT_TRUE(r.score.better_than(p.score(start)));
    }
  }
}

TEST(CeresRefine, HonoursTheIterationLimit) {
  Problem p("rosenbrock");
  p.add_variable("x", Domain::real_interval(-2, 2));
  p.add_variable("y", Domain::real_interval(-2, 2));
  add_jet<Rosenbrock, 2>(p, {0, 1}, Rosenbrock{});
  SolveContext context;
  context.limits.max_iterations = 3;
  const SolverResult r = make_refiner()->solve(p, csp::Assignment{-1.2, 1.0}, context);
  EXPECT_LE(r.iterations, 3u);
  EXPECT_EQ(r.stop, StopReason::kIterationLimit) << r.brief_report("ceres-refine");
  // The solver's own max_iterations (per Ceres run) is its course, not a limit that stopped
  // it. Rosenbrock has no hard constraint, so the runs are the refine rounds (the poll, which
  // would add a round after it moves, is off).
  const SolverResult own =
      make_refiner({{"max_iterations", "3"}, {"smoothing_rounds", "2"}, {"poll_evaluations", "0"}})
          ->solve(p, csp::Assignment{-1.2, 1.0});
  EXPECT_LE(own.iterations, 6u);
  EXPECT_EQ(own.stop, StopReason::kCompleted);
  EXPECT_NE(own.message.find("NO_CONVERGENCE"), std::string::npos) << own.message;
}

}  // namespace
}  // namespace sightline::solvers
