// The output folder's manifest: which suite a folder of results belongs to.
//
// OUT/manifest is a small key=value text file written (write, then rename) when a suite
// starts in the folder:
//   format=sightline-suite-output 1
//   suite=<the suite's name>
//   suite_file=<the suite file, as given>
//   definition=<16 hex digits: FNV-1a of every run's definition, in the suite's order>
//   runs=<number of runs>
// A suite is identified by its name. A folder whose manifest names another suite is refused
// (results of two studies must not mix in one results.csv). The same suite with another
// definition hash is the suite edited: accepted, and as before exactly the runs whose
// definition changed are redone (each run file names its definition). A folder without a
// manifest is accepted when it is new or empty, or when it is a folder of an earlier version
// (runs/ but no manifest) and every result file in runs/ names a definition of this suite;
// anything else (another suite's old runs, a folder of unrelated files) is refused, since
// the runner would overwrite its results.csv.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "sightline/experiments/suite/suite.h"

namespace sightline::experiments {

// A folder the suite may not use: another suite's, unrelated files, or not writable.
class OutputFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// FNV-1a (64 bits, as 16 hex digits) of the runs' definitions, one a line, in order.
std::string suite_definition_hash(const std::vector<SuiteRun>& runs);

// Creates out_dir if needed, checks it may hold this suite's runs (see above) and writes
// its manifest. Throws OutputFolderError naming the folder (and both suites when it is
// another's).
void claim_output_folder(const Suite& suite, const std::vector<SuiteRun>& runs,
                         const std::string& out_dir);

}  // namespace sightline::experiments
