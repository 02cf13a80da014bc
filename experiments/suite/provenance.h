// Provenance: where and how a result was made (host, CPU model, build commit, command line).
//
// A researcher who publishes a table must be able to say which machine and which build
// produced each row, and how to produce it again. Every run file and every row of
// results.csv carries these four texts; comparisons between runs ignore them
// (is_provenance_column in suite_runner.h).
#pragma once

#include <string>
#include <vector>

namespace sightline::experiments {

struct Provenance {
  std::string host;          // gethostname
  std::string cpu_model;     // the first "model name" of /proc/cpuinfo ("unknown" without)
  std::string build_commit;  // `git rev-parse HEAD` when the program was built, "-dirty"
                             // appended when the tree had uncommitted changes; "unknown"
                             // when built outside git
  std::string command_line;  // the command that was run, shell-quoted where needed
};

// This process's provenance, worked out once.
const Provenance& this_process_provenance();

// The words joined by spaces, each quoted for a POSIX shell when it needs it.
std::string shell_command_line(const std::vector<std::string>& words);

}  // namespace sightline::experiments
