#include "sightline/csp/files/table_writers.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "sightline/csp/files/decimal_costs.h"
#include "sightline/csp/files/expanded_table.h"
#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/json_text.h"

namespace sightline::csp {
namespace {

// Numbers as they read back exactly (%.17g; every one written here is finite).
std::string exact(double v) { return json_number(v); }

// The weighted cost of every tuple of a constraint's scope, dense (expanded_table.h order).
std::vector<double> dense_costs(const Problem& problem, ConstraintId id, const char* format) {
  const Constraint& c = problem.constraint(id);
  std::vector<double> costs = expand_violations(problem, id, format);
  for (double& v : costs) {
    if (!std::isfinite(v) || v < 0) {
      throw std::invalid_argument("cannot write " + problem.constraint_name(id) + " to " + format +
                                  ": a violation is not a finite number >= 0");
    }
    v *= c.weight();
  }
  return costs;
}

// Whether toulbar2 reads `name` as a name: not empty, not starting like a number, none of
// the characters its parser splits on (and none JSON would escape).
bool cfn_identifier(const std::string& name) {
  if (name.empty() || std::string_view("0123456789-.+").find(name[0]) != std::string_view::npos) {
    return false;
  }
  for (const char ch : name) {
    const auto u = static_cast<unsigned char>(ch);
    if (u <= ' ' || u == 0x7f || std::string_view("/#[]{}:,\"\\").find(ch) != std::string_view::npos) {
      return false;
    }
  }
  return true;
}

// Hands out distinct .cfn identifiers within one namespace (the variables, or one domain's
// values): the preferred name when it is one and free, else the fallback, made distinct
// with trailing underscores.
class CfnNames {
 public:
  std::string take(const std::string& preferred, const std::string& fallback) {
    std::string name = cfn_identifier(preferred) && !taken_.count(preferred) ? preferred : fallback;
    while (taken_.count(name)) name += "_";
    taken_.insert(name);
    return name;
  }

 private:
  std::set<std::string> taken_;
};

}  // namespace

void write_cfn(const Problem& problem, std::ostream& out,
               const std::vector<std::vector<std::string>>& value_labels) {
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    if (!problem.domain(v).is_discrete()) {
      throw std::invalid_argument("cannot write variable " + problem.variable_name(v) +
                                  " to .cfn: its domain is not discrete");
    }
  }
  // The tables, the upper bound and the decimal places every soft cost needs.
  std::vector<std::vector<double>> tables;
  double ub = 1;
  int decimals = 0;
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    tables.push_back(dense_costs(problem, id, ".cfn"));
    if (c.is_hard() || tables.back().empty()) continue;
    for (const double cost : tables.back()) {
      const std::optional<int> d = cost_decimals(cost);
      if (!d) {
        throw std::invalid_argument("cannot write " + problem.constraint_name(id) +
                                    " to .cfn: its weighted cost " + exact(cost) + " has more than " +
                                    std::to_string(kMaxCostDecimals) +
                                    " decimal places (toulbar2 would round it)");
      }
      decimals = std::max(decimals, *d);
    }
    ub += *std::max_element(tables.back().begin(), tables.back().end());
  }
  const std::string bound = fixed_decimal(ub, decimals);
  out << "{\"problem\": {\"name\": " << json_string(CfnNames().take(problem.name(), "problem"))
      << ", \"mustbe\": \"<" << bound << "\"},\n \"variables\": {";
  CfnNames variable_names;
  std::vector<std::string> names(problem.num_variables());
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    names[v] = variable_names.take(problem.variable_name(v), "x" + std::to_string(v));
    const Domain& d = problem.domain(v);
    out << (v ? ",\n  " : "\n  ") << json_string(names[v]) << ": [";
    CfnNames value_names;
    for (std::size_t i = 0; i < d.size(); ++i) {
      const double value = d.value_at(i);
      const std::string* label = find_value_label(value_labels, v, value);
      out << (i ? ", " : "") << json_string(value_names.take(label ? *label : "", "v" + short_number(value)));
    }
    out << "]";
  }
  out << "},\n \"functions\": {";
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    out << (id ? ",\n  " : "\n  ") << json_string("c" + std::to_string(id)) << ": {\"scope\": [";
    const auto scope = c.scope();
    for (std::size_t i = 0; i < scope.size(); ++i) out << (i ? ", " : "") << json_string(names[scope[i]]);
    out << "], \"costs\": [";
    const auto& costs = tables[id];
    for (std::size_t i = 0; i < costs.size(); ++i) {
      out << (i ? ", " : "");
      if (c.is_hard()) {
        out << (costs[i] > 0 ? bound : "0");
      } else {
        out << fixed_decimal(costs[i], decimals);
      }
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
    const std::vector<double> violations = expand_violations(problem, id, "a problem file");
    out << "    default: 0\n    tuples: [";
    std::vector<std::size_t> digit(scope.size(), 0);
    std::size_t written = 0;
    for (double violation : violations) {
      if (!std::isfinite(violation) || violation < 0) {
        throw std::invalid_argument("cannot write " + problem.constraint_name(id) +
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
