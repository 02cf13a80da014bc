#include "apps/report.h"

#include "sightline/csp/json_text.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "apps/text_table.h"
#include "sightline/solvers/options.h"

namespace sightline::apps {

std::string describe_problem(const csp::Problem& problem) {
  std::size_t discrete = 0, hard = 0;
  for (csp::VariableId v = 0; v < problem.num_variables(); ++v) {
    discrete += problem.domain(v).is_discrete() ? 1 : 0;
  }
  for (csp::ConstraintId c = 0; c < problem.num_constraints(); ++c) {
    hard += problem.constraint(c).is_hard() ? 1 : 0;
  }
  std::ostringstream out;
  out << problem.name() << ": " << problem.num_variables() << " variables (" << discrete
      << " discrete, " << problem.num_variables() - discrete << " continuous), "
      << problem.num_constraints() << " constraints (" << hard << " hard, "
      << problem.num_constraints() - hard << " soft)";
  return out.str();
}

solvers::SolverResult solve_and_print(std::ostream& out, const csp::Problem& problem,
                                      solvers::Solver& solver,
                                      const solvers::SolveContext& context,
                                      const std::string& what) {
  if (const std::string why = solver.unsuitable_reason(problem); !why.empty()) {
    throw solvers::OptionError("solver '" + solver.name() + "' cannot solve " + what + ": " + why);
  }
  solvers::SolverResult result = solver.solve(problem, problem.default_assignment(), context);
  problem.check_assignment(result.best);
  print_result(out, problem, result, solver.name());
  return result;
}

solvers::SolverResult solve_quietly(const csp::Problem& problem, solvers::Solver& solver,
                                    const solvers::SolveContext& context) {
  if (const std::string why = solver.unsuitable_reason(problem); !why.empty()) {
    throw solvers::OptionError("solver '" + solver.name() + "' cannot solve '" + problem.name() +
                               "': " + why);
  }
  solvers::SolverResult result = solver.solve(problem, problem.default_assignment(), context);
  problem.check_assignment(result.best);
  return result;
}

std::string result_json(const csp::LoadedProblem& model, const std::string& solver,
                        const solvers::SolverResult& r) {
  const csp::Problem& p = *model.problem;
  std::ostringstream out;
  out << "{\"problem\": " << csp::json_string(p.name()) << ", \"solver\": " << csp::json_string(solver)
      << ", \"feasible\": " << (r.feasible() ? "true" : "false")
      << ", \"cost\": " << csp::json_number(r.score.soft) << ", \"hard\": " << csp::json_number(r.score.hard)
      << ", \"stop\": " << csp::json_string(solvers::to_string(r.stop))
      << ", \"message\": " << csp::json_string(r.message)
      << ", \"wall_seconds\": " << csp::json_number(r.wall_seconds)
      << ", \"best_found_seconds\": " << csp::json_number(r.best_found_seconds)
      << ", \"evaluations\": " << r.evaluations << ", \"evaluations_at_best\": " << r.evaluations_at_best
      << ", \"iterations\": " << r.iterations << ", \"assignment\": {";
  for (csp::VariableId v = 0; v < p.num_variables(); ++v) {
    const std::string* label = csp::find_value_label(model.value_labels, v, r.best[v]);
    out << (v ? ", " : "") << csp::json_string(p.variable_name(v)) << ": "
        << (label ? csp::json_string(*label) : csp::json_number(r.best[v]));
  }
  out << "}, \"violated\": [";
  bool first = true;
  for (const csp::ConstraintCost& c : r.breakdown) {
    if (!(c.violation > 0)) continue;
    const std::string name = p.constraint_name(c.id);
    out << (first ? "" : ", ") << "{\"constraint\": " << csp::json_string(name)
        << ", \"hard\": " << (c.hard ? "true" : "false") << ", \"cost\": " << csp::json_number(c.cost) << "}";
    first = false;
  }
  out << "]}";
  return out.str();
}

void print_result(std::ostream& out, const csp::Problem& problem,
                  const solvers::SolverResult& result, const std::string& solver_name,
                  std::size_t top) {
  out << result.brief_report(solver_name) << '\n';
  if (result.breakdown.empty() && problem.num_constraints() > 0) return;
  std::vector<const csp::ConstraintCost*> violated;
  std::size_t hard = 0;
  for (const auto& c : result.breakdown) {
    if (c.violation > 0) {
      violated.push_back(&c);
      hard += c.hard ? 1 : 0;
    }
  }
  out << "violated constraints: " << violated.size() << " of " << problem.num_constraints();
  if (violated.empty()) {
    out << '\n';
    return;
  }
  out << " (" << hard << " hard, " << violated.size() - hard << " soft)\n";
  // Hard ones first, then by cost: the order in which they matter.
  const std::size_t shown = std::min(top, violated.size());
  std::partial_sort(violated.begin(), violated.begin() + static_cast<std::ptrdiff_t>(shown),
                    violated.end(), [](const auto* a, const auto* b) {
                      if (a->hard != b->hard) return a->hard;
                      return a->cost > b->cost;
                    });
  TextTable table;
  table.column("constraint")
      .column("kind")
      .column("hard")
      .column("violation", TextTable::Align::kRight)
      .column("cost", TextTable::Align::kRight);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& c = *violated[i];
    table.add_row({problem.constraint_name(c.id), std::string(problem.constraint(c.id).kind()), c.hard ? "hard" : "soft",
                   format_number(c.violation), format_number(c.cost)});
  }
  out << "costliest " << shown << ":\n";
  table.print(out);
}

void write_solution(const std::string& path, const csp::Problem& problem,
                    std::span<const double> values, std::ostream& out) {
  std::ostringstream text;
  text.precision(std::numeric_limits<double>::max_digits10);
  for (csp::VariableId v = 0; v < problem.num_variables(); ++v) {
    const csp::Domain& domain = problem.domain(v);
    if (v > 0) text << ' ';
    if (domain.is_discrete()) {
      const auto index = domain.index_of(values[v]);
      if (!index) {
        throw std::invalid_argument("value " + format_number(values[v], 17) + " of variable '" +
                                    problem.variable_name(v) + "' is not in its domain " +
                                    domain.describe());
      }
      text << *index;
    } else {
      text << values[v];
    }
  }
  text << '\n';
  if (path == "-") {
    out << text.str();
    return;
  }
  std::ofstream file(path);
  file << text.str();
  file.close();
  if (!file) throw std::runtime_error("cannot write the solution file '" + path + "'");
}

}  // namespace sightline::apps
