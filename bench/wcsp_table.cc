// wcsp_table: sls, bnb, sls>bnb, tabu and lns against toulbar2 on .wcsp instances, as a Markdown table
// (the one in docs/BENCHMARKS.md).
//
//   wcsp_table [--runs N] [--time-limit S] [--toulbar2 PATH] [--cpu] FILE.wcsp...
//
// Per instance: the known optimum (NAME.ub beside the file, if any), then for each of our
// solvers the cost reached ("*" = proved optimal; "inf" = no feasible assignment found) and
// the median time over the runs (seeds 1..N; the whole solve when proved optimal, else when
// the best was found, as the solver reports it; reading the file is not included; with
// --cpu scaled to CPU time, as toulbar2's own figure is), then toulbar2's optimum, the median of the time it prints
// ("Optimum: C in ... and T seconds") and of the wall time of the whole process (start-up
// and reading included). Not a Google Benchmark program: it compares whole runs of an
// external solver, which Google Benchmark cannot time.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <ctime>

#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/solvers/registry.h"

namespace {

using namespace sightline;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

std::string seconds(double s) {
  std::ostringstream out;
  if (s < 0.001) {
    out << std::fixed << std::setprecision(2) << s * 1e3 << " ms";
  } else if (s < 1) {
    out << std::fixed << std::setprecision(1) << s * 1e3 << " ms";
  } else {
    out << std::fixed << std::setprecision(2) << s << " s";
  }
  return out.str();
}

struct Cell {
  std::string cost;
  double time = 0;
};

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Cell run_ours(const csp::Problem& problem, const std::string& solver, int runs, double limit,
              bool use_cpu, const solvers::OptionValues& extra) {
  Cell cell;
  std::vector<double> times;
  for (int seed = 1; seed <= runs; ++seed) {
    solvers::OptionValues options;
    if (solver == "sls") options["restarts"] = "200";
    if (solver == "sls>bnb") options["sls.restarts"] = "200";
    for (const auto& [key, value] : extra) {
      if (key.rfind(solver + ".", 0) == 0) options[key.substr(solver.size() + 1)] = value;
    }
    auto s = solvers::SolverRegistry::global().create(solver, options);
    solvers::SolveContext context;
    context.seed = static_cast<std::uint64_t>(seed);
    context.limits.time_limit_seconds = limit;
    context.want_breakdown = false;
    const double cpu_before = process_cpu_seconds();
    const auto r = s->solve(problem, problem.default_assignment(), context);
    const double cpu = process_cpu_seconds() - cpu_before;
    // Proved (or no time to best recorded): the whole solve; otherwise when the best was
    // found. On a loaded machine wall time counts other programs' turns on the core, so
    // --cpu scales the solver's wall clock readings by this run's CPU/wall ratio.
    const bool proved = r.stop == solvers::StopReason::kProvenOptimal;
    double t = proved || r.best_found_seconds < 0 ? r.wall_seconds : r.best_found_seconds;
    if (use_cpu && r.wall_seconds > 0) t *= std::min(1.0, cpu / r.wall_seconds);
    times.push_back(t);
    std::ostringstream c;
    if (r.feasible()) {
      c << r.cost() << (r.stop == solvers::StopReason::kProvenOptimal ? "*" : "");
    } else {
      c << "inf (hard " << r.score.hard << ")";
    }
    if (seed == 1) {
      cell.cost = c.str();
    } else if (cell.cost != c.str()) {
      cell.cost += " / " + c.str();  // seeds disagree: show every outcome
    }
  }
  cell.time = median(times);
  return cell;
}

struct Toulbar2Cell {
  std::string optimum = "-";
  double reported = 0, wall = 0;
};

Toulbar2Cell run_toulbar2(const std::string& toulbar2, const std::string& path, int runs) {
  Toulbar2Cell cell;
  std::vector<double> reported, wall;
  const std::regex optimum(R"(Optimum: (\d+) .* and ([0-9.eE+-]+) seconds)");
  for (int i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    FILE* pipe = popen(("'" + toulbar2 + "' '" + path + "' 2>&1").c_str(), "r");
    if (!pipe) return cell;
    std::string output;
    std::array<char, 4096> buffer;
    while (std::fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
    pclose(pipe);
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    std::smatch m;
    if (std::regex_search(output, m, optimum)) {
      cell.optimum = m[1];
      reported.push_back(std::stod(m[2]));
    }
  }
  cell.reported = median(reported);
  cell.wall = median(wall);
  return cell;
}

std::string known_optimum(const std::string& path) {
  std::filesystem::path p(path);
  std::string stem = p.filename().string();
  stem = stem.substr(0, stem.find(".wcsp"));
  std::ifstream in((p.parent_path() / (stem + ".ub")).string());
  std::string ub;
  return in >> ub ? ub : "?";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sls, bnb and sls>bnb against toulbar2 on .wcsp files, as a Markdown table"};
  int runs = 3;
  double limit = 60;
  std::string toulbar2 = "toulbar2";
  std::vector<std::string> files;
  app.add_option("--runs", runs, "runs per solver (seeds 1..N); times are medians")
      ->check(CLI::PositiveNumber);
  app.add_option("--time-limit", limit, "seconds per run of our solvers")
      ->check(CLI::PositiveNumber);
  app.add_option("--toulbar2", toulbar2, "the toulbar2 program");
  bool use_cpu = false;
  app.add_flag("--cpu", use_cpu,
               "our times in CPU seconds (toulbar2 prints CPU time), not wall: for a loaded "
               "machine");
  std::vector<std::string> columns = {"sls", "bnb", "sls>bnb", "tabu", "lns", "toulbar2"};
  app.add_option("--solvers", columns,
                 "the columns, in order (default: sls bnb sls>bnb tabu lns toulbar2); any "
                 "registered solver or pipeline, toulbar2 for the reference program")
      ->delimiter(',')
      ->allow_extra_args(false);
  std::vector<std::string> settings;
  app.add_option("--set", settings,
                 "SOLVER.OPTION=VALUE for one column's solver (e.g. tabu.hard_weight=0); "
                 "repeatable")
      ->allow_extra_args(false);
  app.add_option("files", files, ".wcsp files")->required();
  CLI11_PARSE(app, argc, argv);
  solvers::OptionValues extra;
  for (const std::string& setting : settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos) {
      std::cerr << "--set expects SOLVER.OPTION=VALUE, got '" << setting << "'\n";
      return 1;
    }
    extra[setting.substr(0, eq)] = setting.substr(eq + 1);
  }

  std::cout << "| instance | optimum |";
  std::string rule = "|---|---:|";
  for (const std::string& column : columns) {
    std::cout << (column == "toulbar2" ? " toulbar2 | its time | wall |" : " " + column + " | time |");
    rule += column == "toulbar2" ? "---:|---:|---:|" : "---:|---:|";
  }
  std::cout << "\n" << rule << "\n";
  for (const std::string& path : files) {
    std::unique_ptr<csp::Problem> problem;
    try {
      problem = csp::read_wcsp_file(path);
    } catch (const std::exception& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
    std::string name = std::filesystem::path(path).filename().string();
    name = name.substr(0, name.find(".wcsp"));
    std::cout << "| " << name << " | " << known_optimum(path);
    for (const std::string& solver : columns) {
      if (solver == "toulbar2") {
        const Toulbar2Cell t = run_toulbar2(toulbar2, path, runs);
        std::cout << " | " << t.optimum << " | " << seconds(t.reported) << " | "
                  << seconds(t.wall);
      } else {
        const Cell c = run_ours(*problem, solver, runs, limit, use_cpu, extra);
        std::cout << " | " << c.cost << " | " << seconds(c.time);
      }
    }
    std::cout << " |\n" << std::flush;
  }
  return 0;
}
