#include "apps/problem_loader.h"

#include <string_view>

#include "sightline/csp/files/cfn_reader.h"
#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/csp/input_error.h"
#include "sightline/domains/colouring/colouring_problem.h"
#include "sightline/domains/colouring/dimacs_reader.h"

namespace sightline::apps {
namespace {

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

}  // namespace

csp::LoadedProblem load_model(const std::string& path, const LoadOptions& options) {
  if ((ends_with(path, ".yaml") || ends_with(path, ".yml")) && options.colours == 0) {
    return csp::load_problem_file(path);
  }
  csp::LoadedProblem loaded;
  loaded.problem = load_problem(path, options);
  loaded.value_labels.resize(loaded.problem->num_variables());
  return loaded;
}

std::unique_ptr<csp::Problem> load_problem(const std::string& path, const LoadOptions& options) {
  const bool graph = ends_with(path, ".col");
  if (!graph && options.colours > 0) {
    throw csp::InputError({path, 0, 0}, options.colours_name +
                                            " applies to DIMACS graphs (.col) only, not to this file");
  }
  if (ends_with(path, ".yaml") || ends_with(path, ".yml")) return csp::read_problem_file(path);
  if (graph) {
    if (options.colours < 1) {
      throw csp::InputError({path, 0, 0}, "a DIMACS graph is coloured with a number of colours: add " +
                                              options.colours_usage);
    }
    return colouring::build_colouring_problem(colouring::read_dimacs_graph(path), options.colours);
  }
  if (ends_with(path, ".wcsp") || ends_with(path, ".wcsp.gz")) {
    return csp::read_wcsp_file(path);
  }
  for (const char* suffix : {".cfn", ".cfn.gz", ".cfn.bz2", ".cfn.xz"}) {
    if (ends_with(path, suffix)) return csp::read_cfn_file(path);
  }
  throw csp::InputError({path, 0, 0}, "unknown problem file type (expected .yaml/.yml, .col with " +
                                          options.colours_usage +
                                          ", .wcsp or .wcsp.gz, .cfn or .cfn.gz/.bz2/.xz)");
}

}  // namespace sightline::apps
