// `sightline convert PROBLEM --to wcsp [--out FILE] [--colours K]`: a model in another
// format, for other tools. `wcsp`: toulbar2's format (csp/files/wcsp_writer.h): every
// discrete model with integer weighted costs, kinds other than tables and all_different as
// cost tables. Other targets (`cfn`, `yaml`) are refused, saying they are not built.
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "apps/commands.h"
#include "apps/problem_loader.h"
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
      "convert", "write a problem in another format (wcsp: toulbar2's, every discrete model)");
  cmd->add_option("file", args->file, "the problem file (.yaml, .col with --colours, .wcsp, .cfn)")
      ->required();
  cmd->add_option("--to", args->to, "the format to write: wcsp")->required();
  cmd->add_option("--out", args->out, "write it here (default: standard output)");
  cmd->add_option("--colours", args->load.colours, "number of colours, for a DIMACS graph (.col)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->callback([args] {
    if (args->to != "wcsp") {
      throw std::invalid_argument("--to " + args->to + ": only wcsp is built (toulbar2 reads it; "
                                  "cfn and yaml writers are not)");
    }
    const std::unique_ptr<csp::Problem> problem = load_problem(args->file, args->load);
    std::ostringstream text;
    csp::write_wcsp(*problem, text);  // std::invalid_argument naming what it cannot express
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
