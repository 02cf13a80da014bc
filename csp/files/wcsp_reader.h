// Reading toulbar2's .wcsp format into a Problem, so the project's solvers can be checked
// against the reference weighted-CSP solver's own instances and known optima.
//
// The format (toulbar2's "CpWcspFormats"; see docs/WCSP.md for the whole mapping):
//   <name> <nVars> <maxDomSize> <nFuncs> <UB>
//   <domSize_0> ... <domSize_{nVars-1}>
//   per cost function: <arity> <var...> <defaultCost> <nTuples>, then nTuples lines
//   <valueIndex...> <cost>.
// What the reader makes of it:
//  - variable i is "x<i>" with the integer range 0..d_i-1 (values are toulbar2's value
//    indices, so a solution printed as values is what `toulbar2 -w` writes);
//  - a cost function in extension becomes a Table. toulbar2 costs are integers and a cost
//    >= UB means "forbidden", so a function with forbidden tuples is split into a HARD table
//    (violation 1 exactly on the forbidden tuples, label "f<k>/hard") and a soft table with
//    the remaining costs (label "f<k>"); either part is left out when it is empty. The soft
//    cost of a feasible assignment is then exactly toulbar2's cost.
//  - arity 0 is a constant cost: a soft unary table on x0 with that default and no tuples
//    (or, when the constant is >= UB, a hard one: the problem has no solution);
//  - a shared cost function (negative arity) is remembered and reused by later functions
//    whose tuple count is -k (the k-th shared one, from 1), with the shared table's default;
//  - `-1 salldiff var|dec <cost>` becomes AllDifferent with that measure: weight <cost>, or
//    hard with weight 1 when <cost> >= UB.
// Anything else (another global keyword, an interval domain) is an InputError
// "not supported: <keyword>" at its line; so are malformed counts, indices out of range,
// tuples listed twice and truncated files. One difference remains by design: toulbar2 also
// rejects an assignment whose TOTAL cost reaches UB; here such an assignment is feasible
// with that soft cost (which is >= UB, so it never beats a toulbar2 solution).
//
// Files compressed with gzip, bzip2 or xz (recognised by their first bytes, whatever their
// name) are decompressed on the fly with Boost.Iostreams.
#pragma once

#include <istream>
#include <memory>
#include <string>

#include "sightline/csp/problem.h"

namespace sightline::csp {

// Reads a .wcsp file (plain or compressed). Throws InputError naming the file and line.
std::unique_ptr<Problem> read_wcsp_file(const std::string& path);
// Reads .wcsp text from a stream (already decompressed); `origin` names it in errors.
std::unique_ptr<Problem> parse_wcsp(std::istream& in, const std::string& origin);

}  // namespace sightline::csp
