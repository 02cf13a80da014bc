// ToricFraming (`toric`): exact two-subject framing (Lino & Christie 2012).
//
// Given two subjects A and B and the screen points where the shot wants them (its
// screen_position properties of two different targets), the rays from the camera to them
// make a fixed angle theta (from the screen points, the fov and the aspect), so the camera
// lies on a spindle torus around AB: p = A + |AP| (cos(beta) u + sin(beta) (cos(phi) e1 +
// sin(phi) e2)), u = AB / |AB|, beta in (0, pi - theta) the angle at A, |AP| = |AB|
// sin(theta + beta) / sin(theta), phi the turn about AB. At each such p exactly one
// orientation puts A and B on their points; its roll varies with phi. The solver searches
// (beta, phi) on a grid, keeps the poses whose roll the shot allows (for a fixed roll:
// the roots of roll(phi) - roll, bracketed by the grid and found by regula falsi, so both
// subjects land on their points to within rounding), and scores each with the whole
// problem (the other properties, region, clearance): the best is the result. The beta
// samples are visited coarse to fine, so a solve cut short by its time limit has covered
// the whole range. Used alone, or as the seed of a refining solver (`toric>shot-search`).
// With a fov range it tries its ends and its middle.
#pragma once

#include <cstdint>
#include <string>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::camera {

class ToricFraming : public solvers::Solver {
 public:
  struct Options {
    std::int64_t beta_steps = 64;  // samples of the angle at A
    std::int64_t phi_steps = 96;   // samples of the turn about AB (roots are bisected)

    static const solvers::OptionSchema<Options>& schema();
    std::string validate() const;
  };

  ToricFraming(std::string name, Options options) : name_(std::move(name)), options_(options) {}
  std::string name() const override { return name_; }
  // Needs a composition problem with screen_position properties of two different targets
  // at different screen points.
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const solvers::SolveContext& context, solvers::SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
};

}  // namespace sightline::camera
