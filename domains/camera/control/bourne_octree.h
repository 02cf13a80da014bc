// BourneOctreeSolver ("bourne-octree"): Bourne & Sattar's original Sliding Octree Solver
// for the chase camera (thesis table 8, section 3.3), kept as published so its difference
// from Ali's occlusion-aware version can be measured.
//
// Candidates are scored on the profile's terms only (height, distance, orientation, frame
// coherence and any extras); occlusion is handled "nominally": before the passes, four rays
// are cast from the character's look-at point to the sides, top and bottom of the initial
// search cube (sides along the camera's right vector, top and bottom along +y). If the top
// ray is blocked, the height constraint's desired value is raised by the cube's half-size
// for this frame, pushing the camera up over whatever is in the way. Nothing else looks at
// visibility, which is why, in enclosed rooms, it picks positions behind walls (thesis
// figs. 24, 27, 30, 32). Only works on camera problems.
#pragma once

#include <optional>
#include <string>

#include "sightline/domains/camera/control/camera_problem_view.h"
#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::camera {

class BourneOctreeSolver : public solvers::Solver {
 public:
  struct Options {
    std::int64_t passes = 8;
    double initial_size = 0;  // half-size of the first cube, metres; 0 = the search box
    double scale = 0.6;       // cube shrink per pass, (0, 1)
    static const solvers::OptionSchema<Options>& schema();
    std::string validate() const { return ""; }
  };

  BourneOctreeSolver(std::string name, Options options)
      : name_(std::move(name)), options_(options) {}
  std::string name() const override { return name_; }
  std::string unsuitable_reason(const csp::Problem& problem) const override;
  void solve_into(const csp::Problem& problem, std::span<const double> start,
                  const solvers::SolveContext& context, solvers::SolverResult& result) override;

 private:
  std::string name_;
  Options options_;
  CameraProblemViewCache views_;
};

}  // namespace sightline::camera
