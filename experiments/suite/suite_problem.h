// Building the problem of a toy suite run (N-queens, a problem file, a coloured graph), with
// the independent judge each kind has.
//
// Every run builds its own Problem (runs happen on several threads, and a Problem is used by
// one solver at a time). The judge counts broken conditions with code the constraints do not
// share (attacking queen pairs, conflicting edges), so results.csv can show that a reported
// cost is real; problem files have no judge.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/experiments/suite/suite.h"

namespace sightline::experiments {

struct LoadedSuiteProblem {
  std::unique_ptr<csp::Problem> problem;
  std::string label;  // "8-queens", the problem's name, "myciel5 (6 colours)"
  // Attacking pairs / conflicting edges of an assignment; empty for problem files.
  std::function<std::size_t(std::span<const double>)> count_broken;
  std::string broken_name;  // "attacking pairs", "conflicts"
  // A problem file's value labels (csp::LoadedProblem::value_labels); empty for the others.
  std::vector<std::vector<std::string>> value_labels;
};

// Throws csp::InputError for unreadable or malformed files and unknown extensions
// (.yaml/.yml problem files, .wcsp/.wcsp.gz, and for graphs .col/.yaml).
LoadedSuiteProblem load_suite_problem(const SuiteProblem& problem);

}  // namespace sightline::experiments
