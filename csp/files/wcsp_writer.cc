#include "sightline/csp/files/wcsp_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "sightline/csp/files/decimal_costs.h"
#include "sightline/csp/files/expanded_table.h"
#include "sightline/csp/json_text.h"

namespace sightline::csp {
namespace {

constexpr double kMaxExact = 9007199254740992.0;  // 2^53

// How a constraint goes into the file.
enum class Form { kTable, kSalldiff, kExpanded };

// salldiff compares value indices: equal indices mean equal values only when every variable
// of the scope has the same domain; otherwise an all_different is written as a table too.
bool salldiff_able(const Problem& problem, const Constraint& c) {
  const std::optional<Distinctness> a = c.distinctness();
  if (!a || !a->zero_offsets) return false;
  const Domain& first = problem.domain(c.scope()[0]);
  for (VariableId v : c.scope()) {
    const Domain& d = problem.domain(v);
    if (d.size() != first.size()) return false;
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (d.value_at(i) != first.value_at(i)) return false;
    }
  }
  return true;
}

// The problem's constraints as the file will hold them, and the scale of their costs.
class WcspPlan {
 public:
  WcspPlan(const Problem& problem, const WcspWriteOptions& options)
      : problem_(problem), max_decimals_(options.max_decimals) {
    if (max_decimals_ < 0 || max_decimals_ > kMaxCostDecimals) {
      throw std::invalid_argument("max_decimals must be in 0.." + std::to_string(kMaxCostDecimals));
    }
    forms_.resize(problem.num_constraints());
    expanded_.resize(problem.num_constraints());
    int decimals = 0;
    for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
      const Constraint& c = problem.constraint(id);
      forms_[id] = c.table_costs() ? Form::kTable : salldiff_able(problem, c) ? Form::kSalldiff : Form::kExpanded;
      if (forms_[id] == Form::kExpanded) expanded_[id] = expand_violations(problem, id, ".wcsp");
      if (c.is_hard()) continue;
      for_each_cost(id, [&](double cost) { decimals = std::max(decimals, decimals_of(id, cost)); });
    }
    scale_ = decimal_scale(decimals);
    // The upper bound: 1 + the largest total soft cost.
    ub_ = 1;
    for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
      if (problem.constraint(id).is_hard()) continue;
      std::int64_t largest = 0;
      for_each_cost(id, [&](double cost) { largest = std::max(largest, integer_cost(id, cost)); });
      if (forms_[id] == Form::kSalldiff) {
        const Distinctness a = *problem.constraint(id).distinctness();
        const auto k = static_cast<std::int64_t>(problem.constraint(id).scope().size());
        largest *= a.counts_variables ? k - 1 : k * (k - 1) / 2;
      }
      ub_ += largest;
      if (static_cast<double>(ub_) > kMaxExact) {
        throw std::invalid_argument("cannot write to .wcsp: the total soft cost exceeds 2^53");
      }
    }
  }

  Form form(ConstraintId id) const { return forms_[id]; }
  const std::vector<double>& violations(ConstraintId id) const { return expanded_[id]; }
  double scale() const { return scale_; }
  std::int64_t ub() const { return ub_; }

  // A violation of constraint `id` as the file's integer cost: the upper bound for a hard
  // constraint's violation, else weight x violation x scale.
  std::int64_t cost_text(ConstraintId id, double violation) const {
    if (problem_.constraint(id).is_hard()) return violation > 0 ? ub_ : 0;
    return integer_cost(id, violation);
  }

 private:
  // Every violation a soft constraint's file entry holds: a table's default and tuples, the
  // unit of a salldiff, the expanded table's entries.
  template <class F>
  void for_each_cost(ConstraintId id, F f) const {
    const Constraint& c = problem_.constraint(id);
    switch (forms_[id]) {
      case Form::kTable: {
        const TableCosts& t = *c.table_costs();
        f(t.default_cost());
        for (std::size_t i = 0; i < t.num_tuples(); ++i) f(t.tuple_cost(i));
        break;
      }
      case Form::kSalldiff: f(1.0); break;
      case Form::kExpanded:
        for (double v : expanded_[id]) f(v);
        break;
    }
  }

  std::string refusal(ConstraintId id, double weighted, const std::string& why) const {
    return "cannot write " + problem_.constraint_name(id) + " to .wcsp: its weighted cost " +
           json_number(weighted) + " " + why;
  }

  int decimals_of(ConstraintId id, double violation) const {
    const double weighted = problem_.constraint(id).weight() * violation;
    if (!(weighted >= 0) || !std::isfinite(weighted)) {
      throw std::invalid_argument(refusal(id, weighted, "is not a finite number >= 0"));
    }
    const std::optional<int> d = cost_decimals(weighted, max_decimals_);
    if (d) return *d;
    if (max_decimals_ == 0) {
      throw std::invalid_argument(refusal(
          id, weighted, "is not a non-negative integer (.wcsp costs are integers; .cfn takes decimals)"));
    }
    throw std::invalid_argument(refusal(
        id, weighted, "has more than " + std::to_string(max_decimals_) +
                          " decimal places (costs are written exactly, scaled by at most 10^" +
                          std::to_string(max_decimals_) + ")"));
  }

  std::int64_t integer_cost(ConstraintId id, double violation) const {
    const double scaled = std::round(problem_.constraint(id).weight() * violation * scale_);
    if (scaled > kMaxExact) {
      throw std::invalid_argument(refusal(id, problem_.constraint(id).weight() * violation,
                                          "exceeds 2^53 as a .wcsp integer"));
    }
    return static_cast<std::int64_t>(scaled);
  }

  const Problem& problem_;
  int max_decimals_;
  std::vector<Form> forms_;
  std::vector<std::vector<double>> expanded_;  // kExpanded constraints' violations
  double scale_ = 1;
  std::int64_t ub_ = 1;
};

}  // namespace

double write_wcsp(const Problem& problem, std::ostream& out, const WcspWriteOptions& options) {
  std::size_t max_domain = 0;
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    const Domain& d = problem.domain(v);
    if (!d.is_discrete()) {
      throw std::invalid_argument("cannot write variable '" + problem.variable_name(v) +
                                  "' to .wcsp: its domain " + d.describe() + " is not discrete");
    }
    max_domain = std::max(max_domain, d.size());
  }
  // Check everything and find the upper bound before writing anything.
  const WcspPlan plan(problem, options);
  std::string name = problem.name().empty() ? "problem" : problem.name();
  std::replace_if(
      name.begin(), name.end(),
      [](char ch) { return std::isspace(static_cast<unsigned char>(ch)); }, '_');
  out << name << " " << problem.num_variables() << " " << max_domain << " "
      << problem.num_constraints() << " " << plan.ub() << "\n";
  for (VariableId v = 0; v < problem.num_variables(); ++v) {
    out << (v ? " " : "") << problem.domain(v).size();
  }
  out << "\n";
  for (ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    const Constraint& c = problem.constraint(id);
    const auto scope = c.scope();
    out << scope.size();
    for (VariableId v : scope) out << " " << v;
    if (plan.form(id) == Form::kExpanded) {
      // Every tuple whose cost is not 0, the default.
      std::ostringstream tuples;
      std::size_t count = 0;
      std::vector<std::size_t> digit(scope.size(), 0);
      for (double violation : plan.violations(id)) {
        const std::int64_t cost = plan.cost_text(id, violation);
        if (cost != 0) {
          for (std::size_t p = 0; p < scope.size(); ++p) tuples << digit[p] << " ";
          tuples << cost << "\n";
          ++count;
        }
        for (std::size_t p = scope.size(); p-- > 0;) {
          if (++digit[p] < problem.domain(scope[p]).size()) break;
          digit[p] = 0;
        }
      }
      out << " 0 " << count << "\n" << tuples.str();
      continue;
    }
    if (plan.form(id) == Form::kSalldiff) {
      out << " -1 salldiff " << c.distinctness()->measure_name << " " << plan.cost_text(id, 1.0) << "\n";
      continue;
    }
    const TableCosts& t = *c.table_costs();
    const std::int64_t default_cost = plan.cost_text(id, t.default_cost());
    // Listed tuples whose values are all in the domains (others can never occur) and whose
    // cost differs from the default (others add nothing).
    std::ostringstream tuples;
    std::size_t count = 0;
    for (std::size_t i = 0; i < t.num_tuples(); ++i) {
      const std::int64_t cost = plan.cost_text(id, t.tuple_cost(i));
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
  return plan.scale();
}

}  // namespace sightline::csp
