#include "sightline/experiments/reports/suite_outputs.h"

#include <filesystem>
#include <sstream>

#include "sightline/experiments/reports/suite_statistics.h"
#include "sightline/experiments/runs/output_text.h"

namespace sightline::experiments {

namespace fs = std::filesystem;

SuiteOutcome write_suite_outputs(const Suite& suite, const std::string& out_dir,
                                 const SuiteState& state) {
  const fs::path out(out_dir);
  SuiteOutcome outcome;
  outcome.total = state.runs.size();
  outcome.reused = state.reused;
  // results.csv: finished runs in the suite's order.
  std::ostringstream csv;
  const std::vector<std::string> header = result_columns(suite);
  for (std::size_t c = 0; c < header.size(); ++c) csv << (c ? "," : "") << header[c];
  csv << '\n';
  for (std::size_t i = 0; i < state.runs.size(); ++i) {
    if (!state.finished[i]) continue;
    const RunResult& r = state.results[i];
    if (r.status == "failed") ++outcome.failed;
    if (r.status == "timeout" || r.status == "memout" || r.status == "crash" ||
        r.status == "wrong") {
      ++outcome.not_ok;
    }
    csv << csv_field(r.id) << ',' << r.kind << ',' << csv_field(r.subject) << ','
        << csv_field(r.solver) << ',' << csv_field(r.profile) << ',' << r.seed << ','
        << r.status;
    for (const std::string& v : r.values) csv << ',' << csv_field(v);
    csv << ',' << csv_field(r.note);
    for (const std::string* p : {&r.provenance.host, &r.provenance.cpu_model,
                                 &r.provenance.build_commit, &r.provenance.command_line,
                                 &r.run_wall_s, &r.run_cpu_s, &r.run_max_rss_mb}) {
      csv << ',' << csv_field(*p);
    }
    csv << '\n';
    outcome.results.push_back(r);
  }
  write_atomically((out / "results.csv").string(), csv.str());
  for (const auto& [name, text] : statistics_files(suite, outcome))
    write_atomically((out / name).string(), text);  // stats.csv, cactus.csv, profiles.csv
  return outcome;
}

}  // namespace sightline::experiments
