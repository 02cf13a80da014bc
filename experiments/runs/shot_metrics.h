// ShotMetrics: how a tracking shot (a scene with a shot: block, filmed frame by frame) kept
// its people, judged from the trace and the scene alone.
//
// A person counts as shown in a frame when as many of their 27 samples (FORMATS.md) as the
// shot asks for are in the image (the least low end of their framed ranges; without one,
// some) and are seen (the least low end of their visible ranges; without one, half): the sight line meets the interior
// of no box, mover or other person's box (touching does not hide) and no level triangle.
// The sight-line test here is this file's own (and IndependentTriangles for a level), so it
// shares no code with the composition's measures. Satisfaction (FORMATS.md's weighted mean)
// is recomputed per frame from the trace's pose by the shot's definitions.
#pragma once

#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/trace.h"

namespace sightline::experiments {

struct PersonShown {
  std::string name;
  double shown_percent = 0;  // frames where they were shown, %
};

struct ShotMetrics {
  std::vector<PersonShown> people;  // every person a property of the shot names
  double shown_percent_min = 0;     // the least shown of them
  double satisfaction_mean = 0, satisfaction_p10 = 0;
  double feasible_percent = 0;      // frames whose pose breaks no rule of the shot
};

// The metrics' names as suites' results.csv columns (shot_shown_min_pct,
// shot_satisfaction_mean, shot_satisfaction_p10, shot_feasible_pct), and their values.
const std::vector<std::string>& shot_metric_names();
std::vector<double> shot_metric_values(const ShotMetrics& m);

// The scene must have a shot; the trace's rows carry its fov and roll.
ShotMetrics shot_metrics(const camera::Scene& scene, const std::vector<TraceRow>& trace);

}  // namespace sightline::experiments
