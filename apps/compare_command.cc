// `sightline compare`: the main job. Every registered solver (and the sliding-octree >
// ceres-refine pipeline) on the same few problems, one table: 1000-queens; map colouring
// (Australia; DIMACS Mycielski and queen graphs, one of them with fewer colours than its
// chromatic number so that the optimum is not 0); and a small continuous problem file.
//
// A solver that declares a problem unsuitable (grid above its size cap, continuous solvers on
// discrete problems) gets a "skipped" row saying why, never a silent omission. Each result is
// also judged by an independent check (attacking pairs, conflicting edges) that shares no
// code with the constraints the solvers saw; a disagreement makes the command fail.
#include <algorithm>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>

#include "apps/commands.h"
#include "sightline/csp/json_text.h"
#include "apps/problem_loader.h"
#include "apps/solve_options.h"
#include "apps/text_table.h"
#include "sightline/domains/colouring/colouring_problem.h"
#include "sightline/domains/nqueens/nqueens.h"
#include "sightline/solvers/registry.h"

#ifndef SIGHTLINE_EXAMPLES_DIR
#define SIGHTLINE_EXAMPLES_DIR "examples"
#endif

namespace sightline::apps {
namespace {

struct Instance {
  std::string label;
  std::string optimum;  // what is known of the optimum, as text
  std::unique_ptr<csp::Problem> problem;
  // The independent judge: the number of broken conditions (0 for a solution).
  // Empty for problems given with --problem, which have no independent judge.
  std::function<std::size_t(std::span<const double>)> count_broken;
  bool broken_is_cost = false;  // colouring: the count must equal the cost exactly
};

Instance queens_instance(std::size_t n) {
  return {std::to_string(n) + "-queens", "0", nqueens::build_nqueens(n),
          [](std::span<const double> rows) { return nqueens::attacking_pairs(rows); }, false};
}

// Colouring instance: `chromatic` is the graph's known chromatic number.
Instance colouring_instance(const std::string& path, int colours, int chromatic) {
  auto graph = std::make_shared<colouring::Graph>(colouring::read_graph_file(path));
  Instance instance;
  instance.label = graph->name() + ", " + std::to_string(colours) + " colours";
  instance.optimum = colours >= chromatic ? "0" : ">= 1 (chi = " + std::to_string(chromatic) + ")";
  instance.problem = colouring::build_colouring_problem(*graph, colours);
  instance.count_broken = [graph](std::span<const double> c) {
    return colouring::count_conflicts(*graph, c);
  };
  instance.broken_is_cost = true;
  return instance;
}

Instance file_instance(const std::string& path, const LoadOptions& load, std::string optimum) {
  Instance instance;
  instance.problem = load_problem(path, load);
  instance.label = instance.problem->name();
  instance.optimum = std::move(optimum);
  return instance;
}

std::vector<Instance> main_job_instances(const std::string& examples) {
  const std::string graphs = examples + "/graphs";
  std::vector<Instance> out;
  out.push_back(queens_instance(1000));
  out.push_back(colouring_instance(graphs + "/australia.yaml", 3, 3));
  out.push_back(colouring_instance(graphs + "/myciel3.col", 3, 4));
  out.push_back(colouring_instance(graphs + "/myciel5.col", 6, 6));
  out.push_back(colouring_instance(graphs + "/queen5_5.col", 5, 5));
  out.push_back(file_instance(examples + "/problems/shelf.yaml", {}, "2.3"));  // see the file
  return out;
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

}  // namespace

void add_compare_command(CLI::App& app) {
  struct Args {
    std::string examples = SIGHTLINE_EXAMPLES_DIR;
    std::string solvers;
    std::vector<std::string> problems;
    LoadOptions load;
    std::uint64_t seed = 1;
    double time_limit_seconds = 3;
    std::string format = "text";
  };
  auto args = std::make_shared<Args>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "the main job: every solver on N-queens, map colouring and a continuous problem, in "
      "one table");
  command
      ->add_option("--examples", args->examples,
                   "the examples folder (holding graphs/ and problems/)")
      ->capture_default_str();
  command->add_option("--solvers", args->solvers,
                      "comma-separated solvers or pipelines to compare (default: every "
                      "registered solver and sliding-octree>ceres-refine)");
  command
      ->add_option("--problem", args->problems,
                   "also compare on this problem file (.yaml/.yml, .wcsp, .col with "
                   "--colours); repeatable")
      ->allow_extra_args(false);
  command->add_option("--colours", args->load.colours, "number of colours for --problem .col files")
      ->check(CLI::Range(1, 1 << 20));
  command->add_option("--seed", args->seed, "random seed for every run")
      ->check(unsigned_integer())
      ->capture_default_str();
  command->add_option("--time-limit", args->time_limit_seconds, "wall-clock limit per run, seconds")
      ->capture_default_str();
  command->add_option("--format", args->format,
                      "text (the default: a table) or json (one object per run, in a list)")
      ->check(CLI::IsMember({"text", "json"}));
  command->callback([args] {
    const bool json = args->format == "json";
    SolveOptions limits;  // reuses the shared validation of the seed and limits
    limits.seed = args->seed;
    limits.time_limit_seconds = args->time_limit_seconds;
    const solvers::SolveContext context = make_context(limits);
    const auto& registry = solvers::SolverRegistry::global();
    std::vector<std::string> names = split_commas(args->solvers);
    if (names.empty()) {
      names = registry.names();
      if (registry.contains("sliding-octree") && registry.contains("ceres-refine")) {
        names.push_back("sliding-octree>ceres-refine");
      }
    }
    for (const auto& name : names) registry.create(name);  // unknown names fail before any run

    std::vector<Instance> instances = main_job_instances(args->examples);
    for (const auto& path : args->problems) {
      instances.push_back(file_instance(path, args->load, "?"));
    }
    if (!json) {
      std::cout << "sightline compare: " << names.size() << " solvers x " << instances.size()
                << " problems, seed " << args->seed << ", time limit "
                << format_seconds(args->time_limit_seconds) << " per run\n\n";
    }
    // --format json: every run as an object (skipped runs say why), in one list.
    std::vector<std::string> runs_json;
    TextTable table;
    using A = TextTable::Align;
    table.column("problem")
        .column("known optimum")
        .column("solver")
        .column("cost", A::kRight)
        .column("feasible")
        .column("evaluations", A::kRight)
        .column("time", A::kRight)
        .column("stop")
        .column("independent check");
    std::size_t failures = 0;
    // (solver, reason) -> the problems it was skipped on, in order of appearance.
    std::vector<std::pair<std::string, std::string>> skip_reasons;
    std::vector<std::string> skipped_on;
    for (const Instance& instance : instances) {
      for (const auto& name : names) {
        auto solver = registry.create(name);
        if (const std::string why = solver->unsuitable_reason(*instance.problem); !why.empty()) {
          table.add_row(
              {instance.label, instance.optimum, name, "-", "-", "-", "-", "skipped", "-"});
          runs_json.push_back("{\"problem\": " + csp::json_string(instance.label) +
                              ", \"solver\": " + csp::json_string(name) +
                              ", \"status\": \"skipped\", \"why\": " + csp::json_string(why) + "}");
          const std::pair<std::string, std::string> key{name, why};
          const auto it = std::find(skip_reasons.begin(), skip_reasons.end(), key);
          if (it == skip_reasons.end()) {
            skip_reasons.push_back(key);
            skipped_on.push_back(instance.label);
          } else {
            skipped_on[static_cast<std::size_t>(it - skip_reasons.begin())] +=
                "; " + instance.label;
          }
          continue;
        }
        const solvers::SolverResult r =
            solver->solve(*instance.problem, instance.problem->default_assignment(), context);
        instance.problem->check_assignment(r.best);  // values inside their domains
        std::string check = "-";
        if (instance.count_broken) {
          const std::size_t broken = instance.count_broken(r.best);
          const bool agrees = instance.broken_is_cost ? static_cast<double>(broken) == r.cost()
                                                      : (broken == 0) == r.feasible();
          if (!agrees) ++failures;
          check = (agrees ? "ok, " : "MISMATCH, ") +
                  count_of(broken, instance.broken_is_cost ? "conflict" : "attacking pair");
        }
        table.add_row({instance.label, instance.optimum, name, format_number(r.cost()),
                       r.feasible() ? "yes" : "no", std::to_string(r.evaluations),
                       format_seconds(r.wall_seconds), solvers::to_string(r.stop), check});
        runs_json.push_back(
            "{\"problem\": " + csp::json_string(instance.label) + ", \"known_optimum\": " +
            csp::json_string(instance.optimum) + ", \"solver\": " + csp::json_string(name) +
            ", \"status\": \"ok\", \"cost\": " + csp::json_number(r.cost()) + ", \"feasible\": " +
            (r.feasible() ? "true" : "false") + ", \"evaluations\": " +
            std::to_string(r.evaluations) + ", \"wall_seconds\": " + csp::json_number(r.wall_seconds) +
            ", \"best_found_seconds\": " + csp::json_number(r.best_found_seconds) + ", \"stop\": " +
            csp::json_string(solvers::to_string(r.stop)) + ", \"independent_check\": " +
            csp::json_string(check) + "}");
      }
    }
    if (json) {
      std::cout << "[";
      for (std::size_t i = 0; i < runs_json.size(); ++i) {
        std::cout << (i ? ",\n " : "") << runs_json[i];
      }
      std::cout << "]\n";
    } else {
      table.print(std::cout);
      if (!skip_reasons.empty()) std::cout << "\nskipped (solver on problems: why):\n";
      for (std::size_t i = 0; i < skip_reasons.size(); ++i) {
        std::cout << "- " << skip_reasons[i].first << " on " << skipped_on[i] << ": "
                  << skip_reasons[i].second << '\n';
      }
    }
    if (failures > 0) {
      throw RunFailed(std::to_string(failures) +
                      " runs disagree with the independent check (see the table)");
    }
  });
}

}  // namespace sightline::apps
