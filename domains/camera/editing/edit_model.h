// EditModel: editing as a weighted CSP over time (Galvane, Ronfard, Lino and Christie 2015's
// costs, in the framework's terms), built from the footage.
//
// Variables: one per slot, slot0 .. slot<n-1>, whose values are the candidate shots
// (0 .. K-1, in Footage::candidates order).
// Constraints, all soft:
//   edit.shot (unary, one per slot): what the shot shows at that slot --
//     composition (1 - satisfaction, and a price when its pose breaks the shot's rules),
//     script (each speaker not shown, shown from behind, or smaller than a fifth of the
//     image; each action's actor not shown; each in proportion to the share of the slot
//     the line or action takes), relevance (the idiom's fit to what happens:
//     the speaker's own medium shot fits a line best, a wide shot least; an establishing
//     shot opens the film);
//   edit.cut (binary, between consecutive slots): a cut's price, crossing the line of
//     action (at the slot's start or at the frame the film cuts on; any change of sign
//     counts), a jump cut, a camera standing on the line; continuing a shot costs nothing
//     unless its camera jumps (then it is a cut keeping the shot's name, priced as one and
//     as a shot cut short, since the runs of the stretch below do not see it);
//   stretch over all the slots: a shot shorter than the minimum length costs
//     short_shot x its shortfall, and one longer than the maximum long_shot x its excess
//     (csp/kinds/stretch.h: two stretch constraints, each with its weight).
// So the model is a chain: `chain` solves it exactly, and bnb, tabu, lns and sls like any
// weighted CSP. greedy_edit is the baseline: at each slot, once the shot has lasted the
// minimum, it cuts to the shot cheapest now if that beats the current one by a margin
// (hysteresis), among the shots a cut reaches without crossing the line or a jump cut.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/editing/continuity.h"
#include "sightline/domains/camera/editing/footage.h"

namespace sightline::camera {

struct EditWeights {
  double composition = 1;     // x (1 - satisfaction), per slot
  double infeasible = 3;      // per slot whose take breaks its shot's rules
  double speaker_hidden = 4;  // per slot and speaker not shown
  double speaker_view = 1;    // per slot and speaker shown from behind; again when too small
  double action_hidden = 4;   // per slot and action whose actor is not shown
  double relevance = 1;       // x the idiom's misfit (0 .. 0.8)
  double cut = 0.5;           // every cut
  double crossing = 20;       // a cut across the line of action
  double jump_cut = 20;
  double on_line = 1;         // a cut from or to a camera within a third of a metre of the line
  double short_shot = 100;    // x a shot's shortfall below the minimum length (fraction)
  double min_shot_seconds = 2;
  // Rhythm: a shot held longer than this costs long_shot x its excess (fraction of it), so a
  // long line is cut up among shots of its speaker (0: no maximum).
  double max_shot_seconds = 8;
  double long_shot = 32;
  double readable_size = 0.2;  // a speaker's body at least this much of the image height
  double max_speed = 8;        // m/s: the film's camera; a shot's moving over half this between slots jumps
  double hysteresis = 0.3;     // greedy: how much cheaper another shot must be to cut to it
};

// A slot's unary cost of one candidate, by part, for reports.
struct ShotCostParts {
  double composition = 0, script = 0, relevance = 0;
  double total() const { return composition + script + relevance; }
};

struct EditCosts {
  std::size_t slots = 0, shots = 0;
  std::size_t min_slots = 1;                    // the minimum shot length in slots
  std::size_t max_slots = 0;                    // the maximum (0: none)
  std::vector<std::vector<ShotCostParts>> unary;  // [slot][shot]
  std::vector<std::vector<double>> totals;      // [slot][shot]: unary[slot][shot].total()
  std::vector<std::vector<double>> change;      // [slot][from * shots + to], slot >= 1
  std::vector<std::vector<bool>> jumps;         // [slot][shot]: its camera jumped into the slot
};

EditCosts edit_costs(const Scene& scene, const Footage& footage, const EditWeights& weights,
                     const ContinuityRules& rules);

// The weighted CSP; `costs` must outlive it.
std::unique_ptr<csp::Problem> edit_problem(const EditCosts& costs, const EditWeights& weights,
                                           const std::string& name);

// The greedy editor with hysteresis: a shot per slot.
std::vector<std::size_t> greedy_edit(const EditCosts& costs, const EditWeights& weights);

}  // namespace sightline::camera
