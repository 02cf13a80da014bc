// Test problems and helpers shared by the ceres-refine tests (ceres_refine_*_test.cc).
//
// The problems use test-local constraints whose gradients come from one templated cost
// functor differentiated with ceres::Jet, the pattern the camera's cost terms follow, and
// 0/1 or hinge-shaped hard constraints whose optima are known.
#pragma once

#include <ceres/jet.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/kinds/abs_deviation.h"
#include "sightline/csp/kinds/linear.h"
#include "sightline/csp/problem.h"
#include "sightline/solvers/ceres_refine.h"
#include "sightline/solvers/registry.h"

namespace sightline::solvers::ceres_refine_testing {

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
inline void add_jet(Problem& problem, std::vector<VariableId> scope, Functor f, double weight = 1) {
  problem.add_constraint(
      std::make_unique<JetConstraint<Functor, N>>(std::move(scope), std::move(f), weight));
}

inline std::unique_ptr<Solver> make_refiner(const OptionValues& options = {}) {
  return SolverRegistry::global().create("ceres-refine", options);
}

inline bool inside_domains(const Problem& problem, const csp::Assignment& values) {
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    if (!problem.variable(v).domain.contains(values[v])) return false;
  }
  return true;
}

// A 3-variable problem with a bowl, a Rosenbrock term, an L1 term and a hard constraint.
inline std::unique_ptr<Problem> mixed_problem() {
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

// A bowl over N variables in [-5, 5]^N, centred at `centre`, as N one-variable bowls.
template <int N>
inline std::unique_ptr<Problem> bowl_problem(const std::array<double, N>& centre,
                                      const std::array<double, N>& curvature) {
  auto p = std::make_unique<Problem>("bowl");
  std::vector<VariableId> scope;
  for (int i = 0; i < N; ++i) {
    scope.push_back(p->add_variable("x" + std::to_string(i), Domain::real_interval(-5, 5)));
  }
  add_jet<Bowl<N>, N>(*p, scope, Bowl<N>{centre, curvature});
  return p;
}

// A bowl whose centre (1, 1) is inside a hard disc of radius 1.5 around (1.2, 0.8), a hard
// half-plane x + y <= 3.5 that cuts the bowl's level sets, and L1 and hinge terms (linear
// kind) that make the landscape kinked, over the box [-4, 4]^2.
inline std::unique_ptr<Problem> guarded_problem() {
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

// Best feasible soft cost on a lattice of (2n + 1)^2 points `step` apart around `centre`.
inline double best_nearby(const Problem& problem, const csp::Assignment& centre, int n, double step) {
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

}  // namespace sightline::solvers::ceres_refine_testing
