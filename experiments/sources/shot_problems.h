// Shot problems: a seeded benchmark of composition problems (FORMATS.md "Shots"), the
// project's own, for comparing composition solvers on satisfaction against time budget.
//
// Each seed makes one scene: 1 to 4 people (standing apart, turned toward each other when
// they are several) among furniture, pillars and a wall with a doorway, and one shot of a
// kind drawn from: close-up and medium shot of one person, over-the-shoulder (from behind
// one at the other), two-shot, group shot (everyone framed), establishing shot (everyone
// small, from above), some with an exclusion (a person who must stay out of the frame).
// The scene is written as scene-file text (shot_problem_yaml) and read like any file, so
// the problems can be written out and judged by other tools.
#pragma once

#include <cstdint>
#include <string>

#include "sightline/domains/camera/scene.h"

namespace sightline::experiments {

// The scene-file text of problem `seed` (>= 1).
std::string shot_problem_yaml(std::uint64_t seed);
// The same, read.
camera::Scene shot_problem(std::uint64_t seed);
// Its shot kind ("close-up", "medium", "over-the-shoulder", "two-shot", "group",
// "establishing"), for tables.
std::string shot_problem_kind(std::uint64_t seed);

}  // namespace sightline::experiments
