// Problem files: a weighted CSP written in YAML, read into a Problem.
//
// The format (docs/PROBLEM_FORMAT.md has the full description) names variables with their
// domains, parameters, and constraints that each name a registered kind:
//
//     name: australia
//     variables:
//       - {names: [WA, NT, SA, Q, NSW, V, T], labels: [red, green, blue]}
//     constraints:
//       - {kind: not_equal, scopes: [[WA, NT], [WA, SA], [NT, SA]]}
//
// Every mistake (malformed YAML, an unknown kind, field or variable, a wrong arity, an empty
// domain, a non-finite number, a name defined twice) is an InputError naming the file and
// line, never a crash and never a guess.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/csp/spec.h"

namespace sightline::csp {

// A problem with what the file says about it beyond the Problem itself.
struct LoadedProblem {
  std::unique_ptr<Problem> problem;
  std::string description;
  // value_labels[v] names the values of variable v (label i is value i) when the file
  // declared it with `labels:`; empty otherwise.
  std::vector<std::vector<std::string>> value_labels;

  // The label of `value` for variable `var` when it has one, else the number as written
  // ("3", "0.25").
  std::string value_name(VariableId var, double value) const;
};

// The label `value_labels` gives `value` of variable `var` (label i is value i), or null when
// there is none: what every writer of labelled values (JSON results, solution files, .cfn
// value names, Python) looks up before falling back on a number of its own.
const std::string* find_value_label(const std::vector<std::vector<std::string>>& value_labels,
                                    VariableId var, double value);

// Reads a problem file. Throws InputError (file, line, what was expected) on any mistake.
std::unique_ptr<Problem> read_problem_file(const std::string& path);
// Parses problem text; `origin` names it in error messages.
std::unique_ptr<Problem> parse_problem(const std::string& text, const std::string& origin);

// The same, keeping the description and value labels.
LoadedProblem load_problem_file(const std::string& path);
LoadedProblem load_problem_text(const std::string& text, const std::string& origin);
// Builds from an already parsed document (`default_name` when it has no `name:`).
LoadedProblem load_problem_spec(const Spec& document, const std::string& default_name);

}  // namespace sightline::csp
