#include "sightline/csp/files/wcsp_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "sightline/csp/files/expanded_table.h"


namespace sightline::csp {
namespace {

constexpr double kMaxExact = 9007199254740992.0;  // 2^53

// A weighted cost as a .wcsp integer; refuses what would not read back exactly.
std::int64_t integer_cost(const Constraint& c, double cost) {
  const double weighted = c.weight() * cost;
  const double rounded = std::round(weighted);
  if (!(std::abs(weighted - rounded) <= 1e-9 * std::max(1.0, std::abs(weighted))) || rounded < 0 ||
      rounded > kMaxExact) {
    std::ostringstream message;
    message << "cannot write " << c.describe() << " to .wcsp: its weighted cost " << weighted
            << " is not a non-negative integer (.wcsp costs are integers)";
    throw std::invalid_argument(message.str());
  }
  return static_cast<std::int64_t>(rounded);
}

// The largest weighted cost a soft constraint can take.
std::int64_t largest_cost(const Constraint& c) {
  if (const TableCosts* t = c.table_costs()) {
    double largest = t->default_cost();
    for (std::size_t i = 0; i < t->num_tuples(); ++i) largest = std::max(largest, t->tuple_cost(i));
    return integer_cost(c, largest);
  }
  const double k = static_cast<double>(c.scope().size());
  return integer_cost(c, c.distinctness()->counts_variables ? k - 1 : k * (k - 1) / 2);
}

}  // namespace

void write_wcsp(const Problem& problem, std::ostream& out) {
  std::size_t max_domain = 0;
  for (const Variable& v : problem.variables()) {
    if (!v.domain.is_discrete()) {
      throw std::invalid_argument("cannot write variable '" + v.name + "' to .wcsp: its domain " +
                                  v.domain.describe() + " is not discrete");
    }
    max_domain = std::max(max_domain, v.domain.size());
  }
  // Check the kinds and find the upper bound before writing anything.
  std::int64_t ub = 1;
  // Constraints that are neither tables nor salldiff-able all_differents become cost tables.
  struct Expanded {
    std::vector<double> violations;
  };
  std::vector<std::optional<Expanded>> expanded(problem.num_constraints());
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    std::optional<Distinctness> a = c.distinctness();
    bool salldiff = a && a->zero_offsets;
    // salldiff compares value indices: equal indices mean equal values only when every
    // variable of the scope has the same domain; otherwise it is written as a table too.
    if (salldiff) {
      const Domain& first = problem.domain(c.scope()[0]);
      for (VariableId v : c.scope()) {
        const Domain& d = problem.domain(v);
        bool same = d.size() == first.size();
        for (std::size_t i = 0; same && i < d.size(); ++i) same = d.value_at(i) == first.value_at(i);
        salldiff = salldiff && same;
      }
    }
    if (!c.table_costs() && !salldiff) {
      expanded[id] = Expanded{expand_violations(problem, c, ".wcsp")};
      if (!c.is_hard()) {
        double largest = 0;
        for (double v : expanded[id]->violations) largest = std::max(largest, v);
        ub += integer_cost(c, largest);
        for (double v : expanded[id]->violations) integer_cost(c, v);  // each must be exact
      }
      if (static_cast<double>(ub) > kMaxExact) {
        throw std::invalid_argument("cannot write to .wcsp: the total soft cost exceeds 2^53");
      }
      continue;
    }
    if (!c.is_hard()) ub += largest_cost(c);
    if (static_cast<double>(ub) > kMaxExact) {
      throw std::invalid_argument("cannot write to .wcsp: the total soft cost exceeds 2^53");
    }
  }
  std::string name = problem.name().empty() ? "problem" : problem.name();
  std::replace_if(
      name.begin(), name.end(),
      [](char ch) { return std::isspace(static_cast<unsigned char>(ch)); }, '_');
  out << name << " " << problem.num_variables() << " " << max_domain << " "
      << problem.num_constraints() << " " << ub << "\n";
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    out << (v ? " " : "") << problem.domain(v).size();
  }
  out << "\n";
  auto cost_text = [&](const Constraint& c, double violation) {
    if (c.is_hard()) return violation > 0 ? ub : std::int64_t{0};
    return integer_cost(c, violation);
  };
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    const auto scope = c.scope();
    out << scope.size();
    for (VariableId v : scope) out << " " << v;
    if (expanded[id]) {
      // Every tuple whose cost is not 0, the default.
      std::ostringstream tuples;
      std::size_t count = 0, index = 0;
      std::vector<std::size_t> digit(scope.size(), 0);
      for (double violation : expanded[id]->violations) {
        const std::int64_t cost = cost_text(c, violation);
        if (cost != 0) {
          for (std::size_t p = 0; p < scope.size(); ++p) tuples << digit[p] << " ";
          tuples << cost << "\n";
          ++count;
        }
        ++index;
        for (std::size_t p = scope.size(); p-- > 0;) {
          if (++digit[p] < problem.domain(scope[p]).size()) break;
          digit[p] = 0;
        }
      }
      out << " 0 " << count << "\n" << tuples.str();
      continue;
    }
    if (const std::optional<Distinctness> a = c.distinctness()) {
      out << " -1 salldiff " << a->measure_name << " "
          << (c.is_hard() ? ub : integer_cost(c, 1.0)) << "\n";
      continue;
    }
    const TableCosts& t = *c.table_costs();
    const std::int64_t default_cost = cost_text(c, t.default_cost());
    // Listed tuples whose values are all in the domains (others can never occur) and whose
    // cost differs from the default (others add nothing).
    std::ostringstream tuples;
    std::size_t count = 0;
    for (std::size_t i = 0; i < t.num_tuples(); ++i) {
      const std::int64_t cost = cost_text(c, t.tuple_cost(i));
      if (cost == default_cost) continue;
      std::ostringstream line;
      bool inside = true;
      for (std::size_t p = 0; p < scope.size() && inside; ++p) {
        const auto index = problem.domain(scope[p]).index_of(t.tuple_value(i, p));
        inside = index.has_value();
        if (inside) line << *index << " ";
      }
      if (!inside) continue;
      tuples << line.str() << cost << "\n";
      ++count;
    }
    out << " " << default_cost << " " << count << "\n" << tuples.str();
  }
}

}  // namespace sightline::csp
