// Loading a problem for `sightline solve` by the file's extension:
//   .yaml / .yml        a problem file (csp/files/problem_file.h)
//   .col                a DIMACS graph, coloured with `colours` colours (domains/colouring)
//   .wcsp / .wcsp.gz    a toulbar2 weighted CSP (csp/files/wcsp_reader.h)
//   .cfn (.gz/.bz2/.xz) the same in toulbar2's JSON format (csp/files/cfn_reader.h)
// Anything else, a .col without a number of colours, and a number of colours for another
// file type, are InputErrors naming the file.
#pragma once

#include <memory>
#include <string>

#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/problem.h"

namespace sightline::apps {

struct LoadOptions {
  int colours = 0;  // for graphs; 0 = not given
  // How the caller's users give `colours`, for the messages about it: the program's option
  // ("--colours", "--colours K"), or the Python module's argument ("colours", "colours=K").
  std::string colours_name = "--colours";
  std::string colours_usage = "--colours K";
};

std::unique_ptr<csp::Problem> load_problem(const std::string& path, const LoadOptions& options);
// The same, with the value labels a problem file gives (empty for the other types).
csp::LoadedProblem load_model(const std::string& path, const LoadOptions& options);

}  // namespace sightline::apps
