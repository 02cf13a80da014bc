// CandidateShots: the shots an editor may cut between -- the scene's named shots (FORMATS.md
// "Script and named shots") and shots made from the idioms of filmed dialogue (He, Cohen and
// Salesin 1996; Arijon's grammar) for the people the script names:
//   close-up and medium shot of a person, over-the-shoulder onto a person from behind the
//   one they talk with, the two-shot of a pair who talk, and an establishing shot of everyone;
// each in two mirror forms, the subject on the left or on the right of the frame, so that an
// edit keeping one side of the line of action keeps screen direction (a speaker on the left
// looks right, toward the one spoken to).
//
// An idiom shot is a shot like any other (properties scored by the composition's
// definitions), and it says where its camera starts at a time (idiom_start): the subject's
// partner (the one they speak with under the line of action then) fixes which side of the
// line the camera stands on for its mirror form.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sightline/domains/camera/composition/camera_pose.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/composition/shot_world.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

enum class Idiom { kNamed, kCloseUp, kMedium, kOverShoulder, kTwoShot, kEstablishing };
const char* to_string(Idiom idiom);

struct CandidateShot {
  std::string name;                  // the named shot's, or "medium ann (left)"
  std::shared_ptr<const Shot> shot;  // what it must show
  Idiom idiom = Idiom::kNamed;
  std::string subject;   // the person it is about (the first of a two-shot's pair)
  std::string other;     // over-the-shoulder: whose shoulder; two-shot: the second of the pair
  bool subject_left = true;  // the subject on the left of the frame (its partner to the right)
};

// Named shots first (file order), then the idioms for every person the script names (or
// every person, without a script), pairs as the script pairs them.
std::vector<CandidateShot> candidate_shots(const Scene& scene);

// Who `person` faces in the scene at t: for the line of action then, the addressee if they
// speak, else the speaker; without one, the nearest other person; -1 when alone. Indices
// into world.people().
int partner_at(const Scene& scene, const ShotWorld& world, int person, double t);

// Where the idiom's camera starts at the world's time: the subject and its partner placed by
// the idiom's distance and vantage, on the side of their line that puts the subject on the
// frame's side the shot asks for. nullopt for a named shot, or a subject not in the world.
std::optional<CameraPose> idiom_start(const CandidateShot& candidate, const Scene& scene,
                                      const ShotWorld& world);

// Whether `pose` keeps the candidate's screen direction at the world's time: the subject's
// partner is on the right of the subject in the view when the subject is on the left, and
// the other way round. True for named shots and subjects alone.
bool keeps_screen_direction(const CandidateShot& candidate, const Scene& scene,
                            const ShotWorld& world, const CameraPose& pose);

}  // namespace sightline::camera
