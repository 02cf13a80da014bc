// Suite comparisons: the pairs of solvers a suite's statistics compare (`statistics:
// {compare: [A, B]}` in a suite file, or `run --compare A,B`), checked against the suite's
// solver labels when read.
#pragma once

#include <string>
#include <vector>

#include "sightline/csp/input_error.h"
#include "sightline/csp/spec.h"
#include "sightline/experiments/suite/suite.h"

namespace sightline::experiments {

// Reads a suite file's `statistics:` mapping (after its solvers are read) into
// suite.comparisons. csp::InputError with the file and line for unknown keys, malformed
// pairs and names that are not solvers of the suite.
void read_statistics_settings(const csp::Spec& section, Suite& suite);

// Appends the pair after checking that a and b differ and are solver labels of one family
// (camera or problems) of the suite; csp::InputError at `where` listing the suite's solvers
// otherwise.
void add_comparison(Suite& suite, const std::string& a, const std::string& b,
                    const csp::SourceLocation& where);

// `--compare A,B` from the command line: the same checks, errors prefixed with "--compare".
void add_comparison_option(Suite& suite, const std::string& text);

// The suite's camera solver labels and problem solver labels, in the suite's order.
std::vector<std::string> camera_labels(const Suite& suite);
std::vector<std::string> problem_labels(const Suite& suite);

}  // namespace sightline::experiments
