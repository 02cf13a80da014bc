// Exact gradients of the smooth camera constraints: the functors of cost_terms.h evaluated
// with ceres::Jet (forward-mode automatic differentiation). Kept in this one translation unit
// so the template-heavy Ceres headers are compiled once.
#include <ceres/jet.h>

#include "sightline/domains/camera/constraints/smooth_constraints.h"

namespace sightline::camera {
namespace {

// Evaluates term(scope values) with one Jet per scope variable, then returns
// shape(r) and writes d shape(r) / d scope[i] into gradient[i], where shape is |r|
// (smoothing = 0) or smooth_abs(r, smoothing).
template <int N, class Term>
double jet_evaluate(const Term& term, std::span<const csp::VariableId> scope,
                    std::span<const double> values, std::span<double> gradient, double smoothing) {
  using Jet = ceres::Jet<double, N>;
  Jet x[N];
  for (int i = 0; i < N; ++i) x[i] = Jet(values[scope[i]], i);
  const Jet r = term(x);
  const Jet shaped = smoothing > 0 ? csp::smooth_abs(r, smoothing) : abs(r);
  for (int i = 0; i < N; ++i) gradient[i] = shaped.v[i];
  return shaped.a;
}

}  // namespace

template <class Derived, int N>
double AbsTermConstraint<Derived, N>::violation_and_gradient(std::span<const double> values,
                                                             std::span<double> gradient) const {
  return jet_evaluate<N>(static_cast<const Derived&>(*this).term(), scope(), values, gradient, 0);
}
template <class Derived, int N>
double AbsTermConstraint<Derived, N>::smooth_violation_and_gradient(std::span<const double> values,
                                                                    std::span<double> gradient,
                                                                    double smoothing) const {
  return jet_evaluate<N>(static_cast<const Derived&>(*this).term(), scope(), values, gradient,
                         smoothing);
}

template class AbsTermConstraint<HeightConstraint, 1>;
template class AbsTermConstraint<DistanceConstraint, 2>;
template class AbsTermConstraint<OrientationConstraint, 2>;
template class AbsTermConstraint<FrameCoherenceConstraint, 3>;

}  // namespace sightline::camera
