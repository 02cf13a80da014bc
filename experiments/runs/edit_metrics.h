// EditMetrics: how an edited film keeps the rules of continuity editing, judged from the
// trace (its camera, look-at point, lens, cut and shot columns) and the scene alone
// (FORMATS.md "Script and named shots"), with IndependentPeople's own geometry:
//   - line-of-action crossings: at a cut, the camera before and the camera after on opposite
//     sides (more than 5 cm) of the line of action at the cut's time;
//   - jump cuts: at a cut, the view direction turns less than 30 degrees and the largest
//     person shown changes size on screen by less than a factor of 1.5;
//   - shots (runs between cuts) shorter than the minimum, cuts per minute, mean shot length;
//   - speaking time: frames inside a line of dialogue, per line under way; the speaker is
//     shown when their head sample and at least 9 of their 27 samples are in the image and
//     unhidden (a close-up's worth), from the front when the camera is within 90 degrees of
//     where they face, large enough to read when their body is a fifth of the image height
//     or more;
//   - action time likewise, the actor shown.
#pragma once

#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

struct EditMetrics {
  int frames = 0, cuts = 0, shots = 0;
  double seconds = 0;
  double cuts_per_minute = 0, mean_shot_seconds = 0, shortest_shot_seconds = 0;
  int short_shots = 0;       // shorter than the minimum
  int line_crossings = 0, jump_cuts = 0;
  double speaking_seconds = 0, speaker_shown_percent = 100, speaker_readable_percent = 100;
  double action_seconds = 0, action_shown_percent = 100;
};

// `aspect` is the image's (16:9 unless the film's shots say otherwise); `min_shot_seconds`
// the minimum shot length judged.
// The metrics' names as suites' results.csv columns, and their values in that order.
const std::vector<std::string>& edit_metric_names();
std::vector<double> edit_metric_values(const EditMetrics& m);

EditMetrics edit_metrics(const camera::Scene& scene, const std::vector<TraceRow>& trace,
                         double min_shot_seconds = 2.0, double aspect = 16.0 / 9.0);

}  // namespace sightline::experiments
