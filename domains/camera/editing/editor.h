// Editor: films a scene as an edited sequence of shots (FORMATS.md "Script and named
// shots"): footage of every candidate shot at every slot (footage.h), the editing model
// (edit_model.h) solved by any registered discrete solver -- `chain` (exact dynamic
// programming, the default), bnb, tabu, lns, sls -- or by the greedy editor ("greedy"), and
// the chosen shots played back frame by frame: within a shot the camera passes through its
// takes on a Catmull-Rom curve (position, view direction, lens), and at a cut (or where a
// shot's own camera jumps: a cut keeping its name) it starts the new take.
#pragma once

#include <string>
#include <vector>

#include "sightline/csp/score.h"
#include "sightline/domains/camera/editing/edit_model.h"
#include "sightline/domains/camera/editing/footage.h"

namespace sightline::camera {

inline constexpr const char* kGreedyEditor = "greedy";
inline constexpr const char* kDefaultEditSolver = "chain";

struct EditorOptions {
  std::string solver = kDefaultEditSolver;  // a registered solver, or "greedy"
  double time_limit_seconds = 0;            // for the solver (0: its own course)
  std::uint64_t seed = 1;
  FootageOptions footage;
  EditWeights weights;
  ContinuityRules rules;
};

// One shot of the film: candidate `shot` from `start` until `end` (the next shot's start, or
// the film's end), and why the editor cut to it.
struct FilmShot {
  std::size_t shot = 0;
  double start = 0, end = 0;
  std::size_t first_slot = 0;
  std::string why;  // the costs that decided the cut ("opening shot" for the first)
};

struct EditedFrame {
  double t = 0;
  CameraPose pose;
  std::size_t shot = 0;
  bool cut = false;
  double cost = 0;  // the shot's unary cost at the frame's slot
};

struct Edit {
  Footage footage;
  EditCosts costs;
  std::vector<std::size_t> choice;  // the shot per slot
  std::vector<FilmShot> shots;
  std::vector<EditedFrame> frames;
  std::string solver;
  csp::Score score;                 // of the choice in the model
  double solve_seconds = 0;         // the solver's (or the greedy editor's) time
  std::size_t model_constraints = 0;
  std::string solver_message;       // the solver's brief report
};

// Films and edits the scene. Throws std::invalid_argument for an unknown solver, one that
// cannot solve the model (continuous-only), or a scene without people.
Edit edit_scene(const Scene& scene, const EditorOptions& options);

// Edits footage already filmed (the same footage for several solvers).
Edit edit_footage(const Scene& scene, Footage footage, const EditorOptions& options);

// The frame times of the film: from the first to the last keyframe of the people, one every
// 1 / frame_rate s, both ends included.
std::vector<double> film_frame_times(const Scene& scene);

}  // namespace sightline::camera
