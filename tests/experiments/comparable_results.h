// results.csv of two runs of a suite (thread pool and MPI, isolated and in process, resumed
// and uninterrupted) made comparable: the columns that describe the machine and the
// invocation (timing, provenance) are blanked, everything else must agree.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/execution/suite_runner.h"

namespace sightline::experiments::testing {

// results.csv with the timing and provenance columns blanked: they describe the machine and
// the invocation, not the run.
inline std::string without_timing(const Suite& suite, const std::string& csv) {
  const std::vector<std::string> columns = result_columns(suite);
  std::istringstream in(csv);
  std::string line, out;
  while (std::getline(in, line)) {
    std::string field;
    std::size_t c = 0;
    bool quoted = false;
    for (char ch : line + ",") {
      if (ch == '"') quoted = !quoted;
      if (ch == ',' && !quoted) {
        const bool blank = c < columns.size() &&
                           (is_timing_column(columns[c]) || is_provenance_column(columns[c]));
        out += (blank ? "<t>" : field) + ",";
        field.clear();
        ++c;
      } else {
        field += ch;
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace sightline::experiments::testing
