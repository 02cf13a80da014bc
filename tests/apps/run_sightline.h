// Runs the sightline program (SIGHTLINE_BINARY, set by CMake) through the shell with the
// given arguments, for the end-to-end tests of tests/apps: its exit status and everything it
// printed (stdout and stderr together).
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace sightline::test {

struct Outcome {
  int status = -1;     // exit status; -1 when the program did not exit normally (a crash)
  std::string output;  // stdout and stderr together
};

inline Outcome run(const std::string& arguments) {
  const std::string command = std::string("'") + SIGHTLINE_BINARY + "' " + arguments + " 2>&1";
  Outcome r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe))
    r.output.append(buffer, n);
  const int raw = pclose(pipe);
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  return r;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace sightline::test
