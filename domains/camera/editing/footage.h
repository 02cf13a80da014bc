// Footage: every candidate shot filmed at every slot of an edit -- the poses an editor
// chooses among, with what they show.
//
// Time is cut into slots (a quarter second by default) from the earliest to the latest
// keyframe of the scene's people, each slot covering [t, t + slot), the last one up to the
// end. At each slot each candidate is composed by the
// cinematographer's solvers: an idiom shot from where its idiom places the camera (moved by
// the people since the last slot), refined by a local shot-search and kept on its side of
// the line of action (screen direction); a named shot as a tracking shot (a global solve at
// the first slot and when it has lost the shot, a local one otherwise). Each take records
// the pose, the shot's verdict (FORMATS.md's satisfaction and feasibility), how each person
// is shown (head and a third of the body in the image and unhidden, from the front, a
// fifth of the image height or more) and the size on screen of its subject.
#pragma once

#include <cstdint>
#include <vector>

#include "sightline/domains/camera/composition/camera_pose.h"
#include "sightline/domains/camera/editing/candidate_shots.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

struct FootageOptions {
  double slot_seconds = 0.25;
  std::uint64_t refine_evaluations = 150;   // local shot-search per take
  std::uint64_t global_evaluations = 1500;  // a named shot's global solve
  std::uint64_t seed = 1;
};

// How one person appears in a take.
struct PersonInTake {
  bool shown = false;   // head and at least 9 of the 27 samples in the image and unhidden
  bool front = false;   // the camera within 90 degrees of where they face
  double size = 0;      // height on screen of the body (FORMATS.md's size, height), 0 if behind
};

struct Take {
  CameraPose pose;
  bool feasible = false;
  double satisfaction = 0;
  std::vector<PersonInTake> people;  // by world.people() index
  double subject_size = 0;           // the largest size among the people shown (0: nobody)
};

struct Footage {
  std::vector<CandidateShot> candidates;
  std::vector<std::string> people;   // names, as ShotWorld orders them
  double start = 0, end = 0;         // the film's first and last times
  double slot_seconds = 0.25;
  std::vector<double> slot_times;    // start + i x slot_seconds, < end (one slot at least)
  std::vector<std::vector<Take>> takes;  // [slot][candidate]
  double seconds = 0;                // spent filming it
  std::uint64_t evaluations = 0;     // shot evaluations spent
};

// The first and last keyframe times of the scene's people (followed character and actors).
std::pair<double, double> people_time_span(const Scene& scene);

// How person `who` appears from `pose` in the world as it is (the editor's own measure).
PersonInTake person_in_view(const class ShotWorld& world, int who, const CameraPose& pose);

// Films every candidate at every slot. Throws std::invalid_argument for a scene without
// people, or a slot <= 0.
Footage film_footage(const Scene& scene, std::vector<CandidateShot> candidates,
                     const FootageOptions& options);

}  // namespace sightline::camera
