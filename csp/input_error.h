// InputError: bad input from a file, with where it is and what was expected.
//
// Every reader in the project (problem files, scenes, profiles, suites, .wcsp) throws this for
// malformed input, so the command line can print "FILE:LINE: message" and exit non-zero
// instead of crashing or guessing.
#pragma once

#include <stdexcept>
#include <string>

namespace sightline::csp {

struct SourceLocation {
  std::string file;  // path as given by the user; empty when not from a file
  int line = 0;      // 1-based; 0 when unknown
  int column = 0;    // 1-based; 0 when unknown

  // "file:line:column", "file:line", "file" or "<input>".
  std::string str() const;
};

class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  // The message without the location prefix.
  const std::string& detail() const { return detail_; }

 private:
  SourceLocation where_;
  std::string detail_;
};

}  // namespace sightline::csp
