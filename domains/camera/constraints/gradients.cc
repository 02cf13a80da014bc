// Exact gradients of the smooth camera constraints: the functors of cost_terms.h evaluated
// with ceres::Jet (forward-mode automatic differentiation). Kept in this one translation unit
// so the template-heavy Ceres headers are compiled once.
#include <ceres/jet.h>

#include "domains/camera/constraints/smooth_constraints.h"

namespace sightline::camera {
namespace {

// Evaluates term(scope values) with one Jet per scope variable, then returns
// shape(r) and writes d shape(r) / d scope[i] into gradient[i], where shape is |r|
// (smoothing = 0) or smooth_abs(r, smoothing).
template <int N, class Term>
double jet_evaluate(const Term& term, std::span<const csp::VariableId> scope,
                    std::span<const double> values, std::span<double> gradient,
                    double smoothing) {
  using Jet = ceres::Jet<double, N>;
  Jet x[N];
  for (int i = 0; i < N; ++i) x[i] = Jet(values[scope[i]], i);
  const Jet r = term(x);
  const Jet shaped = smoothing > 0 ? csp::smooth_abs(r, smoothing) : abs(r);
  for (int i = 0; i < N; ++i) gradient[i] = shaped.v[i];
  return shaped.a;
}

}  // namespace

double HeightConstraint::violation_and_gradient(std::span<const double> values,
                                                std::span<double> gradient) const {
  return jet_evaluate<1>(term(), scope(), values, gradient, 0);
}
double HeightConstraint::smooth_violation_and_gradient(std::span<const double> values,
                                                       std::span<double> gradient,
                                                       double smoothing) const {
  return jet_evaluate<1>(term(), scope(), values, gradient, smoothing);
}

double DistanceConstraint::violation_and_gradient(std::span<const double> values,
                                                  std::span<double> gradient) const {
  return jet_evaluate<2>(term(), scope(), values, gradient, 0);
}
double DistanceConstraint::smooth_violation_and_gradient(std::span<const double> values,
                                                         std::span<double> gradient,
                                                         double smoothing) const {
  return jet_evaluate<2>(term(), scope(), values, gradient, smoothing);
}

double OrientationConstraint::violation_and_gradient(std::span<const double> values,
                                                     std::span<double> gradient) const {
  return jet_evaluate<2>(term(), scope(), values, gradient, 0);
}
double OrientationConstraint::smooth_violation_and_gradient(std::span<const double> values,
                                                            std::span<double> gradient,
                                                            double smoothing) const {
  return jet_evaluate<2>(term(), scope(), values, gradient, smoothing);
}

double FrameCoherenceConstraint::violation_and_gradient(std::span<const double> values,
                                                        std::span<double> gradient) const {
  return jet_evaluate<3>(term(), scope(), values, gradient, 0);
}
double FrameCoherenceConstraint::smooth_violation_and_gradient(std::span<const double> values,
                                                               std::span<double> gradient,
                                                               double smoothing) const {
  return jet_evaluate<3>(term(), scope(), values, gradient, smoothing);
}

}  // namespace sightline::camera
