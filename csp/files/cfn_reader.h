// Reading toulbar2's JSON cost-function-network format (.cfn) into a Problem: the twin of the
// .wcsp reader (wcsp_reader.h), for instances published in the newer format, with named
// variables, named values and decimal costs.
//
// The document (toulbar2's "CFN format"):
//   {"problem": {"name": N, "mustbe": "<UB"},
//    "variables": {name: [value names...] | domain size, ...}   (or an array: unnamed)
//    "functions": {name: {"scope": [...], "defaultcost": c, "costs": [tuple..., cost, ...]}
//                      | {"scope": [...], "costs": [one cost per tuple, lexicographic]}
//                      | {"scope": [...], "costs": "name of another table function"}
//                      | {"scope": [...], "type": "salldiff", "params": {"metric", "cost"}}}}
// What the reader makes of it is what the .wcsp reader makes of the same network
// (docs/WCSP.md): variable values are value indices 0..d-1 (a value name in a tuple is
// looked up in its variable's domain); a table with costs >= UB is split into a hard table
// (violation 1 on the forbidden tuples, label "<function>/hard") and a soft one (label
// "<function>"); arity 0 is a constant; `salldiff` var|dec is an AllDifferent. Costs may be
// decimal (a number, or a number written as a string, as toulbar2 allows).
//
// Refused, with an InputError naming the file, line and column: text that is not JSON (its
// position from nlohmann's parser: toulbar2's relaxed syntax, with unquoted names or
// without commas, is not JSON and is refused as such), maximisation ("mustbe": ">..."), an
// upper bound <= 0, negative costs, interval domains (negative sizes), other global types,
// unknown names and indices, tuples of the wrong length or listed twice, dense tables of
// the wrong size, keys given twice in one object. Semantic errors point at the line of the
// key they are about (the function's or variable's name).
//
// Files compressed with gzip, bzip2 or xz are read as the .wcsp reader reads them.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "sightline/csp/problem.h"

namespace sightline::csp {

// Reads a .cfn file (plain or compressed). Throws InputError naming the file and position.
std::unique_ptr<Problem> read_cfn_file(const std::string& path);
// Reads .cfn text; `origin` names it in errors.
std::unique_ptr<Problem> parse_cfn(std::string_view text, const std::string& origin);

}  // namespace sightline::csp
