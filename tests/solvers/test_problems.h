// Tiny test problems shared by the solver tests: small enough for the grid to be the
// reference optimum, built from test-local constraints (a lambda over the scope's values) and
// the all_different kind, so they depend on no other kind.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/problem.h"

namespace sightline::test_problems {

// A constraint whose violation is any function of its scope's values (no incremental state,
// so local search takes the generic re-evaluation path).
class LambdaConstraint : public csp::Constraint {
 public:
  using Function = std::function<double(const std::vector<double>&)>;
  LambdaConstraint(std::vector<csp::VariableId> scope, Function f, double weight = 1,
                   bool hard = false)
      : Constraint(std::move(scope), weight, hard), f_(std::move(f)) {}
  std::string_view kind() const override { return "test.lambda"; }
  double violation(std::span<const double> values) const override {
    std::vector<double> x(scope().size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = values[scope()[i]];
    return f_(x);
  }

 private:
  Function f_;
};

inline void add(csp::Problem& p, std::vector<csp::VariableId> scope, LambdaConstraint::Function f,
                double weight = 1, bool hard = false) {
  p.add_constraint(
      std::make_unique<LambdaConstraint>(std::move(scope), std::move(f), weight, hard));
}

// Four variables in 0..3 (256 assignments): a hard all_different on a, b, c, soft pulls that
// disagree with each other, so the optimum costs more than zero and has local minima around.
inline std::unique_ptr<csp::Problem> tiny_discrete_problem() {
  auto p = std::make_unique<csp::Problem>("tiny discrete");
  const auto a = p->add_variable("a", csp::Domain::integer_range(0, 3));
  const auto b = p->add_variable("b", csp::Domain::integer_range(0, 3));
  const auto c = p->add_variable("c", csp::Domain::integer_range(0, 3));
  const auto d = p->add_variable("d", csp::Domain::value_set({-1, 0, 2, 5}));
  p->add_constraint(std::make_unique<csp::AllDifferent>(
      std::vector<csp::VariableId>{a, b, c}, std::vector<double>{},
      csp::AllDifferent::Measure::kVariables, 1.0, /*hard=*/true));
  add(
      *p, {a, b}, [](const auto& x) { return std::abs(x[0] - x[1] - 2); }, 1.0);
  add(
      *p, {c}, [](const auto& x) { return (x[0] - 3) * (x[0] - 3); }, 0.7);
  add(
      *p, {c, d}, [](const auto& x) { return x[0] + x[1] == 4 ? 0.0 : 1.0; }, 1.5);
  add(
      *p, {a, d}, [](const auto& x) { return std::abs(x[0] + x[1] - 2); }, 0.9);
  add(
      *p, {b, d}, [](const auto& x) { return x[0] * x[1] > 0 ? 0.0 : 0.4; }, 1.0);
  return p;
}

// Two real variables in [-1, 1]: f(x, y) = (x - 0.31)^2 + 2 (y + 0.17)^2 + 0.5 (x + y - 0.4)^2,
// a smooth bowl with its minimum inside the box at (0.3843, -0.1329) (solve grad f = 0:
// 3x + y = 1.02, x + 5y = -0.28). Its Hessian [[3, 1], [1, 5]] has largest eigenvalue
// 4 + sqrt(2) < kContinuousCurvature.
constexpr double kContinuousCurvature = 5.5;
constexpr std::array<double, 2> kContinuousOptimum = {5.38 / 14, 1.02 - 3 * 5.38 / 14};

inline std::unique_ptr<csp::Problem> tiny_continuous_problem() {
  auto p = std::make_unique<csp::Problem>("tiny continuous");
  const auto x = p->add_variable("x", csp::Domain::real_interval(-1, 1));
  const auto y = p->add_variable("y", csp::Domain::real_interval(-1, 1));
  add(*p, {x}, [](const auto& v) { return (v[0] - 0.31) * (v[0] - 0.31); });
  add(
      *p, {y}, [](const auto& v) { return (v[0] + 0.17) * (v[0] + 0.17); }, 2.0);
  add(
      *p, {x, y}, [](const auto& v) { return (v[0] + v[1] - 0.4) * (v[0] + v[1] - 0.4); }, 0.5);
  return p;
}

// How far above the true minimum a lattice of `points` per dimension on the problem above can
// be: the optimum is within h/2 of a lattice point in each of the 2 dimensions (h = 2 /
// (points - 1)), and f(x* + e) - f* = e'He / 2 <= curvature |e|^2 / 2.
inline double continuous_lattice_tolerance(int points) {
  const double half_step = 1.0 / (points - 1);
  return kContinuousCurvature * 2 * half_step * half_step / 2;
}

// A random Max-CSP no exact solver finishes in seconds (60 variables of 8 values, 400 binary
// cost tables of costs 0..9, optimum above 0), for tests that must stop a solve from outside.
inline std::unique_ptr<csp::Problem> unfinishable_problem() {
  auto p = std::make_unique<csp::Problem>("unfinishable");
  p->add_variables("v", 60, csp::Domain::integer_range(0, 7));
  std::uint64_t state = 1;
  auto next = [&state](std::uint64_t n) {  // a small LCG: the problem is the same everywhere
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (state >> 33) % n;
  };
  for (int k = 0; k < 400; ++k) {
    const auto a = static_cast<csp::VariableId>(next(60));
    auto b = static_cast<csp::VariableId>(next(60));
    while (b == a) b = static_cast<csp::VariableId>(next(60));
    std::array<double, 64> costs{};
    for (double& c : costs) c = static_cast<double>(next(10));
    add(*p, {a, b}, [costs](const auto& v) {
      return costs[static_cast<std::size_t>(v[0]) * 8 + static_cast<std::size_t>(v[1])];
    });
  }
  return p;
}

// Starts for the solver tests. The continuous ones lie within a quarter of the box width of
// the optimum in each dimension: sliding-octree is a local, frame-to-frame method (its
// reach from the start is bounded, see sliding_octree.h), as is ceres-refine.
inline std::vector<std::vector<double>> discrete_starts() {
  return {{0, 0, 0, -1}, {3, 3, 3, 5}, {1, 2, 0, 2}};
}
inline std::vector<std::vector<double>> continuous_starts() {
  return {{0, 0}, {0.6, 0.2}, {0.1, -0.5}};
}

}  // namespace sightline::test_problems
