// `sightline convert PROBLEM --to wcsp|cfn|yaml [--out FILE] [--colours K]`: a model in
// another format, for other tools. `wcsp`: toulbar2's format (csp/files/wcsp_writer.h):
// every discrete model with integer weighted costs, kinds other than tables and
// all_different as cost tables. `cfn`: toulbar2's JSON format, decimal costs, values named
// by their labels, every constraint a dense cost table; `yaml`: this project's problem file, every constraint a
// `table` (csp/files/table_writers.h).
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "apps/commands.h"
#include "apps/problem_loader.h"
#include "sightline/csp/files/table_writers.h"
#include "sightline/csp/files/wcsp_writer.h"

namespace sightline::apps {

void add_convert_command(CLI::App& app) {
  struct Args {
    std::string file;
    LoadOptions load;
    std::string to;
    std::string out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "convert", "write a problem in another format (wcsp, cfn: toulbar2's; yaml: a problem file)");
  cmd->add_option("file", args->file, "the problem file (.yaml, .col with --colours, .wcsp, .cfn)")
      ->required();
  cmd->add_option("--to", args->to, "the format to write: wcsp, cfn or yaml")
      ->required()
      ->check(CLI::IsMember({"wcsp", "cfn", "yaml"}));
  cmd->add_option("--out", args->out, "write it here (default: standard output)");
  cmd->add_option("--colours", args->load.colours, "number of colours, for a DIMACS graph (.col)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->callback([args] {
    const csp::LoadedProblem model = load_model(args->file, args->load);
    const csp::Problem& problem = *model.problem;
    std::ostringstream text;
    // std::invalid_argument naming what it cannot express.
    if (args->to == "wcsp") csp::write_wcsp(problem, text);
    if (args->to == "cfn") csp::write_cfn(problem, text, model.value_labels);
    if (args->to == "yaml") csp::write_problem_yaml(problem, text);
    if (args->out.empty()) {
      std::cout << text.str();
      return;
    }
    std::ofstream out(args->out);
    out << text.str();
    if (!out) throw std::runtime_error("cannot write " + args->out);
  });
}

}  // namespace sightline::apps
