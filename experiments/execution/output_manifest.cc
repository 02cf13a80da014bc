#include "sightline/experiments/execution/output_manifest.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "sightline/experiments/runs/stable_hash.h"
#include "sightline/experiments/execution/suite_runner.h"

namespace sightline::experiments {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat = "sightline-suite-output 1";

std::map<std::string, std::string> read_fields(const fs::path& path) {
  std::map<std::string, std::string> fields;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t eq = line.find('=');
    if (eq != std::string::npos) fields[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return fields;
}

std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

std::string describe(const std::string& name, const std::string& file, const std::string& hash) {
  return "suite '" + name + "' (" + (file.empty() ? "no file" : file) + ", definition " + hash +
         ")";
}

// Anything in the folder but another process's manifest being written.
bool holds_other_files(const fs::path& out) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(out, ec)) {
    if (entry.path().filename().string().rfind("manifest", 0) != 0) return true;
  }
  return false;
}

}  // namespace

std::string suite_definition_hash(const std::vector<SuiteRun>& runs) {
  StableHash h;
  for (const SuiteRun& run : runs) h.add(run.definition).add("\n");
  return h.hex();
}

void claim_output_folder(const Suite& suite, const std::vector<SuiteRun>& runs,
                         const std::string& out_dir) {
  const fs::path out(out_dir);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out)) {
    throw OutputFolderError("cannot use '" + out_dir + "' as the output folder: " +
                            (ec ? ec.message() : std::string("it is not a folder")));
  }
  const std::string hash = suite_definition_hash(runs);
  const fs::path manifest = out / "manifest";
  if (fs::exists(manifest)) {
    std::map<std::string, std::string> fields = read_fields(manifest);
    if (fields["format"] != kFormat) {
      throw OutputFolderError("'" + manifest.string() +
                              "' is not a manifest this version of sightline reads (format '" +
                              fields["format"] + "', expected '" + kFormat + "')");
    }
    if (fields["suite"] != suite.name) {
      throw OutputFolderError(
          "output folder '" + out_dir + "' holds the results of " +
          describe(fields["suite"], fields["suite_file"], fields["definition"]) + ", not of " +
          describe(suite.name, suite.path, hash) +
          ": choose another --out, or delete the folder to start over");
    }
    // The same suite, perhaps edited: each run file's definition decides what is redone.
  } else if (fs::is_directory(out / "runs")) {
    // A folder of an earlier version, without a manifest: accepted only when all its
    // results belong to this suite as it is now.
    std::set<std::string> definitions;
    for (const SuiteRun& run : runs) definitions.insert(run.definition);
    std::size_t foreign = 0;
    std::string example;
    for (const fs::directory_entry& entry : fs::directory_iterator(out / "runs", ec)) {
      if (entry.path().extension() != ".result") continue;
      RunResult stored;
      if (read_run_file(entry.path().string(), stored) && !definitions.count(stored.definition)) {
        if (foreign++ == 0) example = entry.path().string();
      }
    }
    if (foreign > 0) {
      throw OutputFolderError("output folder '" + out_dir +
                              "' has no manifest (an earlier version wrote it) and " +
                              std::to_string(foreign) + " of its run files are not runs of " +
                              describe(suite.name, suite.path, hash) + " (for instance " + example +
                              "): choose another --out, or delete those files");
    }
  } else if (holds_other_files(out)) {
    throw OutputFolderError("output folder '" + out_dir +
                            "' is not empty and holds no suite results (no manifest, no runs/): "
                            "choose a new or empty folder");
  }

  std::ostringstream text;
  text << "format=" << kFormat << "\nsuite=" << one_line(suite.name)
       << "\nsuite_file=" << one_line(suite.path) << "\ndefinition=" << hash
       << "\nruns=" << runs.size() << '\n';
  // A name of this process's own: several processes (MPI ranks) may claim the folder at once.
  const fs::path tmp = out / ("manifest.tmp." + std::to_string(::getpid()));
  {
    std::ofstream file(tmp, std::ios::trunc);
    file << text.str();
    file.flush();
    if (!file) throw OutputFolderError("cannot write in the output folder '" + out_dir + "'");
  }
  fs::rename(tmp, manifest, ec);
  if (ec) {
    throw OutputFolderError("cannot write in the output folder '" + out_dir + "': " + ec.message());
  }
}

}  // namespace sightline::experiments
