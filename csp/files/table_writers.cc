#include "sightline/csp/files/table_writers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sightline/csp/files/expanded_table.h"
#include "sightline/csp/json_text.h"

namespace sightline::csp {
namespace {

// Numbers as they read back exactly (%.17g; every one written here is finite).
std::string exact(double v) { return json_number(v); }

// The weighted cost of every tuple of a constraint's scope, dense (expanded_table.h order).
std::vector<double> dense_costs(const Problem& problem, const Constraint& c, const char* format) {
  std::vector<double> costs = expand_violations(problem, c, format);
  for (double& v : costs) {
    if (!std::isfinite(v) || v < 0) {
      throw std::invalid_argument("cannot write " + c.describe() + " to " + format +
                                  ": a violation is not a finite number >= 0");
    }
    v *= c.weight();
  }
  return costs;
}

}  // namespace

void write_cfn(const Problem& problem, std::ostream& out) {
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    if (!problem.domain(v).is_discrete()) {
      throw std::invalid_argument("cannot write variable " + problem.variable_name(v) +
                                  " to .cfn: its domain is not discrete");
    }
  }
  std::vector<std::vector<double>> tables;
  double ub = 1;
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    tables.push_back(dense_costs(problem, c, ".cfn"));
    if (!c.is_hard() && !tables.back().empty()) {
      ub += *std::max_element(tables.back().begin(), tables.back().end());
    }
  }
  out << "{\"problem\": {\"name\": " << json_string(problem.name().empty() ? "problem" : problem.name())
      << ", \"mustbe\": \"<" << exact(ub) << "\"},\n \"variables\": {";
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    const Domain& d = problem.domain(v);
    out << (v ? ",\n  " : "\n  ") << json_string(problem.variable_name(v)) << ": [";
    for (std::size_t i = 0; i < d.size(); ++i) out << (i ? ", " : "") << json_string(exact(d.value_at(i)));
    out << "]";
  }
  out << "},\n \"functions\": {";
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    out << (id ? ",\n  " : "\n  ") << json_string("c" + std::to_string(id)) << ": {\"scope\": [";
    const auto scope = c.scope();
    for (std::size_t i = 0; i < scope.size(); ++i) out << (i ? ", " : "") << json_string(problem.variable_name(scope[i]));
    out << "], \"costs\": [";
    const auto& costs = tables[id];
    for (std::size_t i = 0; i < costs.size(); ++i) {
      const double cost = c.is_hard() ? (costs[i] > 0 ? ub : 0) : costs[i];
      out << (i ? ", " : "") << exact(cost);
    }
    out << "]}";
  }
  out << "}}\n";
}

void write_problem_yaml(const Problem& problem, std::ostream& out) {
  out << "name: " << json_string(problem.name().empty() ? "problem" : problem.name()) << "\n"
      << "description: written by sightline convert, every constraint as a cost table\n"
      << "variables:\n";
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    const Domain& d = problem.domain(v);
    out << "  - {name: " << json_string(problem.variable_name(v)) << ", ";
    if (d.is_continuous()) {
      out << "real: [" << exact(d.lower()) << ", " << exact(d.upper()) << "]}\n";
      continue;
    }
    out << "values: [";
    for (std::size_t i = 0; i < d.size(); ++i) out << (i ? ", " : "") << exact(d.value_at(i));
    out << "]}\n";
  }
  if (problem.num_constraints() > 0) out << "constraints:\n";
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    const auto scope = c.scope();
    out << "  - kind: table\n    scope: [";
    for (std::size_t i = 0; i < scope.size(); ++i) out << (i ? ", " : "") << json_string(problem.variable_name(scope[i]));
    out << "]\n    weight: " << exact(c.weight()) << "\n";
    if (c.is_hard()) out << "    hard: true\n";
    if (!c.label().empty()) out << "    label: " << json_string(c.label()) << "\n";
    if (const TableCosts* t = c.table_costs()) {
      // Its own tuples: those inside the domains (others never occur).
      out << "    default: " << exact(t->default_cost()) << "\n    tuples: [";
      std::size_t written = 0;
      for (std::size_t i = 0; i < t->num_tuples(); ++i) {
        bool inside = true;
        for (std::size_t p = 0; p < scope.size() && inside; ++p) {
          inside = problem.domain(scope[p]).contains(t->tuple_value(i, p));
        }
        if (!inside) continue;
        out << (written++ ? ", " : "") << "[";
        for (std::size_t p = 0; p < scope.size(); ++p) out << exact(t->tuple_value(i, p)) << ", ";
        out << exact(t->tuple_cost(i)) << "]";
      }
      out << "]\n";
      continue;
    }
    const std::vector<double> violations = expand_violations(problem, c, "a problem file");
    out << "    default: 0\n    tuples: [";
    std::vector<std::size_t> digit(scope.size(), 0);
    std::size_t written = 0;
    for (double violation : violations) {
      if (!std::isfinite(violation) || violation < 0) {
        throw std::invalid_argument("cannot write " + c.describe() +
                                    " to a problem file: a violation is not a finite number >= 0");
      }
      if (violation != 0) {
        out << (written++ ? ", " : "") << "[";
        for (std::size_t p = 0; p < scope.size(); ++p) out << exact(problem.domain(scope[p]).value_at(digit[p])) << ", ";
        out << exact(violation) << "]";
      }
      for (std::size_t p = scope.size(); p-- > 0;) {
        if (++digit[p] < problem.domain(scope[p]).size()) break;
        digit[p] = 0;
      }
    }
    out << "]\n";
  }
}

}  // namespace sightline::csp
