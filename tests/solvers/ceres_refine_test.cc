// Tests of ceres-refine: known optima of smooth problems, never worse than the start on random
// starts (with hard constraints the unconstrained optimum breaks), bounds, limits, options,
// the objective's gradient against finite differences, and the smooth forms of the kinks.
//
// The test problems use test-local constraints whose gradients come from one templated cost
// functor differentiated with ceres::Jet, the pattern the camera's cost terms follow.
#include "solvers/ceres_refine.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <random>

#include "csp/kinds/abs_deviation.h"
#include "csp/kinds/expression.h"
#include "csp/files/problem_file.h"
#include "csp/kinds/linear.h"
#include "csp/problem.h"
#include "solvers/registry.h"

namespace sightline::solvers {
namespace {

using csp::Domain;
using csp::Problem;
using csp::VariableId;
using Terms = detail::RefinementObjective::Terms;

// A soft constraint whose violation is Functor over its N scope values. The gradient is exact:
// the same functor evaluated on ceres::Jet<double, N>, one dual part per scope position.
template <class Functor, int N>
class JetConstraint : public csp::Constraint {
 public:
  JetConstraint(std::vector<VariableId> scope, Functor functor, double weight = 1,
                bool hard = false)
      : Constraint(std::move(scope), weight, hard), functor_(std::move(functor)) {}
  std::string_view kind() const override { return "test.jet"; }
  double violation(std::span<const double> values) const override {
    std::array<double, N> x;
    for (int i = 0; i < N; ++i) x[i] = values[scope()[i]];
    return functor_(x.data());
  }
  bool has_exact_gradient() const override { return true; }
  double violation_and_gradient(std::span<const double> values,
                                std::span<double> gradient) const override {
    using J = ceres::Jet<double, N>;
    std::array<J, N> x;
    for (int i = 0; i < N; ++i) x[i] = J(values[scope()[i]], i);
    const J v = functor_(x.data());
    for (int i = 0; i < N; ++i) gradient[i] = v.v[i];
    return v.a;
  }

 private:
  Functor functor_;
};

// sum_i a_i (x_i - t_i)^2: a bowl with its minimum 0 at t.
template <int N>
struct Bowl {
  std::array<double, N> centre, curvature;
  template <class T>
  T operator()(const T* x) const {
    T sum(0.0);
    for (int i = 0; i < N; ++i) sum += curvature[i] * (x[i] - centre[i]) * (x[i] - centre[i]);
    return sum;
  }
};

// Rosenbrock's banana (1 - x)^2 + 100 (y - x^2)^2, minimum 0 at (1, 1).
struct Rosenbrock {
  template <class T>
  T operator()(const T* x) const {
    return (1.0 - x[0]) * (1.0 - x[0]) + 100.0 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]);
  }
};

// Hard: the point (x, y) stays at least `radius` from `centre`; violation = how far inside.
class DiscExclusion : public csp::Constraint {
 public:
  DiscExclusion(VariableId x, VariableId y, double cx, double cy, double radius)
      : Constraint({x, y}, 1.0, true), cx_(cx), cy_(cy), radius_(radius) {}
  std::string_view kind() const override { return "test.disc_exclusion"; }
  double violation(std::span<const double> v) const override {
    const double d = std::hypot(v[scope()[0]] - cx_, v[scope()[1]] - cy_);
    return std::max(0.0, radius_ - d);
  }

 private:
  double cx_, cy_, radius_;
};

// Hard: a . x <= b over the scope; violation = the excess.
class HalfSpace : public csp::Constraint {
 public:
  HalfSpace(std::vector<VariableId> scope, std::vector<double> a, double b)
      : Constraint(std::move(scope), 1.0, true), a_(std::move(a)), b_(b) {}
  std::string_view kind() const override { return "test.half_space"; }
  double violation(std::span<const double> v) const override {
    double s = 0;
    for (std::size_t i = 0; i < a_.size(); ++i) s += a_[i] * v[scope()[i]];
    return std::max(0.0, s - b_);
  }

 private:
  std::vector<double> a_;
  double b_;
};

template <class Functor, int N>
void add_jet(Problem& problem, std::vector<VariableId> scope, Functor f, double weight = 1) {
  problem.add_constraint(
      std::make_unique<JetConstraint<Functor, N>>(std::move(scope), std::move(f), weight));
}

std::unique_ptr<Solver> make_refiner(const OptionValues& options = {}) {
  return SolverRegistry::global().create("ceres-refine", options);
}

bool inside_domains(const Problem& problem, const csp::Assignment& values) {
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    if (!problem.variable(v).domain.contains(values[v])) return false;
  }
  return true;
}

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

// A 3-variable problem with a bowl, a Rosenbrock term, an L1 term and a hard constraint.
std::unique_ptr<Problem> mixed_problem() {
  auto p = std::make_unique<Problem>("mixed");
  p->add_variable("x", Domain::real_interval(-2, 3));
  p->add_variable("k", Domain::integer_range(0, 4));
  p->add_variable("y", Domain::real_interval(-1, 1.5));
  p->add_variable("z", Domain::real_interval(0, 10));
  add_jet<Bowl<2>, 2>(*p, {0, 3}, Bowl<2>{{1.0, 4.0}, {2.0, 0.5}}, 1.5);
  add_jet<Rosenbrock, 2>(*p, {0, 2}, Rosenbrock{}, 0.1);
  p->add_constraint(std::make_unique<csp::AbsDeviation>(std::vector<VariableId>{2, 3, 1},
                                                        std::vector<double>{1.0, -0.5, 1.0}, 0.0,
                                                        csp::NumberOrParameter(1.0), 2.0));
  p->add_constraint(
      std::make_unique<HalfSpace>(std::vector<VariableId>{0, 2}, std::vector<double>{1, 1}, 4.0));
  return p;
}

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
// Known optima of smooth problems.

// A bowl over N variables in [-5, 5]^N, centred at `centre`, as N one-variable bowls.
template <int N>
std::unique_ptr<Problem> bowl_problem(const std::array<double, N>& centre,
                                      const std::array<double, N>& curvature) {
  auto p = std::make_unique<Problem>("bowl");
  std::vector<VariableId> scope;
  for (int i = 0; i < N; ++i) {
    scope.push_back(p->add_variable("x" + std::to_string(i), Domain::real_interval(-5, 5)));
  }
  add_jet<Bowl<N>, N>(*p, scope, Bowl<N>{centre, curvature});
  return p;
}

template <int N>
void expect_bowls_minimum_found(std::mt19937_64& rng, double centre_spread) {
  std::uniform_real_distribution<double> coordinate(-5, 5), spread(-centre_spread, centre_spread),
      curvature(0.2, 20);
  auto refiner = make_refiner();
  for (int trial = 0; trial < 10; ++trial) {
    std::array<double, N> centre, weights;
    for (int i = 0; i < N; ++i) {
      centre[i] = spread(rng);
      weights[i] = curvature(rng);
    }
    auto problem = bowl_problem<N>(centre, weights);
    csp::Assignment start(N);
    for (auto& x : start) x = coordinate(rng);
    const SolverResult r = refiner->solve(*problem, start);
    ASSERT_TRUE(inside_domains(*problem, r.best));
    for (int i = 0; i < N; ++i) {
      // The bowl is separable, so the box optimum is the centre clamped to the box.
      EXPECT_NEAR(r.best[i], std::clamp(centre[i], -5.0, 5.0), 1e-5)
          << N << " dims, trial " << trial << ", " << r.brief_report("ceres-refine");
    }
  }
}

TEST(CeresRefine, ReachesTheCentreOfQuadraticBowlsInOneToFiveDimensions) {
  std::mt19937_64 rng(11);
  expect_bowls_minimum_found<1>(rng, 4.5);
  expect_bowls_minimum_found<2>(rng, 4.5);
  expect_bowls_minimum_found<3>(rng, 4.5);
  expect_bowls_minimum_found<4>(rng, 4.5);
  expect_bowls_minimum_found<5>(rng, 4.5);
}

TEST(CeresRefine, StopsOnTheBoxWhenTheBowlsCentreIsOutsideIt) {
  std::mt19937_64 rng(12);
  expect_bowls_minimum_found<2>(rng, 12);
  expect_bowls_minimum_found<5>(rng, 12);
}

TEST(CeresRefine, ReachesTheBowlsCentreWithEveryLineSearchDirection) {
  auto problem = bowl_problem<3>({1.0, -2.0, 0.5}, {1.0, 4.0, 0.5});
  for (const char* direction : {"lbfgs", "bfgs", "nonlinear_cg", "steepest_descent"}) {
    const SolverResult r =
        make_refiner({{"line_search_direction", direction}, {"max_iterations", "2000"}})
            ->solve(*problem, csp::Assignment{-4.0, 4.0, 4.0});
    EXPECT_NEAR(r.best[0], 1.0, 1e-4) << direction << ": " << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[1], -2.0, 1e-4) << direction;
    EXPECT_NEAR(r.best[2], 0.5, 1e-4) << direction;
  }
}

TEST(CeresRefine, ReachesTheRosenbrockMinimumWithinBounds) {
  Problem p("rosenbrock");
  p.add_variable("x", Domain::real_interval(-2, 2));
  p.add_variable("y", Domain::real_interval(-2, 2));
  add_jet<Rosenbrock, 2>(p, {0, 1}, Rosenbrock{});
  const SolverResult r =
      make_refiner({{"max_iterations", "500"}})->solve(p, csp::Assignment{-1.2, 1.0});
  EXPECT_NEAR(r.best[0], 1.0, 1e-4) << r.brief_report("ceres-refine");
  EXPECT_NEAR(r.best[1], 1.0, 1e-4);
  EXPECT_LT(r.cost(), 1e-8);
}

TEST(CeresRefine, ReachesTheRosenbrockMinimumOnAnActiveBound) {
  // With x <= 0.5 the minimum is on the bound: y = x^2 there, so (0.5, 0.25), cost 0.25.
  Problem p("rosenbrock-cut");
  p.add_variable("x", Domain::real_interval(-2, 0.5));
  p.add_variable("y", Domain::real_interval(-2, 2));
  add_jet<Rosenbrock, 2>(p, {0, 1}, Rosenbrock{});
  const SolverResult r =
      make_refiner({{"max_iterations", "500"}})->solve(p, csp::Assignment{-1.2, 1.0});
  EXPECT_NEAR(r.best[0], 0.5, 1e-4) << r.brief_report("ceres-refine");
  EXPECT_NEAR(r.best[1], 0.25, 1e-4);
  EXPECT_NEAR(r.cost(), 0.25, 1e-6);
}

TEST(CeresRefine, ReachesTheUniqueOptimumOfAbsoluteDeviations) {
  // 1 |x - 1| + 1 |x - 2| + 1 |x - 4| + 3 |y - x| + 1 |x + y + z - 7| (abs_deviation kind).
  // x's three terms are minimised at their median x = 2 (slope -1 + ... changes sign only
  // there, and the other terms can be zeroed at x = 2: y = 2, z = 3): unique optimum, cost 3.
  Problem p("medians");
  p.add_variable("x", Domain::real_interval(-10, 10));
  p.add_variable("y", Domain::real_interval(-10, 10));
  p.add_variable("z", Domain::real_interval(-10, 10));
  auto deviation = [&](std::vector<VariableId> scope, std::vector<double> a, double target,
                       double weight) {
    p.add_constraint(std::make_unique<csp::AbsDeviation>(std::move(scope), std::move(a), 0.0,
                                                         csp::NumberOrParameter(target), weight));
  };
  deviation({0}, {1}, 1, 1);
  deviation({0}, {1}, 2, 1);
  deviation({0}, {1}, 4, 1);
  deviation({1, 0}, {1, -1}, 0, 3);
  deviation({0, 1, 2}, {1, 1, 1}, 7, 1);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-10, 10);
  auto refiner = make_refiner({{"max_iterations", "300"}});
  for (int trial = 0; trial < 10; ++trial) {
    const csp::Assignment start = {coordinate(rng), coordinate(rng), coordinate(rng)};
    const SolverResult r = refiner->solve(p, start);
    EXPECT_NEAR(r.best[0], 2.0, 1e-3) << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[1], 2.0, 1e-3);
    EXPECT_NEAR(r.best[2], 3.0, 1e-3);
    EXPECT_NEAR(r.cost(), 3.0, 1e-3);
  }
}

// ---------------------------------------------------------------------------------------
// Never worse, never less feasible.

// A bowl whose centre (1, 1) is inside a hard disc of radius 1.5 around (1.2, 0.8), a hard
// half-plane x + y <= 3.5 that cuts the bowl's level sets, and L1 and hinge terms (linear
// kind) that make the landscape kinked, over the box [-4, 4]^2.
std::unique_ptr<Problem> guarded_problem() {
  auto p = std::make_unique<Problem>("guarded");
  p->add_variable("x", Domain::real_interval(-4, 4));
  p->add_variable("y", Domain::real_interval(-4, 4));
  add_jet<Bowl<2>, 2>(*p, {0, 1}, Bowl<2>{{1.0, 1.0}, {1.0, 3.0}});
  p->add_constraint(std::make_unique<DiscExclusion>(0, 1, 1.2, 0.8, 1.5));
  p->add_constraint(
      std::make_unique<HalfSpace>(std::vector<VariableId>{0, 1}, std::vector<double>{1, 1}, 3.5));
  p->add_constraint(std::make_unique<csp::AbsDeviation>(std::vector<VariableId>{0, 1},
                                                        std::vector<double>{1, -2}, 0.0,
                                                        csp::NumberOrParameter(0.5), 0.7));
  p->add_constraint(std::make_unique<csp::LinearConstraint>(
      std::vector<VariableId>{0}, std::vector<double>{1}, csp::Relation::kGreaterEqual,
      csp::NumberOrParameter(-1.0), 2.0));
  return p;
}

TEST(CeresRefine, NeverWorsensTheScoreNorBreaksAHardConstraintFromRandomStarts) {
  auto problem = guarded_problem();
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> coordinate(-4, 4);
  // Every phase switched on and off: the guarantee must not depend on any of them.
  const std::vector<OptionValues> variants = {
      {},
      {{"guard_hard", "false"}},
      {{"restore_feasibility", "false"}, {"hard_penalty", "0"}},
      {{"smoothing", "0"}, {"backoff_steps", "0"}},
  };
  for (std::size_t variant = 0; variant < variants.size(); ++variant) {
    auto refiner = make_refiner(variants[variant]);
    int improved = 0, feasible_starts = 0, infeasible_starts = 0, restored = 0;
    for (int trial = 0; trial < 100; ++trial) {
      const csp::Assignment start = {coordinate(rng), coordinate(rng)};
      const csp::Score before = problem->score(start);
      const SolverResult r = refiner->solve(*problem, start);
      SCOPED_TRACE("variant " + std::to_string(variant) + " trial " + std::to_string(trial) +
                   ": " + r.brief_report("ceres-refine"));
      ASSERT_TRUE(inside_domains(*problem, r.best));
      const csp::Score after = problem->score(r.best);
      EXPECT_EQ(after.hard, r.score.hard);
      EXPECT_EQ(after.soft, r.score.soft);
      EXPECT_FALSE(before.better_than(after));
      EXPECT_LE(after.hard, before.hard);
      if (before.feasible()) {
        ++feasible_starts;
        EXPECT_TRUE(after.feasible());
      } else {
        ++infeasible_starts;
        restored += after.feasible();
      }
      improved += after.better_than(before);
    }
    // The checks above hold trivially for a solver that returns its start: it must move.
    EXPECT_GT(feasible_starts, 50);
    EXPECT_GT(infeasible_starts, 20);
    if (variant <= 1) {
      EXPECT_EQ(improved, 100) << "variant " << variant;
      // Escaping the disc is always possible, and the restore phase finds the way out.
      EXPECT_EQ(restored, infeasible_starts) << "variant " << variant;
    } else {
      EXPECT_GE(improved, feasible_starts) << "variant " << variant;
    }
  }
}

TEST(CeresRefine, BacksOffAlongTheSegmentWhenTheRefinedPointBreaksAHardConstraint) {
  // Bowl centred at x = 3, hard x <= 1, start 0. Unguarded, Ceres reaches 3 (infeasible);
  // bisecting [0, 3] for the farthest better point ends just below the wall at 1. Known.
  Problem p("wall");
  p.add_variable("x", Domain::real_interval(-5, 5));
  add_jet<Bowl<1>, 1>(p, {0}, Bowl<1>{{3.0}, {1.0}});
  p.add_constraint(
      std::make_unique<HalfSpace>(std::vector<VariableId>{0}, std::vector<double>{1}, 1.0));
  const SolverResult unguarded =
      make_refiner({{"guard_hard", "false"}})->solve(p, csp::Assignment{0.0});
  EXPECT_LE(unguarded.best[0], 1.0) << unguarded.brief_report("ceres-refine");
  EXPECT_GT(unguarded.best[0], 1.0 - 1e-8);
  EXPECT_NE(unguarded.message.find("backed off"), std::string::npos);
  // Guarded, the line search never leaves x <= 1 and ends against the wall.
  const SolverResult guarded = make_refiner()->solve(p, csp::Assignment{0.0});
  EXPECT_TRUE(guarded.feasible());
  EXPECT_GT(guarded.best[0], 0.99) << guarded.brief_report("ceres-refine");
  // No back-off allowed and nothing better on the segment: the start comes back.
  const SolverResult kept = make_refiner({{"guard_hard", "false"}, {"backoff_steps", "1"}})
                                ->solve(p, csp::Assignment{0.0});
  EXPECT_EQ(kept.best[0], 0.0);
}

TEST(CeresRefine, ReturnsTheStartWhenTheStartIsAlreadyOptimal) {
  auto problem = bowl_problem<2>({1.0, -2.0}, {1.0, 1.0});
  const SolverResult r = make_refiner()->solve(*problem, csp::Assignment{1.0, -2.0});
  EXPECT_EQ(r.best, (csp::Assignment{1.0, -2.0}));
  EXPECT_EQ(r.stop, StopReason::kTargetReached);
}

TEST(CeresRefine, KeepsDiscreteVariablesAtTheirStartValues) {
  auto problem = mixed_problem();
  const csp::Assignment start = {-1.5, 3.0, 0.0, 8.0};
  const SolverResult r = make_refiner()->solve(*problem, start);
  EXPECT_EQ(r.best[1], 3.0);
  EXPECT_TRUE(problem->score(r.best).better_than(problem->score(start)));
  EXPECT_TRUE(inside_domains(*problem, r.best));
}

TEST(CeresRefine, IsDeterministic) {
  auto problem = guarded_problem();
  auto a = make_refiner(), b = make_refiner();
  for (const csp::Assignment& start : {csp::Assignment{-3, 3}, csp::Assignment{3.9, -3.9}}) {
    const SolverResult ra = a->solve(*problem, start), rb = b->solve(*problem, start);
    const SolverResult again = a->solve(*problem, start);
    EXPECT_EQ(ra.best, rb.best);
    EXPECT_EQ(ra.best, again.best);
    EXPECT_EQ(ra.evaluations, again.evaluations);
    EXPECT_EQ(ra.iterations, rb.iterations);
  }
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
  // it. Rosenbrock has no hard constraint, so the runs are the refine rounds.
  const SolverResult own = make_refiner({{"max_iterations", "3"}, {"smoothing_rounds", "2"}})
                               ->solve(p, csp::Assignment{-1.2, 1.0});
  EXPECT_LE(own.iterations, 6u);
  EXPECT_EQ(own.stop, StopReason::kCompleted);
  EXPECT_NE(own.message.find("NO_CONVERGENCE"), std::string::npos) << own.message;
}

// ---------------------------------------------------------------------------------------
// User-defined constraints and pipelines.

TEST(CeresRefine, RefinesAnExpressionConstraintThroughFiniteDifferences) {
  // (x - 1.5)^2 + (y + 0.5)^2 written as a formula: no exact gradient, same optimum.
  Problem p("expression");
  p.add_variable("x", Domain::real_interval(-3, 3));
  p.add_variable("y", Domain::real_interval(-3, 3));
  p.add_constraint(std::make_unique<csp::ExpressionConstraint>(
      std::vector<VariableId>{0, 1}, std::vector<std::string>{"x", "y"},
      "(x - 1.5)^2 + (y + 0.5)^2", &p.parameters()));
  ASSERT_FALSE(p.constraint(0).has_exact_gradient());
  const SolverResult r = make_refiner()->solve(p, csp::Assignment{-2.0, 2.5});
  EXPECT_NEAR(r.best[0], 1.5, 1e-4) << r.brief_report("ceres-refine");
  EXPECT_NEAR(r.best[1], -0.5, 1e-4);
}

// Best feasible soft cost on a lattice of (2n + 1)^2 points `step` apart around `centre`.
double best_nearby(const Problem& problem, const csp::Assignment& centre, int n, double step) {
  double best = problem.score(centre).soft;
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      const csp::Assignment q = {centre[0] + i * step, centre[1] + j * step};
      if (!inside_domains(problem, q)) continue;
      const csp::Score score = problem.score(q);
      if (score.feasible()) best = std::min(best, score.soft);
    }
  }
  return best;
}

TEST(CeresRefine, SlidesAlongAWallToTheConstrainedOptimum) {
  // Isotropic bowl centred at (0.5, 0) inside a hard disc of radius 1 around the origin: the
  // constrained optimum is the disc's point nearest the bowl's centre, (1, 0), cost 0.25.
  // The guarded search stops where it first meets the wall; the slide phase follows it.
  Problem p("slide");
  p.add_variable("x", Domain::real_interval(-3, 3));
  p.add_variable("y", Domain::real_interval(-3, 3));
  add_jet<Bowl<2>, 2>(p, {0, 1}, Bowl<2>{{0.5, 0.0}, {1.0, 1.0}});
  p.add_constraint(std::make_unique<DiscExclusion>(0, 1, 0.0, 0.0, 1.0));
  for (const csp::Assignment& start :
       {csp::Assignment{-0.5, 2.0}, csp::Assignment{2.5, -2.5}, csp::Assignment{-1.5, -0.3}}) {
    const SolverResult r = make_refiner()->solve(p, start);
    EXPECT_TRUE(r.feasible()) << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[0], 1.0, 1e-4) << r.brief_report("ceres-refine");
    EXPECT_NEAR(r.best[1], 0.0, 1e-4);
    // Without the slide phase it stalls on the wall somewhere else (the reason it exists).
    const SolverResult stalled = make_refiner({{"hard_penalty", "0"}})->solve(p, start);
    EXPECT_TRUE(stalled.feasible());
    EXPECT_GT(stalled.cost(), r.cost() + 1e-3) << stalled.brief_report("no slide");
  }
}

TEST(CeresRefine, AfterACoarseSolverInAPipelineIsBetterAndLocallyOptimal) {
  auto problem = guarded_problem();
  for (const std::string coarse_name : {"grid", "sliding-octree"}) {
    auto coarse = SolverRegistry::global().create(coarse_name);
    auto pipeline = SolverRegistry::global().create(coarse_name + ">ceres-refine");
    const csp::Assignment start = problem->default_assignment();
    const SolverResult alone = coarse->solve(*problem, start);
    const SolverResult refined = pipeline->solve(*problem, start);
    SCOPED_TRACE(alone.brief_report(coarse_name) + "\n" +
                 refined.brief_report(coarse_name + ">ceres-refine"));
    EXPECT_FALSE(alone.score.better_than(refined.score));
    EXPECT_TRUE(refined.feasible());
    // The coarse solvers miss the kinked optimum on the disc's edge; refinement finds it:
    // no feasible point within 0.1 (a 0.5 mm lattice) is better by more than 1e-6.
    EXPECT_LT(refined.cost(), alone.cost() - 1e-3);
    EXPECT_GT(best_nearby(*problem, refined.best, 200, 0.0005), refined.cost() - 1e-6);
  }
}

TEST(CeresRefine, FindsTheKnownOptimumOfTheShelfExampleAfterEveryCoarseSolver) {
  // examples/problems/shelf.yaml: L1 wishes (abs_deviation), a hard budget (linear), an
  // expression hinge; known unique optimum x = 0.7, y = 4, z = 1.2, cost 2.3.
  const auto problem =
      csp::read_problem_file(std::string(SIGHTLINE_SOURCE_DIR) + "/examples/problems/shelf.yaml");
  for (const std::string name : {"ceres-refine", "grid>ceres-refine", "sliding-octree>ceres-refine",
                                 "sls>ceres-refine"}) {
    const SolverResult r = SolverRegistry::global().create(name)->solve(
        *problem, problem->default_assignment());
    SCOPED_TRACE(r.brief_report(name));
    EXPECT_TRUE(r.feasible());
    EXPECT_NEAR(r.cost(), 2.3, 1e-4);
    EXPECT_NEAR(r.best[0], 0.7, 1e-3);
    EXPECT_NEAR(r.best[1], 4.0, 1e-3);
    EXPECT_NEAR(r.best[2], 1.2, 1e-3);
  }
}

}  // namespace
}  // namespace sightline::solvers
